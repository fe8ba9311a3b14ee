/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimulatedRun.h
 * The simulator under test replayed on a measured run: what drives it (the chamber conditions
 * of that run), the model (device + effects + thermal time-constant scale) and the noise-free
 * simulated bias and thermistor temperatures at the run's samples.
 *
 * Driving input, first found of:
 *  1. the chamber profile the run followed, from SIM.yaml's `profile` or the run's metadata
 *     `sim.profile` (fog-sim records it). The run's power column, when present, must agree with
 *     the profile's power state (a check that the profile is the right one); the run's time
 *     axis starts at the profile's t = 0;
 *  2. the measured log alone: power, table rate and field from their columns (held from one
 *     run sample to the next; absent columns: powered, 0, 0), the chamber air reconstructed
 *     from the thermistors through the model's thermal network (ChamberReconstruction.h), with
 *     its 95 % uncertainty. Times from the run's first sample.
 * The simulator is stepped on the run's own sample grid (rate = 1 / median sample period),
 * exactly as fog-sim steps it, so a run simulated by fog-sim is replayed sample for sample;
 * samples missing from the run (gaps) are simply not compared.
 */

#include <mrpt_fog/discrepancy/ChamberReconstruction.h>
#include <mrpt_fog/discrepancy/SimulatorConfig.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** The model being calibrated: device, effects and a scale of every thermal time constant. */
struct SimModel
{
	sim::FogDevice device;
	sim::EffectSet effects;
	double thermal_time_scale = 1.0;  //!< every heat capacity x this (time constants x this)
};

/** Where the driving input came from. */
enum class DriveSource
{
	Profile,  //!< a chamber profile (SIM.yaml or the run's metadata)
	MeasuredLog  //!< the run's own columns, air reconstructed from the thermistors
};

/** The chamber conditions driving the simulator for one run. */
struct ChamberDrive
{
	DriveSource source = DriveSource::Profile;
	sim::ChamberProfile profile;  //!< Profile
	std::vector<sim::ChamberState> log_states;  //!< MeasuredLog: per simulator step
	AirReconstruction air;  //!< MeasuredLog: the reconstructed air and its uncertainty
	std::string how;  //!< e.g. "profile 'rich' from the run's metadata sim.profile"
	double rate_hz = 1.0;  //!< simulation grid
	std::vector<std::size_t> sim_index;  //!< run sample k -> simulator sample

	std::size_t steps() const;  //!< simulator steps
	sim::ChamberState stateAt(std::size_t step) const;
	sim::InitialThermalState initialState() const;
};

/** Resolves the driving input of `run` (see file comment); a reconstructed air uses the
 * configuration's model as given. Throws std::invalid_argument. */
ChamberDrive chamberDriveForRun(const FogSeries& run, const SimulatorConfig& cfg);

/** For a MeasuredLog drive: the air reconstructed again through `model`'s network (e.g. after
 * the thermal time scale was calibrated). A Profile drive is returned unchanged. */
ChamberDrive reconstructDriveWith(const ChamberDrive& drive, const SimModel& model, const FogSeries& run,
								  const AirReconstructionOptions& opt = {});

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
