/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file HeadingDeadReckoning.h
 * One gyro variant through the navigation chain: vertical FOG rate [deg/h] ->
 * StrapdownAttitude (VerticalOnly, Earth rate at the drive's latitude removed) -> heading ->
 * DeadReckoning2D with the wheel odometry distances. Starts from the truth pose (position and
 * heading) at the first common time, as an aligned vehicle would. */

#include "DriveData.h"

#include <mrpt_fog_nav/StrapdownAttitude.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <vector>

namespace mrpt_fog::drift
{
struct HeadingOptions
{
	double latitude_deg = 0.0;
	bool transport_rate = false;  //!< the simulator's drive is flat-Earth: off by default
	nav::RateSampling sampling = nav::RateSampling::IntervalAverage;  //!< fog-sim: mean over (t - dt, t]
};

struct VariantResult
{
	nav::Trajectory trajectory;  //!< dead-reckoned, at odometry times
	std::vector<double> t_s;  //!< gyro sample times used
	std::vector<double> yaw_rate_rad_s;  //!< gyro rate with the Earth rate removed (for the rawlog)
};

/** t_s: absolute sample times [s]; rate_dph: vertical gyro output [deg/h] (same size).
 * Throws std::runtime_error when the gyro, odometry and truth do not overlap in time. */
VariantResult deadReckonVariant(const std::vector<double>& t_s, const std::vector<double>& rate_dph,
								const DriveData& drive, const HeadingOptions& options);

}  // namespace mrpt_fog::drift
