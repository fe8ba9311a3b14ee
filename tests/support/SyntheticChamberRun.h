/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SyntheticChamberRun.h
 * A small, fully documented generator of chamber runs with KNOWN hidden effects, for the
 * model-gap proof trials (independent of the full simulator in mrpt_fog/sim, which the trials
 * also use where it fits). Physics kept deliberately simple and stated here:
 *  - chamber air temperature from a profile: all_conditions (ramps at 0.5/1/2 C/min, steps, a log sine
 *    sweep 40 -> 4 min periods, rate-table segments at -10/0/60 C, field segments, a power
 *    cycle; ~12.4 h; the simulator's ChamberProfile "rich" is another profile), ramp (one constant 1 C/min ramp 25 -> -40 C and a soak) or
 *    long_ramp (one slow 0.125 C/min ramp 25 -> -40 C: nothing but a constant rate);
 *  - coil: outer node first-order towards the air (tau 900 s), inner node first-order towards
 *    the outer node (tau 240 s), integrated exactly at 1 s sub-steps;
 *  - thermistors Ti1, Ti2 (inner) and To1, To2 (outer) with fixed offsets, white noise and
 *    optional quantisation; a hidden thermistor_lag lags them (first order) behind the nodes;
 *  - bias = static cubic in the true coil mean temperature x = (T - 20)/50:
 *    0.3 + 1.5 x + 0.8 x^2 - 0.6 x^3 [deg/h] (optionally perturbed run to run), plus the hidden
 *    effects, plus noise: AR(1) (correlation time 600 s) + white, 0.01 deg/h each by default;
 *  - each hidden effect's raw shape (truth, from the TRUE node temperatures) is scaled so that
 *    the RMS of its part NOT explained by a cubic in the true mean temperature plus constant
 *    (what a static:3 base model cannot absorb) is `ratio` x the noise RMS.
 * Hidden effect shapes: shupe_rate dTm/dt; radial_gradient Tin - Tout; gradient_rate
 * d(Tin - Tout)/dt; thermistor_lag f(T) - f(T_read) (tau scaled to reach the ratio);
 * hysteresis play-type branch of the true mean, h <- s + (h - s) exp(-|dT|/2 C), s = sign(dT)
 * (kept through soaks, like the simulator's); warmup exp(-(t - t_on)/700 s); scale_factor_temp
 * (Tm - 25) x table rate; magnetic field; temp_poly_order 0.6 x^4 - 0.4 x^5.
 */

#include <mrpt_fog/obs/FogSeries.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** The generator's chamber profiles (see the file comment). */
enum class SyntheticProfile
{
	AllConditions,  //!< ramps, steps, sine sweep, rate table, field, power cycle (~12.4 h)
	Ramp,  //!< one 1 C/min ramp 25 -> -40 C and a soak
	LongRamp  //!< one slow 0.125 C/min ramp 25 -> -40 C
};
/** "all_conditions", "ramp" or "long_ramp" (series metadata). */
const char* toString(SyntheticProfile p);

struct SyntheticRunOptions
{
	SyntheticProfile profile = SyntheticProfile::AllConditions;
	double dt_s = 10.0;  //!< output sample period [s]
	std::uint64_t seed = 1;
	std::map<std::string, double> hidden;  //!< effect id -> effect-to-noise ratio
	double white_noise_dph = 0.01;
	double ar_noise_dph = 0.01;  //!< stationary sigma of the AR(1) part
	double ar_corr_time_s = 600.0;
	double thermistor_noise_C = 0.002;
	double thermistor_quantum_C = 0.0;  //!< 0 = none
	bool gap = false;  //!< drop 20 min of samples in the middle of the run
	std::size_t outliers = 0;  //!< isolated spikes of +-outlier_dph
	double outlier_dph = 0.3;
	double static_coef_error = 0.0;  //!< relative sd of a run-to-run error of the static cubic
};

struct SyntheticRun
{
	FogSeries series;
	/** Scaled truth of each hidden effect at the series' samples [deg/h]. */
	std::map<std::string, std::vector<double>> effect_dph;
	double noise_rms_dph = 0.0;  //!< RMS of the noise process (stationary)
	double thermistor_tau_s = 0.0;  //!< lag used when thermistor_lag is hidden
};

/** Generates a run. Throws std::invalid_argument for an unknown effect id (or
 * heat_source, which concerns temperatures and is not generated here). */
SyntheticRun makeSyntheticChamberRun(const SyntheticRunOptions& opt);

/** The usual test run in one call: the all_conditions profile sampled every dt_s, with the given
 * seed and hidden effects (id -> effect-to-noise ratio), other options at their defaults. */
SyntheticRun makeSyntheticChamberRun(double dt_s, std::uint64_t seed = 1, const std::map<std::string, double>& hidden = {});

}  // namespace mrpt_fog::discrepancy
