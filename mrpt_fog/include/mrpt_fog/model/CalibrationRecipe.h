/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CalibrationRecipe.h
 * The whole calibration of a gyro from whatever runs the user has, in one call: calibrate().
 *
 * What each run gives (decided from the data, under the data's own thermistor names):
 * - every -i run joins the bias fit (fitCalibrationRuns, Calibration.h): bias terms, their
 *   orders (curvature) and the ridge chosen by held-out error (FitOptions::selection auto);
 * - a run that holds a turn-on (a 0 -> 1 power step, or metadata power_on_time_s at or before
 *   its first sample, with a powered sample after it) keeps the first
 *   FitOptions::turn_on_exclusion_s after each turn-on out of the bias fit (default
 *   kSuggestedTurnOnExclusion_s) and, when no separate warm-up runs are given, fits the warm-up
 *   term (WarmupFit.h) on the residual of the bias model; separate warm-up runs fit it instead;
 * - a run that turns a rate table fits the scale factor vs temperature (ScaleFactorFit.h): its
 *   table samples leave the bias fit;
 * - a run whose field_uT column changes fits the magnetic sensitivity (through
 *   CalibrateOptions::magnetic_fit, the discrepancy room's fitter); a coefficient whose 95 %
 *   interval spans zero (|coefficient| < 1.96 standard errors: the field did not excite it) is
 *   not written, and the reason is given;
 * - a multi-axis log is calibrated per axis (AxisRuns.h).
 * The result holds the calibration of each axis and everything a report prints about it (which
 * runs did what, why a term was not fitted); programs format it (fog-calibrate).
 */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/MagneticModel.h>
#include <mrpt_fog/model/ScaleFactorFit.h>
#include <mrpt_fog/obs/FogRun.h>

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** Whether an optional part of the calibration is fitted when the runs hold what it needs. */
enum class PartFit
{
	Auto = 0,  //!< fitted when a run holds what it needs
	Off = 1  //!< never fitted
};
const char* toString(PartFit p);
/** "auto" or "off"; throws std::invalid_argument naming the choices. */
PartFit partFitFromString(const std::string& text);

/** Fits the magnetic sensitivity of `cal` on the runs that have a field column; returns
 * std::nullopt with `why_not` set when the runs cannot support it (e.g. no field variation). */
using MagneticFitter =
	std::function<std::optional<MagneticModel>(const Calibration& cal, const std::vector<FogSeries>& runs_with_field,
												std::string& why_not)>;

struct CalibrateOptions
{
	/** The bias fit's options; turn_on_exclusion_s defaults to kSuggestedTurnOnExclusion_s here. */
	FitOptions fit = recipeFitOptions();
	/** Model preset (ModelPreset.h): the candidate terms the selection chooses among. */
	std::string model = "multipoint";
	PartFit scale_factor = PartFit::Auto;
	ScaleFactorFitOptions scale_factor_fit;
	PartFit magnetic = PartFit::Auto;
	/** The magnetic fitter (discrepancy/MagneticFit.h: discrepancy::magneticFitter()); empty: the
	 * magnetic section is never fitted, and a run with field segments gets a note saying so. */
	MagneticFitter magnetic_fit;
	/** One-thermistor devices: refinement of the automatically selected bias model by its
	 * held-out stability at FitOptions::tau_s (the figure the calibration is judged on; the
	 * selection itself scores every sample, where a noisy gyro's white noise hides a curvature):
	 * the chosen model plus T^2, plus T^2 and T^3, and, when the chosen model reads lag rates, the
	 * same three without them; a candidate replaces the chosen model when its held-out stability
	 * is lower by at least refine_min_gain. Not applied with several thermistors: on the bundled
	 * four-thermistor device a curvature term that lowers the chamber runs' held-out stability by
	 * 10 % made the heading over tuning drives worse (docs/validation/calibration-default.md).
	 * Off (the default): the selection's model. Measured on a real one-sensor burst log (odd
	 * bursts fitted, even ones judged: docs/validation/calibration-default.md) it made two of
	 * three axes worse, so it stays an option for studies. */
	PartFit refine = PartFit::Off;
	double refine_min_gain = 0.05;  //!< relative held-out stability gain a refinement needs
	/** Exponential terms of the warm-up: 0 = chosen by held-out error (selectWarmupTerms), 1 or 2. */
	std::size_t warmup_exponentials = 0;
	/** Axes to calibrate; empty: every axis the runs share. */
	std::vector<GyroAxis> axes;

	/** FitOptions with the recipe's defaults: the hour after a turn-on out of the bias fit. */
	static FitOptions recipeFitOptions()
	{
		FitOptions f;
		f.turn_on_exclusion_s = kSuggestedTurnOnExclusion_s;
		return f;
	}
};

/** The runs of a calibration (labels name them in messages and reports). */
struct CalibrationRuns
{
	std::vector<FogRun> runs;  //!< the calibration runs (bias fit; the -i runs)
	std::vector<std::string> labels;
	std::vector<FogRun> warmup_runs;  //!< runs only for the warm-up term (optional)
	std::vector<std::string> warmup_labels;
	std::vector<FogRun> validation;  //!< at most one independent run for validation figures
	std::string validation_label;
};

/** What a calibration run holds about turn-ons, and what the recipe did with it. */
struct TurnOnUse
{
	enum class Use
	{
		None = 0,  //!< no turn-on
		ExcludedToWarmupFit = 1,  //!< first hour out of the bias fit; the run fitted the warm-up term
		ExcludedWarmupFromOtherRuns = 2,  //!< first hour out of the bias fit; the term from the warm-up runs
		InBiasFit = 3  //!< exclusion 0: the whole run in the bias fit, no term from it
	};
	std::string label;
	std::size_t turn_on_events = 0;  //!< 0 -> 1 power steps
	bool power_on_metadata = false;  //!< metadata power_on_time_s at or before the first sample
	std::size_t gyro_off_rows = 0;
	Use use = Use::None;
};

/** One axis' calibration and what its report needs. */
struct AxisCalibration
{
	Calibration cal;
	ScaleFactorFitReport sf_report;
	std::size_t run_count = 0;
	bool table_rates = false;
	std::string why_empty;  //!< why no thermal term was kept ("" unless the model is a constant)
	std::vector<std::string> skipped;  //!< runs left out for this axis, with the reason
	bool earth_rate_removed = false;
	bool validated = false;
	std::string warmup_terms_why;  //!< how the warm-up term count was chosen
	std::string warmup_why_not;  //!< why the runs' turn-ons gave no warm-up term ("" otherwise)
	std::string magnetic_why_not;  //!< why no magnetic section was written ("" otherwise)
	/** The refinement (CalibrateOptions::refine): each candidate's held-out stability [deg/h]
	 * and what was kept, one line each ("" when none was tried). */
	std::vector<std::string> refinement;
	/** Held-out figures without data behind them: why ("" when cal.held_out.valid). */
	std::string held_out_why_not;
};

struct CalibrationOutcome
{
	std::vector<AxisCalibration> axes;
	std::vector<TurnOnUse> turn_ons;  //!< one per calibration run, in order
	/** Warm-up runs that are also calibration runs (the same label): noted, used for both. */
	std::vector<std::string> warmup_also_calibration;
	CalibrationSet set() const;
};

/** Holds a turn-on: a 0 -> 1 power step, or metadata power_on_time_s at or before the first
 * sample with a powered sample after it. */
TurnOnUse turnOnsOf(const FogRun& run, const std::string& label);

/** The calibration of every axis from `runs` (see the file comment). Throws
 * std::invalid_argument / std::runtime_error with the reason when the runs cannot support a
 * part they ask for (a table run whose scale factor cannot be fitted, warm-up runs whose
 * turn-ons resolve no decay). A model with no thermal term is returned (AxisCalibration::why_empty
 * says why); refusing to write it is the caller's choice. */
CalibrationOutcome calibrate(const CalibrationRuns& runs, const CalibrateOptions& options = {});

}  // namespace mrpt_fog
