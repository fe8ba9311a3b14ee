/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file Trajectory.h
 * Timestamped poses (dead-reckoned or truth) and timestamped attitudes, with interpolation.
 * Positions in metres in the local ENU frame, yaw in rad (CCW from East, MRPT's phi), times
 * in s. */

#include <Eigen/Geometry>

#include <vector>

namespace mrpt_fog::nav
{
struct TrajectoryPoint
{
	double t_s = 0.0;
	double x_m = 0.0, y_m = 0.0, z_m = 0.0;
	double yaw_rad = 0.0;  //!< in (-pi, pi]
	Eigen::Quaterniond q_nb = Eigen::Quaterniond::Identity();  //!< full attitude (3D)
};

using Trajectory = std::vector<TrajectoryPoint>;

/** Sum of the straight segments between consecutive points [m]. */
double pathLength_m(const Trajectory& traj);

/** Pose at time t_s: position linear, yaw along the shortest arc, attitude by slerp between
 * the two neighbouring points. Throws std::out_of_range when t_s is outside the trajectory's
 * time span (no extrapolation) or the trajectory is empty. Times must be increasing. */
TrajectoryPoint interpolate(const Trajectory& traj, double t_s);

/** Attitude history (e.g. the output of StrapdownAttitude), queried by time. */
class AttitudeTrack
{
   public:
	/** Appends; throws std::invalid_argument if t_s does not increase. */
	void push_back(double t_s, const Eigen::Quaterniond& q_nb);
	/** Slerp between neighbours; throws std::out_of_range outside [front, back]. */
	Eigen::Quaterniond at(double t_s) const;
	/** Yaw [rad] at t_s. */
	double yawAt(double t_s) const;
	std::size_t size() const { return t_s_.size(); }
	/** Room for n attitudes (no regrowth: long drives). */
	void reserve(std::size_t n)
	{
		t_s_.reserve(n);
		q_.reserve(n);
	}
	bool empty() const { return t_s_.empty(); }
	double frontTime() const { return t_s_.front(); }
	double backTime() const { return t_s_.back(); }
	const std::vector<double>& times() const { return t_s_; }
	const std::vector<Eigen::Quaterniond>& attitudes() const { return q_; }

   private:
	std::vector<double> t_s_;
	std::vector<Eigen::Quaterniond> q_;
};

}  // namespace mrpt_fog::nav
