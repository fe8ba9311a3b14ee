/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file DeadReckoning.h
 * Position from wheel odometry (distance travelled) and a gyro attitude: the vehicle moves
 * along its body x axis (no side slip). Over each odometry interval the vehicle is taken to
 * follow a constant-curvature arc between the attitudes at the interval's ends, so the
 * displacement is
 *   chord = distance * sinc(dpsi / 2),  along the mid-interval heading,
 * exact for a circle driven at constant speed and yaw rate (2D), second order otherwise.
 *
 * Units: distance [m], times [s], angles [rad]. Bad input (non-increasing time, non-finite
 * distance, odometry time outside the attitude track) throws std::invalid_argument /
 * std::out_of_range naming the time. */

#include <mrpt_fog_nav/Trajectory.h>

#include <vector>

namespace mrpt_fog::nav
{
/** Distance travelled [m] along the body x axis over (previous t_s, t_s]; negative when
 * reversing. */
struct OdometryIncrement
{
	double t_s = 0.0;
	double distance_m = 0.0;
};

/** Distance increments from speed samples [m/s] at the given times (trapezoid rule); the
 * first sample gives the start time (no increment). Throws if sizes differ or time does
 * not increase. */
std::vector<OdometryIncrement> odometryFromSpeed(const std::vector<double>& t_s, const std::vector<double>& speed_mps);

/** Distance increments from cumulative 2D odometry poses (x [m], y [m], phi [rad]) such as
 * CObservationOdometry::odometry: the arc length of each step, chord / sinc(dphi/2), signed
 * by the direction of travel along the body x axis. */
std::vector<OdometryIncrement> odometryFromPoses2D(const std::vector<double>& t_s, const std::vector<double>& x_m,
												   const std::vector<double>& y_m, const std::vector<double>& phi_rad);
/** The same for the poses [first, last) alone (no copies of the range: long drives);
 * throws std::invalid_argument unless first <= last <= size. */
std::vector<OdometryIncrement> odometryFromPoses2D(const std::vector<double>& t_s, const std::vector<double>& x_m,
												   const std::vector<double>& y_m, const std::vector<double>& phi_rad,
												   std::size_t first, std::size_t last);

/** The increment between two consecutive poses (t0, x0, y0, phi0) -> (t1, x1, y1, phi1), as
 * odometryFromPoses2D computes each one. */
OdometryIncrement odometryIncrement2D(double t1_s, double x0_m, double y0_m, double phi0_rad, double x1_m, double y1_m,
									  double phi1_rad);

/** One step of planar dead reckoning: from `last` (its yaw_rad is the heading at last.t_s)
 * by `inc` to the heading yaw1_rad at inc.t_s (what DeadReckoning2D::add does; also for a
 * caller that keeps only the last point: fog-drift's streaming evaluation). Throws
 * std::invalid_argument on a non-finite increment or a time that does not follow last.t_s. */
TrajectoryPoint deadReckonStep2D(const TrajectoryPoint& last, const OdometryIncrement& inc, double yaw1_rad);

/** Planar dead reckoning (z = 0): heading from the attitude track's yaw. */
class DeadReckoning2D
{
   public:
	/** Starts at (x, y) [m] at time t0_s; the heading comes from the attitude track. */
	DeadReckoning2D(double t0_s, double x0_m, double y0_m);

	/** Advances by one odometry increment using the attitude at the interval's ends. */
	void add(const OdometryIncrement& inc, const AttitudeTrack& attitude);

	const Trajectory& trajectory() const { return traj_; }
	/** Room for n points (no regrowth: long drives). */
	void reserve(std::size_t n) { traj_.reserve(n); }
	/** The trajectory, moved out (the object is spent). */
	Trajectory takeTrajectory() { return std::move(traj_); }

   private:
	Trajectory traj_;
};

/** 3D dead reckoning: displacement along q_nb * (1, 0, 0), attitude by slerp. */
class DeadReckoning3D
{
   public:
	DeadReckoning3D(double t0_s, const Eigen::Vector3d& p0_m);
	void add(const OdometryIncrement& inc, const AttitudeTrack& attitude);
	const Trajectory& trajectory() const { return traj_; }

   private:
	Trajectory traj_;
};

/** Convenience: runs DeadReckoning2D over all increments. The first trajectory point is at
 * t0_s with the attitude track's yaw at t0_s. */
Trajectory deadReckon2D(double t0_s, double x0_m, double y0_m, const std::vector<OdometryIncrement>& odometry,
						const AttitudeTrack& attitude);

/** Convenience: runs DeadReckoning3D over all increments. */
Trajectory deadReckon3D(double t0_s, const Eigen::Vector3d& p0_m, const std::vector<OdometryIncrement>& odometry,
						const AttitudeTrack& attitude);

}  // namespace mrpt_fog::nav
