/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimEffectTrial.h
 * Proof trials of the model-gap workflow on the REAL physics simulator (mrpt_fog/sim), with the
 * hidden effect scaled to an effect-to-noise ratio (the simulator-side twin of
 * SyntheticChamberRun + runTrial).
 *
 * Base run: the default device, only `earth_rate` on (every effect of the candidate library
 * off, heat_source included), plus the hidden effect. Ratio = RMS of the hidden effect's bias
 * contribution that the base model cannot absorb (OLS residual of the contribution on the base
 * design; a constant or a cubic part of an effect is not a missing effect) over the RMS of the
 * base fit's residual on the same run without the effect. The contribution is exact truth:
 * two simulator runs with the same seed (identical noise and thermal state), with and without
 * the effect, differ only by it (`FogSample::thermal_error_dph`). The effect's simulator
 * parameter is scaled by ratio x noise / contribution (computed on the analysed seed, not
 * tuned); it is linear in that parameter except the thermistor lag (tau: two secant steps).
 *
 * Parameter scaled per effect (reference = default device unless stated):
 *   shupe_rate         coil.dn_dT_per_K and coil.expansion_per_K together (Shupe gain)
 *   radial_gradient    errors.radial_gradient_dph_per_C
 *   gradient_rate      errors.gradient_rate_dph_per_C_per_min
 *   hysteresis         errors.hysteresis_dph (span 5 C kept)
 *   warmup             errors.warmup_dph (tau 600 s kept)
 *   scale_factor_temp  errors.sf_ppm_per_C
 *   magnetic           errors.magnetic_dph_per_uT
 *   temp_poly_order    errors.temp_poly_dph = k x {0, 0, 0, 1e-6, -2e-8} (x = T_electronics - 25 C:
 *                      a static bias above the cubic base's order)
 *   thermistor_lag     every thermistor's tau_s. A lag changes no bias by itself; it shows only
 *                      through a temperature-dependent bias the base model describes, so these
 *                      runs also carry a static cubic 0.3 + 1.5 x + 0.8 x^2 - 0.6 x^3 deg/h,
 *                      x = (T - 20 C)/50 C, in the TRUE temperature at the thermistor positions
 *                      (added to the simulator's output here: the simulator's own static term is
 *                      in the electronics temperature). The contribution is f(T read without
 *                      lag) - f(T read with lag).
 * The analysed run uses seed 2 s + 1, the confirmation run 2 s + 2 (same device).
 */

#include "support/DiscrepancyTrials.h"
#include <mrpt_fog/obs/FogSeries.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct SimTrialSpec
{
	std::string hidden;  //!< candidate id ("" = no hidden effect)
	double ratio = 1.0;  //!< effect-to-noise ratio (see file comment)
	std::uint64_t seed = 1;
	double rate_hz = 0.1;  //!< output rate of the simulated runs
	std::string profile = "rich";  //!< simulator chamber preset
	std::string base_preset = "static:3";
};

/** One simulated run of a trial plus its truth. */
struct SimTrialRun
{
	FogSeries series;
	std::vector<double> effect_dph;  //!< the hidden effect's bias contribution (empty when none)
	double noise_rms_dph = 0.0;  //!< RMS of the base fit's residual on the run without the effect
	double effect_rms_dph = 0.0;  //!< RMS of the contribution's part the base cannot absorb
};

/** The device of a trial: the hidden effect's parameter after scaling. */
struct SimTrialDevice
{
	std::string hidden;
	std::string parameter;  //!< what was scaled (see file comment)
	double parameter_value = 0.0;  //!< its value after scaling (tau_s, deg/h per C, ...)
	double scale = 1.0;  //!< factor applied to the reference value
};

/** Scales the hidden effect to the spec's ratio on the analysed seed and returns the analysed
 * run (seed 2 s + 1) and the confirmation run (2 s + 2) with the same device. Throws
 * std::invalid_argument for an unknown id, heat_source (a temperature-channel effect), a
 * ratio <= 0 or an unknown profile. */
struct SimTrialRuns
{
	SimTrialDevice device;
	SimTrialRun analysed, confirm;
};
SimTrialRuns makeSimTrialRuns(const SimTrialSpec& spec);

/** Runs the selection on the analysed run, confirms on the other, and scores it like runTrial
 * (named / clean / false naming; gap target against the oracle = base + the TRUE contribution
 * fitted on the analysed run). */
TrialOutcome runSimEffectTrial(const SimTrialSpec& spec, const SelectionOptions& opt = {});

/** The hidden ids the simulator trials cover (every bias-channel candidate). */
const std::vector<std::string>& simTrialEffects();

}  // namespace mrpt_fog::discrepancy
