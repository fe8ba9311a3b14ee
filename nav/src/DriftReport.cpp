/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>
#include <mrpt_fog_nav/DriftReport.h>
#include <mrpt_fog_nav/Rotation.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::nav
{
const DriftSeries& DriftReport::variant(const std::string& name) const
{
	for (const auto& v : variants)
		if (v.name == name) return v;
	throw std::out_of_range("DriftReport: no variant named '" + name + "'");
}

DriftReport computeDriftReport(const Trajectory& truth, const std::vector<NamedTrajectory>& variants)
{
	if (truth.size() < 2) throw std::invalid_argument("computeDriftReport: the truth needs at least 2 poses");
	DriftReport rep;
	rep.distance_m = pathLength_m(truth);
	rep.duration_s = truth.back().t_s - truth.front().t_s;
	for (const auto& [name, traj] : variants)
	{
		if (traj.empty()) throw std::invalid_argument("computeDriftReport: variant '" + name + "' is empty");
		DriftSeries s;
		s.name = name;
		for (auto* v : {&s.t_s, &s.heading_error_deg, &s.position_error_m}) v->reserve(truth.size());  // no regrowth
		for (const auto& gt : truth)
		{
			if (gt.t_s < traj.front().t_s || gt.t_s > traj.back().t_s) continue;
			const TrajectoryPoint p = interpolate(traj, gt.t_s);
			const double dpsi_deg = mrpt::RAD2DEG(wrapToPi(p.yaw_rad - gt.yaw_rad));
			const double dpos =
				std::sqrt(std::pow(p.x_m - gt.x_m, 2) + std::pow(p.y_m - gt.y_m, 2) + std::pow(p.z_m - gt.z_m, 2));
			s.t_s.push_back(gt.t_s);
			s.heading_error_deg.push_back(dpsi_deg);
			s.position_error_m.push_back(dpos);
			s.heading_error_max_deg = std::max(s.heading_error_max_deg, std::abs(dpsi_deg));
			s.position_error_max_m = std::max(s.position_error_max_m, dpos);
		}
		if (s.t_s.empty())
			throw std::invalid_argument("computeDriftReport: variant '" + name + "' does not overlap the truth in time");
		s.heading_error_final_signed_deg = s.heading_error_deg.back();
		s.heading_error_final_deg = std::abs(s.heading_error_deg.back());
		s.position_error_final_m = s.position_error_m.back();
		if (rep.distance_m > 0)
		{
			s.position_error_final_pct = 100.0 * s.position_error_final_m / rep.distance_m;
			s.position_error_max_pct = 100.0 * s.position_error_max_m / rep.distance_m;
		}
		rep.variants.push_back(std::move(s));
	}
	return rep;
}

}  // namespace mrpt_fog::nav
