/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogDevice.h
 * Everything that describes one simulated FOG: coil thermal network, winding, the
 * coefficients of each error source (see ErrorEffects.h), thermistors and gyro noise.
 * Defaults are the project's default device (docs/reference/simulator.md explains every choice; values marked
 * "estimate" are engineering estimates within the ranges of PHYSICS.md, not measurements).
 *
 * YAML overlay (every key optional; unknown keys are errors):
 *
 *   latitude_deg: 40
 *   coil:    {pattern: quadrupolar, fiber_length_m: 1500, mean_diameter_m: 0.1, fiber_layers: 48,
 *             midpoint_offset_m: 1.5, layer_length_mismatch: 0, refractive_index: 1.46, dn_dT_per_K: 1e-5, expansion_per_K: 5.5e-7}
 *   thermal: {layers: 8, sectors: 8, <any CoilThermalParams field>}
 *   errors:  {constant_bias_dph, radial_gradient_dph_per_C, gradient_rate_dph_per_C_per_min,
 *             hysteresis_dph, hysteresis_span_C, warmup_dph, warmup_tau_s, sf_ppm_per_C,
 *             sf_ref_C, magnetic_dph_per_uT, temp_poly_dph: [c1, c2, ...], temp_poly_ref_C}
 *   noise:   {arw_deg_rt_h, bias_instability_dph, bias_corr_time_s, rrw_deg_h_rt_h, angle_quantum_arcsec}
 *   turn_on: {bias_repeatability_dph, sf_repeatability_ppm, aging_dph_per_year, age_days}
 *   thermistors: [{name: Ti1, side: inner, angle_deg: 0, tau_s: 5, offset_C: 0.05}, ...]
 *   thermistor_noise_C: 0.003
 *   thermistor_quantum_C: 0.01
 */

#include <mrpt/containers/yaml_frwd.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/CoilThermalModel.h>
#include <mrpt_fog/sim/CoilWinding.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog::sim
{
/** Coefficients of the non-Shupe error sources (deg/h unless the name says otherwise). */
struct ErrorCoefficients
{
	double constant_bias_dph = 0.3;  //!< turn-on bias, constant (estimate)
	/** Each effect's scalar coefficient, indexed by Effect: its meaning, unit, device YAML key
	 * and default (the reasons for each default too) are the effect's descriptor in
	 * EffectRegistry.cpp. NaN for an effect whose strength is not one scalar. */
	std::array<double, kEffectCount> coefficients = defaultCoefficients();
	double& coefficient(Effect effect) { return coefficients[indexOf(effect)]; }
	double coefficient(Effect effect) const { return coefficients[indexOf(effect)]; }
	// The scalar coefficients by name (with their unit):
	double& radial_gradient_dph_per_C() { return coefficient(Effect::RadialGradient); }  //!< x (Tin - Tout)
	double radial_gradient_dph_per_C() const { return coefficient(Effect::RadialGradient); }
	double& gradient_rate_dph_per_C_per_min() { return coefficient(Effect::GradientRate); }  //!< x d(Tin - Tout)/dt
	double gradient_rate_dph_per_C_per_min() const { return coefficient(Effect::GradientRate); }
	double& hysteresis_dph() { return coefficient(Effect::Hysteresis); }  //!< heating minus cooling offset
	double hysteresis_dph() const { return coefficient(Effect::Hysteresis); }
	double& warmup_dph() { return coefficient(Effect::Warmup); }  //!< extra bias at power-on
	double warmup_dph() const { return coefficient(Effect::Warmup); }
	double& sf_ppm_per_C() { return coefficient(Effect::ScaleFactorTemp); }  //!< scale factor vs coil temperature
	double sf_ppm_per_C() const { return coefficient(Effect::ScaleFactorTemp); }
	double& magnetic_dph_per_uT() { return coefficient(Effect::Magnetic); }  //!< axial field sensitivity
	double magnetic_dph_per_uT() const { return coefficient(Effect::Magnetic); }

	// The fields that shape an effect without setting its strength (EffectDescriptor::shape_fields):
	double hysteresis_span_C = 5.0;  //!< temperature change to swap branch (1/e) (estimate)
	double warmup_tau_s = 600.0;  //!< decay time after power-on (estimate)
	double sf_ref_C = 25.0;  //!< temperature of the nominal scale factor
	/** Static bias c1 x + c2 x^2 + ... with x = T_electronics - temp_poly_ref_C (estimate). */
	std::vector<double> temp_poly_dph = {1.0e-3, 1.0e-5};
	double temp_poly_ref_C = 25.0;
};

/** Gyro noise (IEEE Std 952 terms). */
struct GyroNoiseParams
{
	double arw_deg_rt_h = 0.001;  //!< angle random walk N [deg/sqrt(h)] (PHYSICS.md)
	/** Bias instability [deg/h], simulated as a Gauss-Markov process of this sigma. */
	double bias_instability_dph = 0.003;  //!< PHYSICS.md: 0.003-0.01
	double bias_corr_time_s = 300.0;  //!< Gauss-Markov correlation time (estimate)
	double rrw_deg_h_rt_h = 1e-4;  //!< rate random walk K [deg/h/sqrt(h)] (PHYSICS.md: small)
	double angle_quantum_arcsec = 0.005;  //!< output angle LSB (estimate); 0 = none
};

/** What no chamber calibration holds: the bias offset and scale-factor error drawn at each
 * turn-on (turn-on to turn-on repeatability, IEEE Std 952) and a slow bias drift with the
 * device's age (aging). All zero by default (off): the bundled datasets do not contain them.
 * docs/reference/simulator-turn-on-and-aging.md gives sourced values. */
struct TurnOnParams
{
	double bias_repeatability_dph = 0.0;  //!< 1-sigma of the offset drawn at each power-on [deg/h]
	double sf_repeatability_ppm = 0.0;  //!< 1-sigma of the scale-factor error drawn at each power-on [ppm]
	double aging_dph_per_year = 0.0;  //!< bias drift with age [deg/h per year of 365.25 days]
	double age_days = 0.0;  //!< the device's age at t = 0 of the run [days]
	bool any() const
	{
		return bias_repeatability_dph != 0.0 || sf_repeatability_ppm != 0.0 || aging_dph_per_year != 0.0 || age_days != 0.0;
	}
};

/** One thermistor glued on the coil. */
struct ThermistorSpec
{
	ThermistorInfo info;  //!< name, side (inner/outer), angle on the coil [deg]
	double tau_s = 5.0;  //!< first-order lag (PHYSICS.md: 2-20 s bonded)
	double offset_C = 0.0;  //!< calibration offset (PHYSICS.md: ~0.1 C)
};

struct FogDevice
{
	std::string name = "default";
	double latitude_deg = 40.0;  //!< for the vertical Earth rate (PHYSICS.md example)
	CoilThermalParams thermal;
	WindingParams winding;
	ErrorCoefficients errors;
	GyroNoiseParams noise;
	TurnOnParams turn_on;  //!< turn-on offset and aging (off by default)
	std::vector<ThermistorSpec> thermistors;  //!< default: the seed's Ti1/To1 at 0, Ti2/To2 at 180 deg
	double thermistor_noise_C = 0.003;  //!< white reading noise (estimate)
	double thermistor_quantum_C = 0.01;  //!< reading resolution (PHYSICS.md)

	/** The project's default device (see docs/reference/simulator.md). */
	static FogDevice defaultDevice();
	/** Default device overlaid with a YAML document (see file comment); `source` names it in
	 * errors. Throws std::invalid_argument "<source>: <field>: <reason>". */
	static FogDevice fromYaml(const mrpt::containers::yaml& doc, const std::string& source);
	/** Reads a YAML device file (overlay on the default device). */
	static FogDevice fromFile(const std::string& path);

	/** The same device with every noise source off (gyro white noise, bias instability, rate
	 * random walk, angle quantisation, thermistor noise and quantisation): the deterministic
	 * response that model fits and reconstructions compare against. */
	FogDevice withoutNoise() const;
	/** The absolute time [s] of the run's t = 0: the simulator's epoch (ChamberRun.h), moved
	 * turn_on.age_days later, so that logs of an aging device carry their dates. */
	double epoch_s() const;
	/** Consistency checks (throws std::invalid_argument naming the field). */
	void validate() const;
	/** Every parameter as (key, value) text pairs, keys "device.<section>.<field>". */
	std::vector<std::pair<std::string, std::string>> describe() const;
};

}  // namespace mrpt_fog::sim
