/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file OdometryRawlog.h
 * A dead-reckoned trajectory as stock MRPT observations, for MRPT's own localization apps
 * (pf-localization, which reads observations-only rawlogs):
 *
 *   for each pose:  CObservationOdometry (label odometry_label): odometry = (x, y, yaw)
 *                   CObservationIMU      (label imu_label): IMU_WZ = the gyro rate [rad/s]
 *
 * pf-localization keeps the latest odometry and runs one filter step (with the odometry
 * increment as the action) for every other observation; the IMU observation after each
 * odometry sample is what makes it step, and it carries the compensated yaw rate for any
 * consumer that wants it. Write the vector with a CFileGZOutputStream + archiveFrom (or,
 * in mrpt_fog programs, writeFogRawlog with an empty FogSeries, which is atomic). */

#include <mrpt/obs/CObservation.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <string>
#include <vector>

namespace mrpt_fog::nav
{
struct OdometryRawlogOptions
{
	std::string odometry_label = "ODOMETRY_FOG";
	std::string imu_label = "IMU_FOG";
	bool with_imu = true;  //!< interleave one CObservationIMU after each odometry
};

/** Observations for traj (timestamps = t_s as UNIX time). imu_rate_z_rad_s: the yaw rate
 * per pose (same size as traj); when empty it is the finite difference of the trajectory's
 * yaw (0 for the first pose). Throws std::invalid_argument when sizes differ. */
std::vector<mrpt::obs::CObservation::Ptr> makeOdometryObservations(
	const Trajectory& traj, const std::vector<double>& imu_rate_z_rad_s = {},
	const OdometryRawlogOptions& options = {});

}  // namespace mrpt_fog::nav
