/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "GyroOffOdometry.h"

#include <mrpt/math/wrap2pi.h>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace mrpt_fog::localize
{
mrpt::poses::CPose2D wheelPoseAt(const heading::OdometryPoses& w, double t)
{
	if (w.t_s.empty()) throw std::invalid_argument("no wheel odometry");
	if (t <= w.t_s.front()) return {w.x_m.front(), w.y_m.front(), w.phi_rad.front()};
	if (t >= w.t_s.back()) return {w.x_m.back(), w.y_m.back(), w.phi_rad.back()};
	const auto i = static_cast<std::size_t>(std::upper_bound(w.t_s.begin(), w.t_s.end(), t) - w.t_s.begin());
	const double a = (t - w.t_s[i - 1]) / (w.t_s[i] - w.t_s[i - 1]);
	const double dphi = mrpt::math::wrapToPi(w.phi_rad[i] - w.phi_rad[i - 1]);
	return {w.x_m[i - 1] + a * (w.x_m[i] - w.x_m[i - 1]), w.y_m[i - 1] + a * (w.y_m[i] - w.y_m[i - 1]),
			mrpt::math::wrapToPi(w.phi_rad[i - 1] + a * dphi)};
}

ScanOdometry odometryAtScans(const std::vector<nav::Trajectory>& spans, const heading::OdometryPoses& wheel,
							 const std::vector<double>& t, const mrpt::poses::CPose2D& start)
{
	if (t.size() < 2) throw std::invalid_argument("odometryAtScans: fewer than 2 scans");
	if (wheel.t_s.empty()) throw std::invalid_argument("odometryAtScans: no wheel odometry");
	// the span whose trajectory covers each scan (none: -1)
	const auto spanOf = [&](double tk) -> long {
		for (std::size_t j = 0; j < spans.size(); j++)
			if (!spans[j].empty() && spans[j].front().t_s <= tk && tk <= spans[j].back().t_s) return static_cast<long>(j);
		return -1;
	};
	const auto poseIn = [&](long j, double tk) {
		const nav::TrajectoryPoint p = nav::interpolate(spans[static_cast<std::size_t>(j)], tk);
		return mrpt::poses::CPose2D(p.x_m, p.y_m, p.yaw_rad);
	};
	ScanOdometry out;
	out.poses.reserve(t.size());
	out.step.assign(t.size(), StepSource::Gyro);
	// per span: the rigid move onto the chain (none: the span's poses as dead-reckoned)
	std::vector<std::optional<mrpt::poses::CPose2D>> moved(spans.size());
	std::vector<bool> anchored(spans.size(), false);
	long prev = spanOf(t[0]);
	if (prev >= 0)
	{
		anchored[static_cast<std::size_t>(prev)] = true;
		out.poses.push_back(poseIn(prev, t[0]));
	}
	else
		out.poses.push_back(start);
	for (std::size_t k = 1; k < t.size(); k++)
	{
		const long cur = spanOf(t[k]);
		if (cur >= 0 && cur == prev)
		{
			const auto& m = moved[static_cast<std::size_t>(cur)];
			out.poses.push_back(m ? *m + poseIn(cur, t[k]) : poseIn(cur, t[k]));
		}
		else
		{
			out.step[k] = StepSource::WheelOnly;
			out.wheel_only_steps++;
			const mrpt::poses::CPose2D incr = wheelPoseAt(wheel, t[k]) - wheelPoseAt(wheel, t[k - 1]);
			out.poses.push_back(out.poses.back() + incr);
			if (cur >= 0 && !anchored[static_cast<std::size_t>(cur)])
			{
				// the span's poses from here on: moved so that its pose at this scan is the chain's
				anchored[static_cast<std::size_t>(cur)] = true;
				moved[static_cast<std::size_t>(cur)] = out.poses.back() + (-poseIn(cur, t[k]));  // M (+) P = chain
			}
		}
		prev = cur;
	}
	return out;
}

}  // namespace mrpt_fog::localize
