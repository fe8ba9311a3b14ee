/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ScaleFactorFit.h
 * Fits the scale factor versus temperature (ScaleFactorModel.h) from rate-table runs, the way
 * IEEE Std 952 measures it: rates of both signs at soaked temperatures.
 *
 *  1. Segments: maximal stretches of one constant, non-zero applied rate (`table_rate_dph`)
 *     with the gyro powered; the first `settle_s` of each are dropped (table acceleration,
 *     causal rate-window refill); segments shorter than `min_segment_s` after that are skipped.
 *  2. Per segment: e = raw - bias - applied [deg/h] with the bias from the given (bias-only)
 *     calibration run through the causal compensator, so the scale-factor estimate sees what the
 *     real-time compensator will; s_seg = 1e6 mean(e) / applied [ppm] at the segment's mean
 *     thermistor temperature.
 *  3. Temperature groups: segments whose mean temperatures (first candidate thermistor) lie
 *     within `group_gap_C` of each other form one soak.
 *  4. Candidates: each thermistor x polynomial order min_order..max_order (order + 2 <= groups, so that
 *     every held-out fit stays determined); held-out error = RMS over all segments of the
 *     prediction by the fit without the segment's group (leave-one-temperature-out; the
 *     polynomial is extrapolated there, not clamped, so an over-fitted order pays for it). The
 *     choice: the smallest held-out RMS, then the lowest order (and first thermistor) within
 *     `prefer_simpler` of it.
 *  5. Final fit on all segments (ordinary least squares on z in [-1, 1]); covariance
 *     sigma^2 (Z'Z)^-1 with sigma^2 = RSS / (n - p); the mean slope over the calibrated range
 *     and its measurement-noise 95 % interval (Student t, n - p degrees of freedom).
 *  6. Errors in the temperature variable: the scale factor follows the coil's (mean) temperature,
 *     which no thermistor reads; the thermistors disagree on how far it moved between soaks
 *     (gradients, lags, soaks not fully settled), and a slope measured against one of them is
 *     off by that ratio, an error no noise interval covers and that does not average out over
 *     seeds. Taking the coil temperature as an unknown weighted mean (weights >= 0) of the
 *     thermistor readings, its slope lies between the lowest and the highest slope measured
 *     against each thermistor (same order, same segments). The reported 95 % interval runs from
 *     the lowest lower noise bound to the highest upper one over the thermistors; with one
 *     thermistor it is the noise interval.
 *
 * Throws ScaleFactorFitError (a std::invalid_argument) with the reason when the runs cannot
 * support a fit: no table-rate column, no usable segment, fewer than 2 temperature groups, a
 * temperature span under `min_span_C`, or only one rate sign (bias and scale factor are then
 * not separated).
 */

#include <mrpt_fog/model/Calibration.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_fog
{
struct ScaleFactorFitOptions
{
	double settle_s = 10.0;  //!< dropped at the start of each table segment [s]
	double min_segment_s = 30.0;  //!< shortest usable segment after settle_s [s]
	double group_gap_C = 3.0;  //!< segments closer than this in temperature are one soak [degC]
	double min_span_C = 10.0;  //!< narrowest temperature span accepted [degC]
	int max_order = 3;  //!< highest polynomial order tried (<= 5)
	/** Lowest polynomial order tried (0..max_order). 1 when a temperature dependence is already
	 * established by another test (the model-gap workflow's naming of scale_factor_temp): the
	 * held-out error then chooses among orders >= 1 and the thermistor, and cannot answer "no
	 * dependence" with a constant. Needs min_order + 2 soaks. */
	int min_order = 0;
	double prefer_simpler = 0.05;  //!< a simpler candidate within this relative held-out RMS wins
	/** true: the model reads the mean of all the layout's thermistors (the only temperature
	 * candidate; orders chosen as above) instead of the best single thermistor. At soaks every
	 * thermistor reads the same, so the held-out error cannot choose between them; in a transient
	 * the mean of inner and outer readings is nearer the coil's mean temperature, which the
	 * scale factor follows (docs/validation/navigation.md, error budget). */
	bool thermistor_mean = false;
};

/** One rate-table segment as the fit saw it (returned for reports and tests). */
struct ScaleFactorSegment
{
	std::size_t run = 0;  //!< index into the runs
	double t_begin_s = 0, t_end_s = 0;  //!< used part [s]
	double applied_dph = 0;  //!< table rate [deg/h]
	std::size_t samples = 0;
	std::vector<double> temp_C;  //!< mean temperature per thermistor of the layout [degC]
	double s_ppm = 0;  //!< measured scale-factor error [ppm]
	int group = 0;  //!< temperature group (soak) index
};

/** The candidates' held-out errors and the segments: what the choice was made from. */
struct ScaleFactorFitReport
{
	struct Candidate
	{
		std::string thermistor;
		int order = 0;
		double rms_held_out_ppm = 0;
	};
	std::vector<Candidate> candidates;
	std::vector<ScaleFactorSegment> segments;
	std::size_t groups = 0;
};

class ScaleFactorFitError : public std::invalid_argument
{
   public:
	using std::invalid_argument::invalid_argument;
};

/** True when some run applies a non-zero table rate while powered (a run fog-calibrate must not
 * reduce to a bias fit silently). */
bool hasTableRates(const std::vector<FogSeries>& runs);

/** Fits the scale-factor model of `bias_cal`'s axis from the table segments of `runs` (see the
 * file comment); `bias_cal` must have no scale-factor model. run_labels name runs in messages. */
ScaleFactorModel fitScaleFactor(const std::vector<FogSeries>& runs, const Calibration& bias_cal,
								const ScaleFactorFitOptions& options = {}, ScaleFactorFitReport* report = nullptr,
								const std::vector<std::string>& run_labels = {});

}  // namespace mrpt_fog
