/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimulatedRun.h
 * The simulator under test replayed on a measured run: what drives it (the chamber conditions
 * of that run), the model (device + effects + thermal time-constant scale) and the noise-free
 * simulated bias and thermistor temperatures at the run's samples.
 *
 * Driving input: the chamber profile the run followed, taken from SIM.yaml's `profile` or the
 * run's metadata `sim.profile` (fog-sim records it). The measured columns themselves never carry
 * the chamber air temperature; when neither source names a profile an std::invalid_argument says
 * so. The run's power column, when present, must agree with the profile's power state (a check
 * that the profile is the right one). The simulator is stepped on the run's own sample grid
 * (rate = 1 / median sample period, times k / rate from the profile start), exactly as fog-sim
 * steps it, so a run simulated by fog-sim is replayed sample for sample; samples missing from
 * the run (gaps) are simply not compared.
 */

#include <mrpt_fog/discrepancy/SimulatorConfig.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** The chamber conditions driving the simulator for one run. */
struct ChamberDrive
{
	sim::ChamberProfile profile;
	std::string how;  //!< e.g. "profile 'rich' from the run's metadata sim.profile"
	double rate_hz = 1.0;  //!< simulation grid
	std::vector<std::size_t> sim_index;  //!< run sample k -> simulator sample
};

/** Resolves the driving input of `run` (see file comment). Throws std::invalid_argument. */
ChamberDrive chamberDriveForRun(const FogSeries& run, const SimulatorConfig& cfg);

/** The model being calibrated: device, effects and a scale of every thermal time constant. */
struct SimModel
{
	sim::FogDevice device;
	sim::EffectSet effects;
	double thermal_time_scale = 1.0;  //!< every heat capacity x this (time constants x this)
};

SimModel simModelFromConfig(const SimulatorConfig& cfg);

/** Noise-free simulated signals at the run's samples. */
struct SimTrace
{
	std::vector<double> bias_dph;  //!< rate - table rate; NaN while unpowered
	std::vector<std::vector<double>> temp_C;  //!< per RUN thermistor (matched by name)
	/** Simulated electronics-board temperature [degC]: the temperature of the simulator's static
	 * bias polynomial (temp_poly_order), hence the model's "static temperature". */
	std::vector<double> electronics_C;
};

/** Simulates `model` with every noise source off on the drive's grid, mapped to the run's
 * samples. Throws std::invalid_argument when a run thermistor is absent from the device. */
SimTrace simulateOnRun(const SimModel& model, const ChamberDrive& drive, const FogSeries& run);

/** Scalar parameter slots: temp_poly_dph has one per coefficient (`temp_poly_dph[i]`),
 * thermistor_offsets_C one per device thermistor (`thermistor_offsets_C[name]`). */
struct ParamSlot
{
	std::string id;
	int index = 0;
	std::string label() const;
};
/** Expands free parameter ids into slots for a model (ids whose effect is off are dropped). */
std::vector<ParamSlot> expandSlots(const std::vector<std::string>& free, const SimModel& model);
double getParam(const SimModel& m, const ParamSlot& s);
/** Sets a value (clamped where the simulator requires: hysteresis >= 0, power > 0, scale > 0). */
void setParam(SimModel& m, const ParamSlot& s, double v);

}  // namespace mrpt_fog::discrepancy
