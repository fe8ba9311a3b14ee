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

#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct HeatSourceOptions
{
	double alpha = 0.005;  //!< significance level after the Sidak correction over the grid
	std::vector<double> tau_grid_s = {120, 300, 600, 1200, 2400, 4800};
	int lrv_max_lag = 30;
};

struct ThermistorHeatResponse
{
	ThermistorInfo info;
	double amplitude_C = 0;  //!< residual at full power relative to unpowered [degC]
	double se_C = 0;  //!< its standard error (long-run corrected)
};

struct HeatSourceResult
{
	bool tested = false;
	std::string untestable_reason;  //!< e.g. "the run has no power change"
	bool named = false;  //!< significant, positive and same sign on all thermistors
	bool significant = false;  //!< the common-mode test alone
	bool same_sign = false;
	double tau_s = 0;
	double amplitude_C = 0, ci_low_C = 0, ci_high_C = 0;  //!< common mode, 95 %
	double chi2 = 0, p = 1, p_adjusted = 1, delta_bic = 0, confidence = 0;
	double lrv_factor = 1;
	std::vector<ThermistorHeatResponse> thermistors;
	std::string nearest;  //!< thermistor with the largest amplitude
	std::string sentence;  //!< one readable sentence
};

/** The regressor h_tau at the given times (see file comment). */
std::vector<double> powerResponse(const std::vector<double>& time_s, const std::vector<double>& power, double tau_s);

/** Tests the temperature residual (`residual_C[i][k]`, NaN = unknown) of a run for an
 * unmodelled heat source. `power` empty = always on. */
HeatSourceResult testHeatSource(const std::vector<double>& time_s, const std::vector<double>& power,
								const std::vector<std::vector<double>>& residual_C,
								const std::vector<ThermistorInfo>& thermistors, const HeatSourceOptions& opt = {});

/** Confirmation on another run with tau fixed: p-value of the common-mode amplitude (one
 * test, no grid) and whether it has the same (positive) sign. */
struct HeatSourceConfirm
{
	bool tested = false;
	bool confirmed = false;
	double p = 1, amplitude_C = 0;
};
HeatSourceConfirm confirmHeatSource(const std::vector<double>& time_s, const std::vector<double>& power,
									const std::vector<std::vector<double>>& residual_C, double tau_s, double alpha,
									int lrv_max_lag = 30);

}  // namespace mrpt_fog::discrepancy
