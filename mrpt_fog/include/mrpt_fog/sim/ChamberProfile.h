/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ChamberProfile.h
 * What a thermal chamber (or a vehicle cabin) does to the gyro over time: chamber-air
 * temperature [degC], gyro power, applied rate-table rotation [deg/h] and axial magnetic field
 * [uT], as a list of segments read from YAML or taken from a built-in preset.
 *
 * YAML (times in minutes, temperatures in degC):
 *
 *   name: my_profile
 *   initial_temp_C: 25
 *   power_initially: true          # gyro powered at t = 0
 *   initial_state: steady          # steady (thermal equilibrium at t = 0) | cold (unpowered soak)
 *   segments:
 *     - {type: hold, duration_min: 30}
 *     - {type: ramp, to_C: -40, rate_C_per_min: 1}
 *     - {type: step, to_C: 10}                       # instantaneous air change
 *     - {type: sine, amplitude_C: 5, period_min: 10, cycles: 3}      # about the current temp
 *     - {type: sweep, amplitude_C: 5, period_start_min: 40, period_end_min: 2, duration_min: 120}
 *     - {type: power, on: false}                     # instantaneous settings that persist
 *     - {type: table, rate_dph: 3600}
 *     - {type: field, field_uT: 200}
 *
 * Bad input (unknown type or key, missing or non-numeric field, non-positive duration/rate,
 * ramp rate 0) throws std::invalid_argument naming the source and the field, e.g.
 * "b.yaml: segments[3].rate_C_per_min: must be > 0". */

#include <mrpt/containers/yaml_frwd.h>

#include <string>
#include <vector>

namespace mrpt_fog::sim
{
/** Chamber conditions at one instant. */
struct ChamberState
{
	double air_C = 25.0;  //!< chamber (or cabin) air temperature [degC]
	bool power_on = true;  //!< gyro powered
	double table_rate_dph = 0.0;  //!< applied rotation about the sensitive axis [deg/h]
	double field_uT = 0.0;  //!< applied axial magnetic field [uT]
};

/** One profile segment (internal form; times in seconds). */
struct ProfileSegment
{
	enum class Kind
	{
		Hold,
		Ramp,
		Step,
		Sine,
		Sweep,
		Power,
		Table,
		Field
	};
	Kind kind = Kind::Hold;
	double start_s = 0;  //!< filled by the profile
	double duration_s = 0;  //!< 0 for instantaneous settings
	double from_C = 0;  //!< air temperature at the segment start (filled by the profile)
	double to_C = 0;  //!< ramp/step target [degC]
	double amplitude_C = 0;  //!< sine/sweep amplitude [degC]
	double period_s = 0;  //!< sine period; sweep start period [s]
	double period_end_s = 0;  //!< sweep end period [s]
	double value = 0;  //!< power (1/0), table rate [deg/h] or field [uT]
};

/** How the thermal state is initialised at t = 0. */
enum class InitialThermalState
{
	Steady,  //!< equilibrium with the t = 0 conditions (power included)
	Cold  //!< unpowered equilibrium at the initial air temperature (cold start)
};

class ChamberProfile
{
   public:
	/** Parses a YAML document (see file comment); `source` names it in error messages. */
	static ChamberProfile fromYaml(const mrpt::containers::yaml& doc, const std::string& source);
	/** Reads a YAML file; throws std::invalid_argument naming the file on any error. */
	static ChamberProfile fromFile(const std::string& path);
	/** Built-in profile by name (see presetNames()); throws std::invalid_argument otherwise. */
	static ChamberProfile preset(const std::string& name);
	/** Names of the built-in chamber presets: seed, B, warmup, rich, ratetable, drive_cabin. */
	static std::vector<std::string> presetNames();
	/** YAML text of a preset (what preset(name) parses). */
	static std::string presetYaml(const std::string& name);

	const std::string& name() const { return name_; }
	double duration_s() const { return duration_s_; }
	InitialThermalState initialState() const { return initial_state_; }
	const std::vector<ProfileSegment>& segments() const { return segments_; }

	/** Conditions at time t [s] (t < 0 -> initial; t > duration -> final). Instantaneous
	 * settings at time t apply from t on. */
	ChamberState stateAt(double t_s) const;

   private:
	std::string name_;
	double initial_C_ = 25.0;
	bool power_initially_ = true;
	InitialThermalState initial_state_ = InitialThermalState::Steady;
	std::vector<ProfileSegment> segments_;
	double duration_s_ = 0;
};

}  // namespace mrpt_fog::sim
