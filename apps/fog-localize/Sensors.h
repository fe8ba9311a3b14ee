/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file Sensors.h
 * Simulated 2D laser scans on the world's grid at the true poses, by MRPT's own simulator
 * (COccupancyGridMap2D::laserScanSimulator): a 360-degree scanner on the vehicle's roof,
 * range noise Gaussian, rays that hit nothing within the range are invalid (no return). The
 * noise comes from MRPT's global random generator, seeded here (the scans are the same for
 * every gyro and every filter seed). */

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <cstdint>
#include <vector>

namespace mrpt_fog::localize
{
struct LaserOptions
{
	double range_m = 60.0;
	std::size_t rays = 181;  //!< over 360 deg (2 deg apart)
	double range_noise_m = 0.05;
	std::uint64_t seed = 20240501;
};

/** One scan (label "LASER") at each time of scan_t_s, from the truth pose interpolated there. */
std::vector<mrpt::obs::CObservation2DRangeScan::Ptr> simulateScans(const mrpt::maps::COccupancyGridMap2D& grid,
																	const nav::Trajectory& truth,
																	const std::vector<double>& scan_t_s,
																	const LaserOptions& options);

/** Number of valid returns of a scan. */
std::size_t validReturns(const mrpt::obs::CObservation2DRangeScan& scan);

}  // namespace mrpt_fog::localize
