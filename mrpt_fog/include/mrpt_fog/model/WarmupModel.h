/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file WarmupModel.h
 * The turn-on (warm-up) bias of one gyro axis: after a power-on at t_on, an extra bias
 *
 *   warmup_dph(t) = amplitude_dph * exp(-(t - t_on) / tau_s),   t >= t_on,
 *
 * on top of the thermal bias model (the residual the temperature terms do not explain: the
 * source and electronics settling). The compensator adds it from the turn-on on; before any
 * known turn-on it adds nothing. Fitted by fitWarmup (WarmupFit.h) from runs holding a turn-on.
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

	/** Extra bias [deg/h] at time_since_on_s after a turn-on (0 for a negative or NaN time). */
	double bias_dph(double time_since_on_s) const
	{
		return time_since_on_s >= 0 ? amplitude_dph * std::exp(-time_since_on_s / tau_s) : 0.0;
	}
};

}  // namespace mrpt_fog
