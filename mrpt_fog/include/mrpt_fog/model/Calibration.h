/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file Calibration.h
 * A FOG thermal-bias calibration and how to make one.
 *
 *   Calibration cal = fitCalibration({runA}, "multipoint");      // fit (library API)
 *   CompensatedSeries out = compensate(cal, runB);               // see Compensator.h
 *   saveCalibrationYaml(cal, "cal.yaml");                         // see CalibrationYaml.h
 *
 * What the fit does (fitCalibration):
 *  1. bias y = gyro rate - applied table rate (if the log has one) [deg/h]; samples with the
 *     gyro powered off, a thermistor dropout, or no rate estimate yet are left out;
 *  2. rates dT/dt with the chosen estimator (default: the same causal estimator the real-time
 *     compensator runs, so the compensator reproduces the fitted model);
 *  3. every signal normalised to [-1, 1] over the calibration data (ThermalFeatureSet.h);
 *  4. streaming QR factors accumulated per validation fold (StreamingQr.h): memory independent of the
 *     log length. Folds: one per run when several runs are given (leave-one-run-out), else
 *     `folds` contiguous time blocks of the single run (blocked k-fold);
 *  5. term selection (default "auto"): greedy forward selection of whole signal groups (e.g. all
 *     powers of T(Ti1)) and a ridge value from a grid, both by held-out (cross-validated) error;
 *     a group is added only if it lowers the held-out RMS. For "multipoint" and "points:K" the
 *     search is nested over thermistor subsets: the choice for a set S is the best of the
 *     greedy selection from S and of the choices for every S minus one thermistor (recursively,
 *     memoised; up to 8 thermistors, else refused). A subset's choice is a candidate for every
 *     superset, so with the same folds more thermistors never give a larger cross-validated
 *     error, by construction. Fallback for thermistor t: the nested choice without t.
 *     "none" fits every preset term (plain least squares, optional fixed ridge): the seed's way,
 *     which generalises badly on collinear thermistors;
 *  6. fallback models: for each thermistor of the model, the same selection without it; and
 *     the rate-free start-up model (Calibration::startup) when the main model reads rates;
 *  7. figures: in-sample (the fitted model, run through the causal compensator) and held-out
 *     (each fold predicted by the model fitted on the other folds), always labelled.
 *
 * Refusals (std::invalid_argument, one line with the reason): no runs, runs with different
 * layouts, fewer than min_samples_per_term x terms usable samples, a temperature span narrower
 * than min_temp_span_per_order_C x order, a rank-deficient system with plain least squares.
 */

#include <mrpt_fog/model/MagneticModel.h>
#include <mrpt_fog/model/RateEstimator.h>
#include <mrpt_fog/model/ScaleFactorModel.h>
#include <mrpt_fog/model/ThermalFeatureSet.h>
#include <mrpt_fog/model/WarmupModel.h>
#include <mrpt_fog/obs/FogRun.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <Eigen/Dense>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** What a bias model does with a signal (a temperature, a rate, a difference) outside the range
 * it was calibrated on. The model is a sum of one polynomial per signal, so each signal is
 * extended on its own:
 *  - Clamp: the signal is held at the edge of its range (PX4/ArduPilot practice). Beyond the
 *    edge the estimated bias stops changing, so the compensated output follows the raw one.
 *  - Linear: the signal's polynomial is continued along its tangent at the edge (value and
 *    slope continuous). Physically the leading bias terms are linear (Shupe: linear in dT/dt;
 *    thermal stress: linear in Tin - Tout), so a tangent keeps their trend where a clamp drops
 *    it, and unlike the raw polynomial it cannot blow up with the 5th power. The default, chosen
 *    on held-out data outside the range (docs/reference/model.md, "Extrapolation").
 *  - Polynomial: the raw polynomial (for studies only; a 5th order diverges quickly). */
enum class ExtrapolationPolicy : unsigned char
{
	Clamp = 0,
	Linear = 1,
	Polynomial = 2
};
/** "clamp" / "linear" / "polynomial". */
const char* toString(ExtrapolationPolicy p);
/** Parses the names above; throws std::invalid_argument naming the known ones. */
ExtrapolationPolicy extrapolationPolicyFromString(const std::string& text);

/** How the fit chooses the terms of the model (a closed set; the file comment's item 5). */
enum class TermSelection : unsigned char
{
	Auto = 0,  //!< "auto": signal groups, orders and the ridge by held-out error
	None = 1  //!< "none": every preset term, plain least squares with an optional fixed ridge
};
/** "auto" / "none" (the spelling in calibration files and on command lines). */
const char* toString(TermSelection s);
/** Parses "auto" / "none"; throws std::invalid_argument "selection must be 'auto' or 'none',
 * got '...'". */
TermSelection termSelectionFromString(const std::string& text);

/** How a single calibration run is cut into validation folds (several runs: one fold per run). */
enum class FoldScheme : unsigned char
{
	Regimes = 0,  //!< whole thermal regimes (cooling ramp, soak, heating ramp) held out (>= 3 needed, else Blocks)
	Blocks = 1  //!< folds x blocks_per_fold interleaved time blocks
};

/** How several calibration runs are cut into validation folds (a closed set). */
enum class RunFolds : unsigned char
{
	/** One fold per run: each run is predicted by the model fitted on the other runs alone. */
	Runs = 0,
	/** Each run's thermal regimes (as FoldScheme::Regimes cuts one run, at most max_regime_folds
	 * folds per run; a run with fewer than 3 regimes is one fold): each fold is predicted by the
	 * model fitted on everything else, the other runs included. */
	RegimesWithinRuns = 1
};

/** What the bias fit does with samples taken while the table applied a rate (a closed set). */
enum class TableSamples : unsigned char
{
	SubtractRate = 0,  //!< bias = gyro - applied rate (the nominal scale factor assumed)
	Exclude = 1  //!< left out of the bias fit (they serve the scale-factor fit, ScaleFactorFit.h)
};

/** How selection "auto" judges whether a forward step (a new signal or a higher order) is worth
 * taking (a closed set). */
enum class StepRule : unsigned char
{
	/** The held-out RMS must drop by FitOptions::min_relative_gain (relative to the RMS itself:
	 * at high sample rates the RMS is mostly the gyro's white noise, so a thermal gain that matters
	 * can fall below the threshold). */
	RelativeGain = 0,
	/** The held-out mean squared error must drop by more than FitOptions::step_z standard errors
	 * of the paired difference, the standard error from the per-block differences (the run cut
	 * into 40 time blocks, split by fold): a test of whether the gain is real, which does not
	 * depend on the sample rate for white noise (the per-sample noise grows as sqrt(rate), the
	 * number of samples as rate). */
	Significant = 1
};

/** Which models selection "auto" compares (a closed set). */
enum class OrderSearch : unsigned char
{
	/** Forward stepwise: from the linear multipoint model, one signal's order raised (or a
	 * physics candidate added) per step (FitOptions::linear_base, step_rule). */
	PerSignal = 0,
	/** Every thermistor's temperature at one common order (1 .. the preset's) and every rate at
	 * one common order (1 .. the preset's): the preset's own shape at each order pair, no
	 * physics candidates; the pair (and ridge) with the lowest held-out error is kept
	 * (parsimony: the simplest within one standard error). multipoint and points:K only (other
	 * presets keep PerSignal). */
	Common = 1
};

/** The FitOptions::turn_on_exclusion_s suggested for a calibration run that starts with a
 * turn-on (fog-sim's `calibration` profile) [s]: six time constants of a warm-up that settles in
 * 10 min (an estimate: fog-sim's warmup_tau_s, sim/FogDevice.h; PHYSICS.md gives no number). A
 * slower warm-up needs a longer exclusion. */
constexpr double kSuggestedTurnOnExclusion_s = 3600.0;

/** Lag time constants from the coil's thermal time constants [s] (shared/design/PHYSICS.md
 * "Thermal time constants": radial diffusion through the winding ~70 s, housing to air ~30 min;
 * docs/reference/simulator.md: the simulated network's modes at 1-3 min, ~6 min and 29.4 min): a geometric grid,
 * factor 4, from radial diffusion to the housing. */
inline const std::vector<double> kPhysicsLagTaus_s = {100.0, 400.0, 1600.0};

struct FitOptions
{
	RateEstimatorSettings rate_estimator;  //!< default causal, 60 s window
	/** Lengthen the rate window for coarsely quantised thermistors: the window used is
	 * windowForQuantum_s(rate_estimator.window_s, q) with q the largest reading quantum
	 * (readingQuantum_C) of the preset's thermistors in the runs, recorded in the calibration.
	 * false: rate_estimator.window_s as given (fog-calibrate --window sets it false). */
	bool window_for_quantum = true;
	TermSelection selection = TermSelection::Auto;
	double ridge = 0.0;  //!< fixed ridge for selection "none" (relative, unit-diagonal system)
	std::size_t folds = 5;  //!< blocked folds when a single run is given (>= 2)
	/** The single run is cut into folds x blocks_per_fold contiguous blocks, block b held out in
	 * fold b mod folds: every fold then samples the whole temperature range (1 = plain blocked
	 * k-fold, which makes the end folds pure polynomial extrapolation). */
	std::size_t blocks_per_fold = 4;
	/** "auto": a signal group is added only if it lowers the held-out RMS by this fraction. */
	double min_relative_gain = 0.005;
	FoldScheme fold_scheme = FoldScheme::Regimes;
	double regime_rate_C_per_min = 0.2;  //!< |mean thermistor rate| below this: a soak
	double min_regime_s = 600.0;  //!< shorter regime segments join the one before
	std::size_t max_regime_folds = 8;  //!< regime segment j is fold j mod this
	RunFolds run_folds = RunFolds::Runs;  //!< folds of several runs
	OrderSearch order_search = OrderSearch::PerSignal;
	StepRule step_rule = StepRule::RelativeGain;
	double step_z = 2.0;  //!< StepRule::Significant: standard errors a step's gain must exceed
	/** "auto": choose each signal's order (T 1..5, rates 1..3, up to the preset's) by held-out
	 * error; false: a signal enters with all the preset's powers (the earlier method). */
	bool select_orders = true;
	/** "auto": the simplest candidate within one standard error of the best held-out error. */
	bool parsimony = true;
	/** Parsimony's standard error: true, that of the paired per-fold difference (per block with
	 * StepRule::Significant) between a
	 * candidate and the best (the same folds judge both); false, the spread of the best's own
	 * per-fold errors, which mostly measures how unlike the folds are. */
	bool paired_se = false;
	/** "auto": candidates are scored on the means of consecutive samples over bins of this many
	 * seconds (within a fold), not on single samples: the gyro's white noise per sample grows
	 * with the sample rate and would otherwise decide the choice (at 40 Hz it is ~1 deg/h per
	 * sample, 100x the thermal error). 0: every sample (the earlier scoring). */
	double selection_bin_s = 0.0;
	/** "auto" with multipoint / points:K: add physics-shaped candidates for each inner/outer pair
	 * at the same angle: dT(in-out)^1 (thermal stress) and d/dt dT(in-out)^1 (gradient rate). */
	bool physics_candidates = true;
	/** multipoint / points:K: for each thermistor of the preset and each time constant here [s],
	 * the candidate dTlag/dt(a,tau)^1, the rate of its reading through a first-order lag
	 * (LagFilter.h: what the coil's interior sees of a boundary sensor; the Shupe error is linear
	 * in the interior's rates). "auto" adds them by held-out error like any other signal (never
	 * in the linear base unless lag_in_base); "none" never uses them (every preset term only: name
	 * them in a terms: preset). Empty: none. Default kPhysicsLagTaus_s, the grid from the coil's
	 * time constants (chosen on the generalization bench's tuning devices: docs/validation/generalization.md,
	 * "One thermistor: lags of its history"). */
	std::vector<double> lag_taus_s = kPhysicsLagTaus_s;
	/** The lag candidates are offered only when the preset reads at most this many thermistors:
	 * with an inner and an outer sensor the winding's radial spread is seen by the sensors
	 * themselves, and a lag of one of them stands in for the other's rate (worse held out on the
	 * tuning devices); one boundary sensor sees the interior only through its own history. */
	std::size_t lag_max_thermistors = 1;
	/** "auto" with lag candidates: they start in the linear base with T^1 and dT/dt^1 (one boundary
	 * sensor: the interior's rates are what the Shupe error is linear in, and one calibration
	 * profile cannot tell which of them other profiles need), instead of being added by steps. */
	bool lag_in_base = true;
	/** "auto": the search starts from T^1 and dT/dt^1 of every thermistor of the preset (the
	 * linear multipoint model: the Shupe error is linear in the coil's temperature rates) and
	 * adds orders and candidates by held-out error; multipoint then keeps all its thermistors
	 * (points:K still searches subsets). false: from the constant, over thermistor subsets. */
	bool linear_base = true;
	/** "auto": refits on wild-bootstrap resamples of the calibration data to measure how stable
	 * the choice is: the run is cut into 40 time blocks, and in each resample the residual of
	 * the chosen model changes sign in a random half of them (the thermal history stays: a new
	 * noise realisation of the same run, what a recalibration with another noise seed sees);
	 * 0 = not measured. */
	std::size_t stability_resamples = 10;
	std::uint64_t stability_seed = 1;  //!< fixed: the same data give the same report
	/** The choice is called stable when at least this share of refits repeat it. 0.9: with 10
	 * refits, a coin flip between two models reaches 9 of 10 with probability 1.1 % (8 of 10:
	 * 5.5 %, 6 of 10: 38 %), so "stable" is not given to a toss-up. */
	double stable_share = 0.9;
	double min_samples_per_term = 10.0;
	double min_temp_span_per_order_C = 0.5;  //!< T(a) of order k needs a span >= k x this [degC]
	double tau_s = 100.0;  //!< averaging time of the stability figures [s]
	bool fallbacks = true;  //!< fit one fallback model per thermistor
	/** Samples within this time after a turn-on (a 0 -> 1 step in power, or metadata
	 * power_on_time_s at or before the first sample) stay out of the bias fit [s]; 0: none left
	 * out. Their transient is the warm-up term's (fitWarmup on the same runs), not a thermal
	 * effect the bias model should take; this lets one chamber run that starts with a turn-on
	 * calibrate both (docs/validation/generalization.md, "One calibration run"). */
	double turn_on_exclusion_s = 0.0;
	/** Fit the rate-free start-up model (Calibration::startup) when the main model reads rates. */
	bool startup_model = true;
	ExtrapolationPolicy extrapolation = ExtrapolationPolicy::Linear;  //!< recorded in the calibration
	TableSamples table_samples = TableSamples::SubtractRate;
	std::optional<GyroAxis> axis;  //!< the gyro axis to calibrate (default: the runs' first axis)
};

/** Figures of one evaluation, labelled by how they were obtained. */
struct FitFigures
{
	std::string label;  //!< e.g. "in-sample", "held-out (blocked 5-fold)", "validation run"
	bool valid = false;
	std::size_t samples = 0;
	double rms_dph = 0.0;  //!< RMS of the compensated bias about its mean [deg/h]
	double stability_dph = 0.0;  //!< std of tau-s averages of the compensated output [deg/h]
	double range_dph = 0.0;  //!< max - min of the tau-s averages, compensated [deg/h]
	double raw_stability_dph = 0.0;  //!< the same for the uncompensated output
	double raw_range_dph = 0.0;
	double tau_s = 100.0;
	/** Through the compensator (validation runs): samples with a temperature / a rate outside
	 * the calibrated range, and the largest distance beyond it. */
	std::size_t temp_outside_samples = 0, rate_outside_samples = 0;
	double max_temp_excursion_C = 0.0, max_rate_excursion_C_per_s = 0.0;
};

/** One fitted bias model: bias_dph = sum_i coef_dph[i] * feature_i (features normalised). */
struct BiasModel
{
	std::string dropped;  //!< "" for the main model; the missing thermistor for a fallback
	ThermalFeatureSet features;  //!< terms + normalisation + calibrated ranges
	std::vector<double> coef_dph;  //!< [deg/h], one per term
	Eigen::MatrixXd covariance;  //!< of coef_dph [(deg/h)^2]
	double ridge = 0.0;
	double condition_number = 0.0;
	std::size_t numerical_rank = 0;
	double effective_dof = 0.0;
	std::size_t samples = 0;
	double rms_in_sample_dph = 0.0;  //!< residual RMS on the fitted samples
	double rms_held_out_dph = 0.0;  //!< cross-validated residual RMS

	/** Bias [deg/h] from signal values (features.signals() order); with clamp, values are
	 * clamped to the calibrated ranges and *clamped (if given) receives how many were. */
	double evaluate(const double* signal_values, bool clamp, int* clamped = nullptr) const;
	/** Bias [deg/h] with a signal outside its calibrated range handled by `policy`;
	 * *outside (if given) receives how many signals were outside. */
	double evaluate(const double* signal_values, ExtrapolationPolicy policy, int* outside = nullptr) const;
	/** d(bias)/d(signal) of signal s at its lower (upper = false) or upper calibrated edge
	 * [deg/h per unit of the signal]: the slope the Linear policy continues with. */
	double edgeSlope(std::size_t signal, bool upper) const;
};

/** How stable the selected model is under resampling of the calibration data (FitOptions). */
struct SelectionStability
{
	std::size_t resamples = 0;  //!< 0: not measured (selection none, or switched off)
	double chosen_share = 0.0;  //!< share of refits that chose exactly the calibrated model
	bool stable = true;  //!< chosen_share >= FitOptions::stable_share
	struct Alternative
	{
		std::string terms;  //!< "T(Ti1)^1 + dT/dt(Ti1)^1 + ..."
		double share = 0.0;  //!< share of refits that chose it
		double held_out_rms_dph = 0.0;  //!< its cross-validated RMS on the calibration's folds [deg/h]
	};
	std::vector<Alternative> alternatives;  //!< the other models refits chose, most frequent first
	/** The chosen model's cross-validated RMS on the calibration's folds [deg/h] and one standard
	 * error of its cross-validated MSE [(deg/h)^2] (spread over the folds). */
	double chosen_held_out_rms_dph = 0.0, held_out_se_mse = 0.0;
	/** Unstable choices only: true when every alternative's held-out MSE lies within one standard
	 * error of the chosen model's, i.e. the refits disagree only among models the calibration
	 * data cannot tell apart (the held-out error does not depend on which one is used; other
	 * profiles may still, since the data did not separate them); false when some alternative
	 * is distinguishably worse or better. Not stored in the calibration file. */
	bool alternatives_equivalent = false;
	std::vector<std::pair<std::string, double>> term_share;  //!< each term: share of refits that include it
};

/** How the Earth rate entered a calibration's bias (a closed set). */
enum class EarthRateHandling : unsigned char
{
	/** Static runs: the fitted bias holds the axis' projection of the Earth rate at the
	 * calibration latitude (the compensator removes it with the bias). */
	InBias = 0,
	/** The runs' applied (table) rate already included the Earth rate: the bias is free of it. */
	InTableRate = 1
};
/** "in_bias" / "in_table_rate". */
const char* toString(EarthRateHandling h);
/** Parses the above; throws std::invalid_argument naming the allowed values. */
EarthRateHandling earthRateHandlingFromString(const std::string& text);

/** The calibration of one gyro axis: the thermal bias model (always), and the optional
 * scale-factor and warm-up models (absent = not fitted: the compensator then does exactly the
 * bias-only compensation). A calibration file holds one or more of these (CalibrationSet). */
struct Calibration
{
	std::string sensor_label;
	GyroAxis axis = GyroAxis::Z;
	std::vector<ThermistorInfo> layout;  //!< the layout the calibration was made for
	/** Latitude of the calibration runs [deg] (NaN = unknown, e.g. a version 1 file or runs
	 * without latitude metadata) and how the Earth rate entered the bias. File-level in the
	 * YAML: every axis of a CalibrationSet carries the same values. */
	double latitude_deg = std::numeric_limits<double>::quiet_NaN();
	EarthRateHandling earth_rate = EarthRateHandling::InBias;
	std::string preset;  //!< as given to the fit
	TermSelection selection = TermSelection::Auto;  //!< how the fit chose the terms
	RateEstimatorSettings rate_estimator;
	ExtrapolationPolicy extrapolation = ExtrapolationPolicy::Linear;  //!< outside the calibrated range
	BiasModel model;
	std::vector<BiasModel> fallbacks;  //!< one per thermistor of the model
	/** Rate-free start-up model: the main model's temperature (and difference)
	 * terms refitted without any rate signal. The compensator uses it while a rate the main
	 * model reads is not yet estimable or its window covers less than half its length (the
	 * start of a log, each burst of a burst log, after a gap longer than the window), instead
	 * of the main model with a rate from a few samples (at 1 kHz two samples 1 ms apart and a
	 * 0.01 degC quantum give 10 degC/s). Absent: the main model has no rate term, or a file
	 * written before it existed (then the warm-up is compensated as before: fallback / mean
	 * bias until 2 samples, then the main model, flagged RateWarmup). */
	std::optional<BiasModel> startup;
	double mean_bias_dph = 0.0;  //!< used when no model applies (>= 2 thermistors missing)
	std::vector<std::string> runs;  //!< labels of the calibration runs
	FitFigures in_sample, held_out, validation;
	SelectionStability selection_stability;  //!< see SelectionStability (stored in the bias section of version 2 files)
	std::optional<ScaleFactorModel> scale_factor;  //!< absent: nominal scale factor (s = 0)
	std::optional<WarmupModel> warmup;  //!< absent: no turn-on term
	/** Bias per applied axial magnetic field (MagneticModel.h); absent: no field term (the
	 * compensator then ignores any field it is given). */
	std::optional<MagneticModel> magnetic;
	/** Gaps in the calibration runs longer than the rate window (burst logs): dT/dt cannot be
	 * estimated across a gap, so each restart's first samples (no rate yet) are left out of the
	 * fit. Reported by fog-calibrate; not stored in the file. */
	std::size_t rate_gaps = 0;
	/** The runs are burst logs whose continuous stretches are shorter than half the rate window,
	 * so that for most samples no rate can be estimated (the compensator would never run a model
	 * that reads rates): the model was fitted without rate signals. Reported by fog-calibrate;
	 * not stored in the file. */
	bool rates_unavailable = false;
	/** The largest reading quantum of the model's thermistors in the runs [degC]
	 * (readingQuantum_C; 0 = unquantised or not measured), which set the rate window when
	 * FitOptions::window_for_quantum. Reported by fog-calibrate; not stored in the file. */
	double reading_quantum_C = 0;

	/** Fallback model for a missing thermistor, or nullptr. */
	const BiasModel* fallbackFor(const std::string& thermistor) const;
};

/** A calibration file's content: one Calibration per calibrated axis (1 to 3, distinct axes,
 * same sensor label, thermistor layout, latitude and Earth-rate handling). */
struct CalibrationSet
{
	std::vector<Calibration> axes;
	/** The calibration of an axis, or nullptr. */
	const Calibration* forAxis(GyroAxis axis) const;
	/** Throws std::invalid_argument naming the first violation of the invariants above. */
	void validate() const;
};

/** Fits a calibration (see the file comment). run_labels (optional) names the runs in the file
 * and messages. Throws std::invalid_argument with the reason on data that cannot support the
 * model. */
Calibration fitCalibration(const std::vector<FogSeries>& runs, const std::string& preset, const FitOptions& options = {},
						   const std::vector<std::string>& run_labels = {});
/** fitCalibration() over runs read in sequential passes (obs/FogRun.h: e.g. spilled to a temporary
 * file by readFogRun()): the same numbers, with memory that does not grow with the runs' length
 * (one bit per sample; the non-causal savgol estimator loads each run's columns). */
Calibration fitCalibrationRuns(const std::vector<FogRun>& runs, const std::string& preset, const FitOptions& options = {},
						   const std::vector<std::string>& run_labels = {});

/** The latitude [deg] in the runs' `latitude_deg` metadata when every run states the same one,
 * else NaN (unknown). */
double commonLatitude_deg(const std::vector<FogSeries>& runs);

/** Runs the compensator over a series (e.g. a validation run) and returns labelled figures. */
FitFigures evaluateCalibration(const Calibration& cal, const FogSeries& series, const std::string& label,
							   double tau_s = 100.0);
/** The same over a run read in sequential passes (memory independent of its length). */
FitFigures evaluateCalibration(const Calibration& cal, const FogRun& run, const std::string& label, double tau_s = 100.0);

}  // namespace mrpt_fog
