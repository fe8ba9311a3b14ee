/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt/core/format.h>
#include <mrpt_fog_nav/Rotation.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::nav
{
namespace
{
/** Index i with t[i] <= t_s <= t[i+1] and the fraction along it. */
std::pair<std::size_t, double> bracket(const std::vector<double>& t, double t_s, const char* what)
{
	if (t.empty()) throw std::out_of_range(mrpt::format("%s: empty", what));
	if (!(t_s >= t.front() && t_s <= t.back()))
		throw std::out_of_range(
			mrpt::format("%s: time %.6f s outside [%.6f, %.6f] s", what, t_s, t.front(), t.back()));
	if (t.size() == 1) return {0, 0.0};
	auto it = std::upper_bound(t.begin(), t.end(), t_s);
	std::size_t i1 = (it == t.end()) ? t.size() - 1 : static_cast<std::size_t>(it - t.begin());
	std::size_t i0 = i1 - 1;
	const double f = (t_s - t[i0]) / (t[i1] - t[i0]);
	return {i0, f};
}
}  // namespace

double pathLength_m(const Trajectory& traj)
{
	double len = 0.0;
	for (std::size_t k = 1; k < traj.size(); ++k)
		len += std::sqrt(std::pow(traj[k].x_m - traj[k - 1].x_m, 2) + std::pow(traj[k].y_m - traj[k - 1].y_m, 2) +
						 std::pow(traj[k].z_m - traj[k - 1].z_m, 2));
	return len;
}

TrajectoryPoint interpolate(const Trajectory& traj, double t_s)
{
	if (traj.empty()) throw std::out_of_range("interpolate(trajectory): empty");
	if (!(t_s >= traj.front().t_s && t_s <= traj.back().t_s))
		throw std::out_of_range(mrpt::format("interpolate(trajectory): time %.6f s outside [%.6f, %.6f] s", t_s,
											 traj.front().t_s, traj.back().t_s));
	if (traj.size() == 1) return traj.front();
	auto it = std::upper_bound(traj.begin(), traj.end(), t_s,
							   [](double t, const TrajectoryPoint& p) { return t < p.t_s; });
	const std::size_t i1 = (it == traj.end()) ? traj.size() - 1 : static_cast<std::size_t>(it - traj.begin());
	const std::size_t i0 = i1 - 1;
	const double f = (t_s - traj[i0].t_s) / (traj[i1].t_s - traj[i0].t_s);
	const TrajectoryPoint& a = traj[i0];
	const TrajectoryPoint& b = traj[i0 + 1];
	TrajectoryPoint p;
	p.t_s = t_s;
	p.x_m = a.x_m + f * (b.x_m - a.x_m);
	p.y_m = a.y_m + f * (b.y_m - a.y_m);
	p.z_m = a.z_m + f * (b.z_m - a.z_m);
	p.yaw_rad = wrapToPi(a.yaw_rad + f * wrapToPi(b.yaw_rad - a.yaw_rad));
	p.q_nb = a.q_nb.slerp(f, b.q_nb);
	return p;
}

void AttitudeTrack::push_back(double t_s, const Eigen::Quaterniond& q_nb)
{
	if (!t_s_.empty() && !(t_s > t_s_.back()))
		throw std::invalid_argument(mrpt::format("AttitudeTrack: time %.6f s does not increase", t_s));
	t_s_.push_back(t_s);
	q_.push_back(q_nb);
}

Eigen::Quaterniond AttitudeTrack::at(double t_s) const
{
	const auto [i0, f] = bracket(t_s_, t_s, "AttitudeTrack::at");
	if (t_s_.size() == 1) return q_.front();
	return q_[i0].slerp(f, q_[i0 + 1]);
}

double AttitudeTrack::yawAt(double t_s) const { return yawOf(at(t_s)); }

}  // namespace mrpt_fog::nav
