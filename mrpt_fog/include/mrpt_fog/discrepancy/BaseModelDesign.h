/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file BaseModelDesign.h
 * The bias model under test as a linear least-squares design, refitted on the measured run.
 * The terms come from the bias-model room: a preset (model/ModelPreset.h: multipoint, M1..M4,
 * points:K -> all its candidate thermistors, terms:...) or the term list of a calibration YAML
 * (model/CalibrationYaml.h; only the terms are used, the coefficients are refitted). One extra
 * preset exists here for the proof trials: `static:P[:NAME]`, a polynomial of order P in one
 * thermistor (default: the mean of all thermistors).
 *
 * Columns are built from RunSignals with fixed scaling, so coefficients fitted on one run apply
 * to another: temperature x = (T - 20 degC) / 50 degC, rates in degC/min, differences in degC.
 * A constant column is always present; when the run has a varying table rate a `table_rate`
 * column (constant scale-factor error, not a thermal effect) is added as a nuisance term.
 */

#include <mrpt_fog/discrepancy/RunSignals.h>
#include <mrpt_fog/model/ThermalFeatureSet.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Resolved base model: the terms to refit. */
struct BaseModelSpec
{
	std::string source;  //!< preset text or calibration file, as given
	std::vector<ThermalTerm> terms;  //!< model-room terms (constant included)
	/** `static:P[:NAME]`: order and thermistor ("mean" = all); 0 when not this preset. */
	int static_order = 0;
	std::string static_name = "mean";
};

/** Resolves `static:P[:NAME]`, any model-room preset, or a calibration YAML (*.yaml / *.yml)
 * against the run's thermistor layout. Throws std::invalid_argument (unknown preset or
 * thermistor, unreadable calibration, naming the file and field). */
BaseModelSpec resolveBaseModel(const std::string& preset_or_yaml, const FogSeries& run);

/** The base design on one run. */
struct BaseDesign
{
	Eigen::MatrixXd X;  //!< n x p, every sample (unusable rows are finite but ignored)
	std::vector<std::string> names;  //!< term names, e.g. "T(Ti1)^3"
	/** 1 for static temperature terms T^k, k >= 1 (what a thermistor lag distorts). */
	std::vector<unsigned char> is_static_temp;
	int max_static_order = 0;  //!< highest static power (temp_poly_order adds the next ones)
	/** Temperature of the (first) static polynomial [degC] (temp_poly_order uses it). */
	std::vector<double> static_temp_C;
};

/** Builds the columns on a run. Throws std::invalid_argument when a term names a thermistor
 * absent from the run. */
BaseDesign buildBaseDesign(const BaseModelSpec& spec, const FogSeries& run, const RunSignals& sig);

/** Scaled temperature x = (T - 20) / 50 used by every polynomial column. */
inline double scaledTemp(double temp_C) { return (temp_C - 20.0) / 50.0; }

}  // namespace mrpt_fog::discrepancy
