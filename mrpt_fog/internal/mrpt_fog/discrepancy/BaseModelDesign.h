/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file BaseModelDesign.h
 * The bias model under test as a linear least-squares design, refitted on the measured run.
 * One model path with the compensator: the model is built by the calibration code.
 *  - a preset (model/ModelPreset.h grammar: multipoint, M1..M4, points:K, terms:...) is fitted
 *    on the analysed run by fitCalibration with fog-calibrate's defaults (calibrationUnderTest);
 *  - a calibration YAML (*.yaml / *.yml) is loaded as is.
 * The columns are that calibration's selected terms (ThermalFeatureSet) with its normalisation,
 * evaluated on its own rate estimator (by default the causal order-2 estimator the compensator
 * runs, in degC/s) and continued outside the calibrated range by its extrapolation policy
 * (clamp or tangent), i.e. exactly the features fog-compensate evaluates; the calibration's
 * coefficients times these columns are the bias fog-compensate subtracts. The coefficients are
 * then refitted on the measured run together with the candidate effects.
 *
 * One extra grammar remains for the synthetic proof trials only: `static:P[:NAME]`, a
 * polynomial of order P in one thermistor or in the MEAN of all thermistors (the synthetic
 * generator's bias law, which no calibration term expresses), x = (T - 20 degC) / 50 degC.
 * For each rate term of a calibration, a nuisance column "centred minus causal" (the same
 * feature on the analysis' centred slope, RunSignals, minus the feature on the calibration's
 * causal rate) lets the refit use a better estimate of the same rate: what the compensator's
 * rate estimator misses is its gap, not a missing physical effect.
 * A constant column is always present; when the run has a varying table rate a `table_rate`
 * column (constant scale-factor error, not a thermal effect) is added as a nuisance term, and
 * when the calibration has a scale factor versus temperature of order >= 1, one column per
 * power of it (table rate x 1e-6 x z^k, its normalisation, clamped as the compensator does).
 */

#include <mrpt_fog/discrepancy/DiscrepancyOptions.h>
#include <mrpt_fog/discrepancy/RunSignals.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/ThermalFeatureSet.h>

#include <Eigen/Dense>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Resolved base model: the terms to refit. */
struct BaseModelSpec
{
	std::string source;  //!< preset text or calibration file, as given
	std::vector<ThermalTerm> terms;  //!< model-room terms (constant included)
	/** The calibration's selected terms with their normalisation and calibrated ranges, its rate
	 * estimator and extrapolation policy (unused for `static:`). */
	ThermalFeatureSet features;
	RateEstimatorSettings rate_estimator;
	ExtrapolationPolicy extrapolation = ExtrapolationPolicy::Linear;
	/** The calibration's scale factor versus temperature (absent: nominal / not fitted). */
	std::optional<ScaleFactorModel> scale_factor;
	/** `static:P[:NAME]`: order and thermistor ("mean" = all); 0 when not this preset. */
	int static_order = 0;
	std::string static_name = "mean";
};

/** What calibrationUnderTest fits for a preset. */
enum class FitScope : unsigned char
{
	Full = 0,  //!< what fog-calibrate writes (fallback models, selection-stability refits)
	MainModelOnly = 1  //!< the same main model (and scale factor) without the fallbacks and the stability refits
};

/** The calibration under test: a calibration YAML (*.yaml, *.yml) loaded as is, or the preset
 * fitted on `run` by fitCalibration with fog-calibrate's default options (as fog-calibrate: on
 * a run with table rates the table samples are left out of the bias fit and the scale factor
 * versus temperature is fitted from them, ScaleFactorFit.h; when they cannot support that fit the bias-only
 * calibration stands, as with fog-calibrate --scale-factor off). Throws std::invalid_argument
 * as fitCalibration / loadCalibrationYaml do. */
Calibration calibrationUnderTest(const std::string& preset_or_yaml, const FogSeries& run,
								 FitScope scope = FitScope::Full, ScaleFactorFitting sf = ScaleFactorFitting::Auto);

/** Resolves `static:P[:NAME]`, any model-room preset, or a calibration YAML (*.yaml / *.yml)
 * against the run's thermistor layout (calibrationUnderTest, main model only). Throws
 * std::invalid_argument (unknown preset or thermistor, unreadable calibration naming the file
 * and field, the fit's refusal, e.g. too narrow a temperature span). */
BaseModelSpec resolveBaseModel(const std::string& preset_or_yaml, const FogSeries& run,
								ScaleFactorFitting sf = ScaleFactorFitting::Auto);

/** The base design on one run. */
struct BaseDesign
{
	Eigen::MatrixXd X;  //!< n x p, every sample (unusable rows are finite but ignored)
	/** 1 where every column is defined: 0 where the calibration's causal rate has no estimate
	 * yet (the first half window of the log or after a gap longer than the window; the
	 * compensator flags these samples as rate warm-up). */
	std::vector<unsigned char> defined;
	std::vector<std::string> names;  //!< term names, e.g. "T(Ti1)^3"
	/** 1 for static temperature terms T^k, k >= 1 (what a thermistor lag distorts). */
	std::vector<unsigned char> is_static_temp;
	/** 1 for columns that are no term of the calibration: for each rate term, the feature on
	 * the analysis' centred rate minus the feature on the calibration's causal rate ("the same
	 * term, better estimated"), so that the rate estimator's errors are not named as a missing
	 * effect. */
	std::vector<unsigned char> is_nuisance;
	int max_static_order = 0;  //!< highest static power (temp_poly_order adds the next ones)
	/** Temperature of the (first) static polynomial [degC] (temp_poly_order uses it). */
	std::vector<double> static_temp_C;
};

/** Builds the columns on a run. Throws std::invalid_argument when a term names a thermistor
 * absent from the run. */
BaseDesign buildBaseDesign(const BaseModelSpec& spec, const FogSeries& run, const RunSignals& sig);

/** Marks the samples where the base design is not defined as unusable in `sig` (they enter no
 * fit and no gap figure). Returns how many usable samples were removed. */
std::size_t restrictToDefinedRows(RunSignals& sig, const BaseDesign& base);

/** Scaled temperature x = (T - 20) / 50 used by every polynomial column. */
inline double scaledTemp(double temp_C) { return (temp_C - 20.0) / 50.0; }

}  // namespace mrpt_fog::discrepancy
