/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ChamberRun.h
 * A static gyro (sensitive axis vertical) in a thermal chamber following a ChamberProfile,
 * sampled at rate_hz, as a FogSeries: rate_z_dph, the device's thermistors, the power column,
 * and table_rate_dph / field_uT when the profile uses them. The metadata records everything
 * needed to regenerate the run bit for bit (program version, profile, seed, effects, rate and
 * every device parameter) plus latitude_deg. */

#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/ErrorEffects.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace mrpt_fog::sim
{
/** The fixed UNIX epoch of simulated runs: 2024-05-01T00:00:00Z (reproducible timestamps). */
constexpr double kSimEpoch_s = 1714521600.0;

/** Settings shared by the chamber and vehicle runs. */
struct SimSettings
{
	std::uint64_t seed = 20240501;  //!< run seed (= kDefaultSeed, SimRandom.h)
	double rate_hz = 10.0;  //!< output sample rate [Hz] (> 0, <= 1000)
	EffectSet effects = defaultEffects();
	std::string profile_source;  //!< what to record as the profile (preset name or file)

	/** Throws std::invalid_argument if rate_hz is out of range. */
	void validate() const;
};

/** Simulates the chamber run. Throws std::invalid_argument on bad settings. */
FogSeries simulateChamber(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings);

/** The run simulateChamber() returns, without samples: label, epoch, axis, thermistors, metadata;
 * the optional columns it fills (table_rate_dph, field_uT when the profile uses them; power)
 * hold one NaN (FogLogReader::header()'s form, what FogLogWriter takes). */
FogSeries chamberRunHeader(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings);

/** simulateChamber()'s samples one at a time, in order (a long run need not be held):
 * f(time_s, rate_z_dph, temp_C, table_rate_dph, field_uT, power) with the values simulateChamber()
 * stores (table / field are passed whether or not the run has the column). Stops after the last
 * sample whose time is <= max_time_s + 1e-9 (fog-sim --duration-s; infinity: the whole profile). */
using ChamberSampleSink = std::function<void(double time_s, double rate_z_dph, const std::vector<double>& temp_C,
											 double table_rate_dph, double field_uT, double power)>;
void simulateChamberSamples(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings,
							double max_time_s, const ChamberSampleSink& f);

/** Writes the common simulator metadata (sim.*, device.*, latitude_deg) into a series. */
void recordSimMetadata(FogSeries& series, const std::string& scenario, const ChamberProfile& profile,
					   const FogDevice& device, const SimSettings& settings);

}  // namespace mrpt_fog::sim
