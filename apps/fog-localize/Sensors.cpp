/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "Sensors.h"

#include <mrpt/random/RandomGenerators.h>

#include <cmath>

namespace mrpt_fog::localize
{
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> simulateScans(const mrpt::maps::COccupancyGridMap2D& grid,
																	const nav::Trajectory& truth,
																	const std::vector<double>& scan_t_s,
																	const LaserOptions& o)
{
	mrpt::random::getRandomGenerator().randomize(static_cast<uint32_t>(o.seed));
	std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> out;
	out.reserve(scan_t_s.size());
	for (double t : scan_t_s)
	{
		const nav::TrajectoryPoint p = nav::interpolate(truth, t);
		auto scan = mrpt::obs::CObservation2DRangeScan::Create();
		scan->sensorLabel = "LASER";
		scan->timestamp = mrpt::Clock::fromDouble(t);
		scan->aperture = static_cast<float>(2 * M_PI * (o.rays - 1) / o.rays);  // no duplicated ray at +-180 deg
		scan->maxRange = static_cast<float>(o.range_m);
		scan->rightToLeft = true;
		scan->stdError = static_cast<float>(o.range_noise_m);
		grid.laserScanSimulator(*scan, mrpt::poses::CPose2D(p.x_m, p.y_m, p.yaw_rad), 0.5f, o.rays,
								static_cast<float>(o.range_noise_m));
		out.push_back(scan);
	}
	return out;
}

std::size_t validReturns(const mrpt::obs::CObservation2DRangeScan& scan)
{
	std::size_t n = 0;
	for (std::size_t i = 0; i < scan.getScanSize(); ++i) n += scan.getScanRangeValidity(i) ? 1 : 0;
	return n;
}

}  // namespace mrpt_fog::localize
