/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file WarmupModel.h
 * The turn-on (warm-up) bias of one gyro axis: after a power-on at t_on, an extra bias
 *
 *   warmup_dph(t) = amplitude_dph * exp(-(t - t_on) / tau_s)
 *                 [+ amplitude2_dph * exp(-(t - t_on) / tau2_s)],   t >= t_on,
 *
 * on top of the thermal bias model (the residual the temperature terms do not explain: the
 * source and electronics settling). The compensator adds it from the turn-on on; before any
 * known turn-on it adds nothing. Fitted by fitWarmup (WarmupFit.h) from runs holding a turn-on.
 *
 * While the compensator runs the rate-free start-up model in the first rate window after a
 * turn-on (its rate windows cover less than half their length), it adds startup_offset_dph as
 * well: that model's own error at a turn-on (the thermistors' inner/outer differences of an
 * unpowered, uniform coil, which no powered calibration sample has), fitted on the same turn-ons.
 */

#include <cmath>
#include <string>
#include <vector>

namespace mrpt_fog
{
struct WarmupModel
{
	double amplitude_dph = 0.0;  //!< extra bias at the turn-on [deg/h]
	double tau_s = 1.0;  //!< decay time constant [s] (> 0)
	double amplitude_std_dph = 0.0;  //!< standard error of amplitude_dph [deg/h]
	double tau_std_s = 0.0;  //!< standard error of tau_s [s]
	double fitted_span_s = 0.0;  //!< time after the turn-on covered by the fit [s]
	std::size_t turn_ons = 0;  //!< turn-ons in the fitted runs
	std::size_t samples = 0;
	double rms_before_dph = 0.0;  //!< residual RMS of the bias model alone over the fitted span [deg/h]
	double rms_after_dph = 0.0;  //!< with the warm-up term [deg/h]
	/** Added while the rate-free start-up model runs in the first rate window after a turn-on
	 * [deg/h] (0: none fitted, e.g. a model without rates or files before it existed). */
	double startup_offset_dph = 0.0;
	double startup_offset_std_dph = 0.0;  //!< its standard error [deg/h]
	std::size_t startup_samples = 0;  //!< start-up samples it was fitted on

	/** Optional second term (tau2_s > tau_s; amplitude2_dph 0 = none): a turn-on seen through the
	 * bias model can hold two time constants (the thermal model's error at a turn-on, and the
	 * source's own settling). */
	double amplitude2_dph = 0.0;
	double tau2_s = 1.0;
	double amplitude2_std_dph = 0.0;
	double tau2_std_s = 0.0;

	bool hasSecondTerm() const { return amplitude2_dph != 0.0; }
	/** Extra bias [deg/h] at time_since_on_s after a turn-on (0 for a negative or NaN time). */
	double bias_dph(double time_since_on_s) const
	{
		if (!(time_since_on_s >= 0)) return 0.0;
		double b = amplitude_dph * std::exp(-time_since_on_s / tau_s);
		if (amplitude2_dph != 0.0) b += amplitude2_dph * std::exp(-time_since_on_s / tau2_s);
		return b;
	}
};

}  // namespace mrpt_fog
