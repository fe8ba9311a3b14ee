/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt/core/format.h>
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/Rotation.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::nav
{
namespace
{
/** sin(x)/x, with its series near 0. */
double sinc(double x)
{
	if (std::abs(x) < 1e-4) return 1.0 - x * x / 6.0;
	return std::sin(x) / x;
}

void checkIncrement(const OdometryIncrement& inc, double t_prev_s)
{
	if (!std::isfinite(inc.t_s) || !std::isfinite(inc.distance_m))
		throw std::invalid_argument(mrpt::format("dead reckoning: non-finite odometry at t=%.6f s", inc.t_s));
	if (!(inc.t_s > t_prev_s))
		throw std::invalid_argument(
			mrpt::format("dead reckoning: odometry time %.6f s does not follow %.6f s", inc.t_s, t_prev_s));
}

void checkTimes(const std::vector<double>& t_s, std::size_t n, const char* what)
{
	if (t_s.size() != n) throw std::invalid_argument(mrpt::format("%s: column sizes differ", what));
	for (std::size_t k = 0; k < t_s.size(); ++k)
		if (!std::isfinite(t_s[k]) || (k > 0 && !(t_s[k] > t_s[k - 1])))
			throw std::invalid_argument(mrpt::format("%s: time not increasing at sample %zu", what, k));
}
}  // namespace

std::vector<OdometryIncrement> odometryFromSpeed(const std::vector<double>& t_s, const std::vector<double>& speed_mps)
{
	checkTimes(t_s, speed_mps.size(), "odometryFromSpeed");
	std::vector<OdometryIncrement> out;
	for (std::size_t k = 1; k < t_s.size(); ++k)
		out.push_back({t_s[k], 0.5 * (speed_mps[k - 1] + speed_mps[k]) * (t_s[k] - t_s[k - 1])});
	return out;
}

std::vector<OdometryIncrement> odometryFromPoses2D(const std::vector<double>& t_s, const std::vector<double>& x_m,
												   const std::vector<double>& y_m, const std::vector<double>& phi_rad)
{
	return odometryFromPoses2D(t_s, x_m, y_m, phi_rad, 0, t_s.size());
}

std::vector<OdometryIncrement> odometryFromPoses2D(const std::vector<double>& t_s, const std::vector<double>& x_m,
												   const std::vector<double>& y_m, const std::vector<double>& phi_rad,
												   std::size_t first, std::size_t last)
{
	checkTimes(t_s, x_m.size(), "odometryFromPoses2D");
	checkTimes(t_s, y_m.size(), "odometryFromPoses2D");
	checkTimes(t_s, phi_rad.size(), "odometryFromPoses2D");
	if (!(first <= last && last <= t_s.size())) throw std::invalid_argument("odometryFromPoses2D: range outside the poses");
	std::vector<OdometryIncrement> out;
	out.reserve(last > first ? last - first - 1 : 0);
	for (std::size_t k = first + 1; k < last; ++k)
		out.push_back(odometryIncrement2D(t_s[k], x_m[k - 1], y_m[k - 1], phi_rad[k - 1], x_m[k], y_m[k], phi_rad[k]));
	return out;
}

OdometryIncrement odometryIncrement2D(double t1_s, double x0_m, double y0_m, double phi0_rad, double x1_m, double y1_m,
									  double phi1_rad)
{
	const double dx = x1_m - x0_m, dy = y1_m - y0_m;
	const double dphi = wrapToPi(phi1_rad - phi0_rad);
	const double chord = std::hypot(dx, dy);
	// Direction of travel relative to the body x axis at mid-interval.
	const double mid = phi0_rad + 0.5 * dphi;
	const double along = dx * std::cos(mid) + dy * std::sin(mid);
	const double arc = chord / sinc(0.5 * dphi);
	return {t1_s, along < 0 ? -arc : arc};
}

DeadReckoning2D::DeadReckoning2D(double t0_s, double x0_m, double y0_m)
{
	TrajectoryPoint p;
	p.t_s = t0_s;
	p.x_m = x0_m;
	p.y_m = y0_m;
	traj_.push_back(p);
}

TrajectoryPoint deadReckonStep2D(const TrajectoryPoint& last, const OdometryIncrement& inc, double yaw1_rad)
{
	checkIncrement(inc, last.t_s);
	const double yaw0 = last.yaw_rad;
	const double dpsi = wrapToPi(yaw1_rad - yaw0);
	const double mid = yaw0 + 0.5 * dpsi;
	const double chord = inc.distance_m * sinc(0.5 * dpsi);
	TrajectoryPoint p;
	p.t_s = inc.t_s;
	p.x_m = last.x_m + chord * std::cos(mid);
	p.y_m = last.y_m + chord * std::sin(mid);
	p.yaw_rad = yaw1_rad;
	p.q_nb = quatFromYawPitchRoll(yaw1_rad, 0, 0);
	return p;
}

void DeadReckoning2D::add(const OdometryIncrement& inc, const AttitudeTrack& attitude)
{
	TrajectoryPoint& last = traj_.back();
	checkIncrement(inc, last.t_s);
	if (traj_.size() == 1)
	{
		last.q_nb = quatFromYawPitchRoll(attitude.yawAt(last.t_s), 0, 0);
		last.yaw_rad = attitude.yawAt(last.t_s);
	}
	traj_.push_back(deadReckonStep2D(last, inc, attitude.yawAt(inc.t_s)));
}

DeadReckoning3D::DeadReckoning3D(double t0_s, const Eigen::Vector3d& p0_m)
{
	TrajectoryPoint p;
	p.t_s = t0_s;
	p.x_m = p0_m.x();
	p.y_m = p0_m.y();
	p.z_m = p0_m.z();
	traj_.push_back(p);
}

void DeadReckoning3D::add(const OdometryIncrement& inc, const AttitudeTrack& attitude)
{
	TrajectoryPoint& last = traj_.back();
	checkIncrement(inc, last.t_s);
	if (traj_.size() == 1)
	{
		last.q_nb = attitude.at(last.t_s);
		last.yaw_rad = yawOf(last.q_nb);
	}
	const Eigen::Quaterniond q0 = last.q_nb;
	const Eigen::Quaterniond q1 = attitude.at(inc.t_s);
	const Eigen::Quaterniond q_mid = q0.slerp(0.5, q1);
	const double angle = quatToRotvec(q0.conjugate() * q1).norm();
	const Eigen::Vector3d d = inc.distance_m * sinc(0.5 * angle) * (q_mid * Eigen::Vector3d::UnitX());
	TrajectoryPoint p;
	p.t_s = inc.t_s;
	p.x_m = last.x_m + d.x();
	p.y_m = last.y_m + d.y();
	p.z_m = last.z_m + d.z();
	p.q_nb = q1;
	p.yaw_rad = yawOf(q1);
	traj_.push_back(p);
}

Trajectory deadReckon2D(double t0_s, double x0_m, double y0_m, const std::vector<OdometryIncrement>& odometry,
						const AttitudeTrack& attitude)
{
	DeadReckoning2D dr(t0_s, x0_m, y0_m);
	dr.reserve(odometry.size() + 1);
	for (const auto& inc : odometry) dr.add(inc, attitude);
	if (odometry.empty())
	{
		Trajectory t = dr.takeTrajectory();
		t.front().yaw_rad = attitude.yawAt(t0_s);
		t.front().q_nb = quatFromYawPitchRoll(t.front().yaw_rad, 0, 0);
		return t;
	}
	return dr.takeTrajectory();
}

Trajectory deadReckon3D(double t0_s, const Eigen::Vector3d& p0_m, const std::vector<OdometryIncrement>& odometry,
						const AttitudeTrack& attitude)
{
	DeadReckoning3D dr(t0_s, p0_m);
	for (const auto& inc : odometry) dr.add(inc, attitude);
	if (odometry.empty())
	{
		Trajectory t = dr.trajectory();
		t.front().q_nb = attitude.at(t0_s);
		t.front().yaw_rad = yawOf(t.front().q_nb);
		return t;
	}
	return dr.trajectory();
}

}  // namespace mrpt_fog::nav
