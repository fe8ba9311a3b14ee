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
#include <string>

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

/** Writes the common simulator metadata (sim.*, device.*, latitude_deg) into a series. */
void recordSimMetadata(FogSeries& series, const std::string& scenario, const ChamberProfile& profile,
					   const FogDevice& device, const SimSettings& settings);

}  // namespace mrpt_fog::sim
