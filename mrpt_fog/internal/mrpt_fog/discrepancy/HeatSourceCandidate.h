/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file HeatSourceCandidate.h
 * The temperature-channel candidate `heat_source`: an internal heat source the model lacks
 * (electronics, light source). Its signature in the thermistor residual (measured - simulated,
 * degC) is a response to the gyro's power: a first-order lag of the power signal,
 * h_tau(t) = power low-passed with time constant tau (the lag runs through data gaps and starts
 * settled at the first sample's power state), with the SAME sign (warmer) on every thermistor and
 * a larger amplitude nearer the source.
 *
 * Test: the common-mode residual (mean over thermistors) is regressed on [1, h_tau] by feasible
 * GLS with an ARMA(1,1) noise model estimated by REML (WhitenedRegression.h; exact start of
 * every block), the Wald chi-square of the amplitude deflated by the Bartlett long-run variance
 * factor of the whitened residual; tau by profile search over `tau_grid_s`, Sidak-corrected over
 * the grid; BIC gain = chi2 - ln(n_eff) - ln(grid), n_eff = n / long-run factor. Named when the
 * corrected p < alpha, the BIC gain > 0, the common amplitude is positive and every thermistor's
 * own amplitude (same tau, own noise model) is positive. Confidence = BIC weight against "no
 * effect": 1 / (1 + exp(-gain / 2)). The thermistor with the largest amplitude locates the source.
 * Needs a power change (power cycle) in the run: a constant power is absorbed by the offsets.
 */

#include <mrpt_fog/discrepancy/TemperatureChannel.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** The regressor h_tau at the given times (see file comment). */
std::vector<double> powerResponse(const std::vector<double>& time_s, const std::vector<double>& power, double tau_s);

/** Tests the temperature residual (`residual_C[i][k]`, NaN = unknown) of a run for an
 * unmodelled heat source. `power` empty = always on. */
HeatSourceResult testHeatSource(const std::vector<double>& time_s, const std::vector<double>& power,
								const std::vector<std::vector<double>>& residual_C,
								const std::vector<ThermistorInfo>& thermistors, const HeatSourceOptions& opt = {});

/** Confirmation on another run with tau fixed (HeatSourceConfirm, TemperatureChannel.h). */
HeatSourceConfirm confirmHeatSource(const std::vector<double>& time_s, const std::vector<double>& power,
									const std::vector<std::vector<double>>& residual_C, double tau_s, double alpha,
									int lrv_max_lag = 30);

}  // namespace mrpt_fog::discrepancy
