/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file BaseModelDesign.h
 * The model under test, as a linear least-squares design: the regressor columns of a
 * bias-model preset (the seed's M1..M4, multipoint, points:K, plus `static:P[:NAME]`, a
 * polynomial of order P in one temperature), built from RunSignals. This is the documented
 * internal least-squares form used until the bias-model room's API can be plugged in; the
 * columns follow the seed (temperatures up to 5th order, rates and differences up to 3rd).
 *
 * Scaling (fixed, so coefficients fitted on one run apply to another): temperature
 * x = (T - 20 degC) / 50 degC; rates in degC/min; differences in degC. A constant column is
 * always present; when the run has a varying table rate, a `table_rate` column (constant
 * scale-factor error, not a thermal effect) is added as a nuisance term.
 */

#include <mrpt_fog/discrepancy/RunSignals.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Parsed preset. */
struct BaseModelSpec
{
	std::string preset;  //!< the text given, e.g. "M2:Ti1"
	/** Temperature columns with a static polynomial (thermistor names; "mean" = all). */
	std::vector<std::string> static_temps;
	int static_order = 5;
	/** Temperature columns with a polynomial in their own rate dT/dt. */
	std::vector<std::string> rate_temps;
	int rate_order = 3;
	/** Inner/outer pair for difference terms ("" = inner/outer means). */
	std::string diff_in, diff_out;
	int diff_order = 0;  //!< poly order in (Tin - Tout); 0 = none
	int diff_rate_order = 0;  //!< poly order in d(Tin - Tout)/dt; 0 = none
};

/** Parses a preset: `static:P[:NAME]`, `M1[:NAME]`, `M2[:NAME]`, `M3[:IN,OUT]`, `M4[:IN,OUT]`,
 * `multipoint[:NAME,NAME...]`, `points:K`. Thermistor names are checked against the run's
 * names later (buildBaseDesign). Throws std::invalid_argument naming the bad part. */
BaseModelSpec parseBasePreset(const std::string& preset);

/** The base design on one run. */
struct BaseDesign
{
	Eigen::MatrixXd X;  //!< n x p, every sample (unusable rows are finite but ignored)
	std::vector<std::string> names;  //!< human-readable term names, e.g. "T(Ti1)^3"
	/** 1 for static temperature terms T^k, k >= 1 (what a thermistor lag distorts). */
	std::vector<unsigned char> is_static_temp;
	int max_static_order = 0;  //!< highest static power (temp_poly_order adds the next ones)
	std::string static_temp_name = "mean";  //!< temperature the static polynomial uses first
};

/** Builds the columns on a run. Throws std::invalid_argument when a named thermistor is
 * absent, or when difference terms are asked for and no inner/outer pair exists. */
BaseDesign buildBaseDesign(const BaseModelSpec& spec, const FogSeries& run, const RunSignals& sig);

/** Scaled temperature x = (T - 20) / 50 used by every polynomial column. */
inline double scaledTemp(double temp_C) { return (temp_C - 20.0) / 50.0; }

}  // namespace mrpt_fog::discrepancy
