/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimulatorConfig.h
 * A simulator configuration as the model under test (`fog-discrepancy --sim SIM.yaml`): the
 * fog-sim device, which effects are on, which parameters are free (calibrated to the measured
 * run) and where the chamber conditions that drive the simulator come from.
 *
 *   device: {...}              # FogDevice YAML overlay (FogDevice.h), or
 *   device_file: gyro.yaml     # the same in a file (relative to SIM.yaml)
 *   effects: [shupe_rate, radial_gradient, earth_rate]   # fog-sim --effect syntax; default all
 *   free: [constant_bias_dph, radial_gradient_dph_per_C, thermal_time_scale]  # default: see below
 *   profile: rich              # chamber profile the runs followed (preset or file); default:
 *                              # the run's metadata `sim.profile`
 *
 * Free parameter ids (freeParameterIds()): constant_bias_dph; the coefficient of each bias
 * effect: winding_asymmetry_m (shupe_rate, the coil's midpoint offset), radial_gradient_dph_per_C
 * (elasto-optic), gradient_rate_dph_per_C_per_min, hysteresis_dph, warmup_dph, sf_ppm_per_C,
 * magnetic_dph_per_uT, temp_poly_dph (all its coefficients); temperature channel:
 * thermal_time_scale (every heat capacity x s, so every time constant x s), electronics_power_W
 * (heat_source), thermistor_offsets_C (one offset per thermistor).
 * Default free set (defaultFreeParameters): constant_bias_dph, thermistor_offsets_C,
 * thermal_time_scale, and the coefficient of every enabled effect that has one.
 */

#include <mrpt/containers/yaml_frwd.h>
#include <mrpt_fog/sim/ErrorEffects.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct SimulatorConfig
{
	std::string source;  //!< file name (error messages, report)
	sim::FogDevice device = sim::FogDevice::defaultDevice();
	sim::EffectSet effects = sim::defaultEffects();
	std::vector<std::string> free;  //!< free parameter ids (resolved)
	bool free_is_default = true;
	std::string profile;  //!< chamber profile override ("" = from the run's metadata)
};

/** Every free parameter id, in a fixed order. */
const std::vector<std::string>& freeParameterIds();

/** The free parameter holding the coefficient of a simulator effect ("" when it has none:
 * thermistor_lag, earth_rate). */
std::string coefficientParameterOf(const std::string& effect_id);

/** The documented default free set for an effect set. */
std::vector<std::string> defaultFreeParameters(const sim::EffectSet& effects);

/** Reads SIM.yaml. Throws std::invalid_argument "<file>: <field>: <reason>" on any problem
 * (unknown key, effect or free parameter id; bad device overlay). */
SimulatorConfig readSimulatorConfig(const std::string& path);

/** The same from a parsed document (`source` names it; device_file is relative to base_dir). */
SimulatorConfig simulatorConfigFromYaml(const mrpt::containers::yaml& doc, const std::string& source,
										const std::string& base_dir = ".");

}  // namespace mrpt_fog::discrepancy
