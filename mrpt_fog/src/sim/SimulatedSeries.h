/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
// Private to the simulator: the empty series a simulated single-axis run fills.
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/FogDevice.h>

namespace mrpt_fog::sim
{
/** An empty series labelled FOG, z axis only, the device's thermistors, at the device's epoch (FogDevice::epoch_s). */
inline FogSeries emptySimulatedSeries(const FogDevice& device)
{
	FogSeries out;
	out.sensor_label = "FOG";
	out.epoch_s = device.epoch_s();
	out.has_axis = {false, false, true};
	for (const auto& t : device.thermistors) out.thermistors.push_back(t.info);
	out.temp_C.assign(device.thermistors.size(), {});
	return out;
}
}  // namespace mrpt_fog::sim
