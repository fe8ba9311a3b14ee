/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ScaleFactorModel.h
 * Scale factor versus temperature (IEEE Std 952: scale-factor temperature sensitivity) of one
 * gyro axis: the relative scale-factor error s [ppm] as a polynomial in one thermistor
 * temperature,
 *
 *   s_ppm(T) = sum_k coef_ppm[k] z^k,   z = (clamp(T, min_C, max_C) - centre_C) / scale_C,
 *
 * applied by the compensator after the bias: omega = (omega_raw - bias) / (1 + 1e-6 s_ppm).
 * The temperature is clamped to the calibrated range: the polynomial is never extrapolated.
 * Fitted by fitScaleFactor (ScaleFactorFit.h) from rate-table segments.
 */

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace mrpt_fog
{
struct ScaleFactorModel
{
	std::string thermistor;  //!< the temperature the model reads ("mean" or "weighted" with `thermistors`)
	/** Non-empty: the model reads the mean of these thermistors' readings, and `thermistor` is
	 * "mean" (fitScaleFactor with ScaleFactorFitOptions::thermistor_mean); or, with `weights`,
	 * their weighted sum and `thermistor` is "weighted". All must be valid, else the last value
	 * is held (Compensator.h). */
	std::vector<std::string> thermistors;
	/** Non-empty (same length as `thermistors`, summing to 1): T = sum weights[i] x reading i, an
	 * estimate of the coil's mean temperature, which the scale factor follows and no single
	 * thermistor reads in a transient (fitted from table segments in temperature transients and
	 * turn-ons, where the thermistors disagree; ScaleFactorFit.h). */
	std::vector<double> weights;
	double centre_C = 0.0;  //!< normalisation centre [degC]
	double scale_C = 1.0;  //!< normalisation half-width [degC] (> 0)
	double min_C = 0.0, max_C = 0.0;  //!< calibrated temperature range [degC] (inputs clamped to it)
	std::vector<double> coef_ppm;  //!< coefficient of z^k, k = 0..order [ppm]
	Eigen::MatrixXd covariance_ppm2;  //!< of coef_ppm [ppm^2]
	/** Mean temperature sensitivity over the calibrated range, (s(max) - s(min)) / (max - min)
	 * [ppm/degC], of this model's thermistor. */
	double slope_ppm_per_C = 0.0;
	/** 95 % interval of the coil's temperature sensitivity: the measurement-noise interval
	 * (slope_noise_ci95_*) widened by the errors in the temperature variable, i.e. from the lowest
	 * to the highest noise bound over the slopes measured against each thermistor of the layout
	 * (the coil's effective temperature taken as an unknown weighted mean of the thermistors;
	 * ScaleFactorFit.h, docs/reference/model.md). */
	double slope_ci95_lo_ppm_per_C = 0.0, slope_ci95_hi_ppm_per_C = 0.0;
	/** Measurement-noise-only 95 % interval of slope_ppm_per_C (coefficient covariance, Student t). */
	double slope_noise_ci95_lo_ppm_per_C = 0.0, slope_noise_ci95_hi_ppm_per_C = 0.0;
	/** Lowest and highest mean slope over the thermistors (same order) [ppm/degC]; equal to
	 * slope_ppm_per_C when the layout has one thermistor. */
	double slope_thermistor_min_ppm_per_C = 0.0, slope_thermistor_max_ppm_per_C = 0.0;
	std::size_t slope_thermistors = 0;  //!< thermistors the interval spans (0 = not computed, old file)
	double table_rate_min_abs_dph = 0.0, table_rate_max_abs_dph = 0.0;  //!< |applied rate| range used [deg/h]
	std::size_t segments = 0;  //!< rate-table segments used
	std::size_t samples = 0;  //!< samples in those segments
	double rms_in_sample_ppm = 0.0;  //!< residual RMS of the segment estimates [ppm]
	double rms_held_out_ppm = 0.0;  //!< leave-one-temperature-out RMS [ppm]
	std::string held_out_label;  //!< how rms_held_out_ppm was obtained

	std::size_t order() const { return coef_ppm.empty() ? 0 : coef_ppm.size() - 1; }
	/** s [ppm] at temperature temp_C (clamped to [min_C, max_C]; NaN in -> NaN out). */
	double evaluate_ppm(double temp_C) const
	{
		double v = temp_C < min_C ? min_C : temp_C;
		v = v > max_C ? max_C : v;
		const double z = (v - centre_C) / scale_C;
		double h = 0.0;
		for (std::size_t k = coef_ppm.size(); k-- > 0;) h = h * z + coef_ppm[k];
		return h;
	}
};

}  // namespace mrpt_fog
