/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/DriveTrajectory.h>
#include <mrpt_fog/sim/SimRandom.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::sim
{
DriveTrajectory::DriveTrajectory(const std::vector<DriveSegment>& segments, double initial_speed_mps)
	: segs_(segments), v0_(initial_speed_mps)
{
	if (segs_.empty()) throw std::invalid_argument("DriveTrajectory: no segments");
	if (!(v0_ >= 0)) throw std::invalid_argument("DriveTrajectory: negative initial speed");
	PlanarState s;
	s.speed_mps = v0_;
	double t = 0, v = v0_;
	for (std::size_t i = 0; i < segs_.size(); i++)
	{
		const auto& g = segs_[i];
		if (!(g.duration_s > 0) || !(g.speed_end_mps >= 0) || !std::isfinite(g.yaw_rate_dps))
			throw std::invalid_argument("DriveTrajectory: segment " + std::to_string(i) +
										" needs duration > 0, speed >= 0, finite yaw rate");
		start_s_.push_back(t);
		start_state_.push_back(s);
		s = propagate(s, g, g.duration_s, v);
		v = g.speed_end_mps;
		t += g.duration_s;
	}
	duration_s_ = t;
}

PlanarState DriveTrajectory::propagate(const PlanarState& s0, const DriveSegment& seg, double tau, double v_start) const
{
	const double a = (seg.speed_end_mps - v_start) / seg.duration_s;
	const double w = seg.yaw_rate_dps * units::kDegToRad;
	PlanarState s;
	s.yaw_rad = s0.yaw_rad + w * tau;
	s.speed_mps = v_start + a * tau;
	s.yaw_rate_rad_s = w;
	s.distance_m = s0.distance_m + v_start * tau + 0.5 * a * tau * tau;
	if (std::abs(w) < 1e-12)
	{
		const double d = v_start * tau + 0.5 * a * tau * tau;
		s.x_m = s0.x_m + d * std::cos(s0.yaw_rad);
		s.y_m = s0.y_m + d * std::sin(s0.yaw_rad);
	}
	else
	{
		// int_0^tau (v0 + a s) [cos, sin](psi0 + w s) ds in closed form.
		const double p0 = s0.yaw_rad, p1 = s.yaw_rad, v1 = s.speed_mps;
		s.x_m = s0.x_m + (v1 * std::sin(p1) - v_start * std::sin(p0)) / w + a * (std::cos(p1) - std::cos(p0)) / (w * w);
		s.y_m = s0.y_m - (v1 * std::cos(p1) - v_start * std::cos(p0)) / w + a * (std::sin(p1) - std::sin(p0)) / (w * w);
	}
	return s;
}

PlanarState DriveTrajectory::at(double t_s) const
{
	const double t = std::clamp(t_s, 0.0, duration_s_);
	auto it = std::upper_bound(start_s_.begin(), start_s_.end(), t);
	const std::size_t i = static_cast<std::size_t>(std::max<std::ptrdiff_t>(0, (it - start_s_.begin()) - 1));
	const double v_start = i == 0 ? v0_ : segs_[i - 1].speed_end_mps;
	return propagate(start_state_[i], segs_[i], t - start_s_[i], v_start);
}

DriveTrajectory DriveTrajectory::randomDrive(std::uint64_t seed, double duration_s)
{
	if (!(duration_s > 130)) throw std::invalid_argument("randomDrive: duration must exceed 130 s");
	SimRandom rng(seed, RandomStream::Trajectory);
	auto uni = [&](double lo, double hi) { return lo + (hi - lo) * rng.uniform(); };
	constexpr double kAccel = 1.5, kBrake = 2.0, kMaxLateral = 2.5;
	std::vector<DriveSegment> segs;
	double t = 0, v = 0;
	auto add = [&](double dur, double v_end, double yaw_dps) {
		if (t >= duration_s) return;
		if (t + dur > duration_s)
		{
			// Truncate: speed at the cut follows the same linear law.
			const double f = (duration_s - t) / dur;
			v_end = v + f * (v_end - v);
			dur = duration_s - t;
		}
		if (dur <= 1e-9) return;
		segs.push_back({dur, v_end, yaw_dps});
		t += dur;
		v = v_end;
	};
	auto changeSpeed = [&](double v_target) {
		const double dv = v_target - v;
		if (std::abs(dv) < 1e-9) return;
		add(std::abs(dv) / (dv > 0 ? kAccel : kBrake), v_target, 0.0);
	};
	add(120.0, 0.0, 0.0);  // initial stop (alignment)
	while (t < duration_s)
	{
		const double r = rng.uniform();
		if (r < 0.45)
		{
			changeSpeed(uni(8.0, 20.0));
			add(uni(20.0, 120.0), v, 0.0);
		}
		else if (r < 0.85)
		{
			changeSpeed(uni(5.0, 9.0));
			const double max_rate_dps = std::min(20.0, kMaxLateral / std::max(v, 1e-3) * units::kRadToDeg);
			const double rate = uni(0.5, 1.0) * max_rate_dps * (rng.uniform() < 0.5 ? -1.0 : 1.0);
			const double angle = uni(45.0, 180.0);
			add(angle / std::abs(rate), v, rate);
		}
		else
		{
			changeSpeed(0.0);
			add(uni(10.0, 60.0), 0.0, 0.0);
		}
	}
	return DriveTrajectory(segs, 0.0);
}

}  // namespace mrpt_fog::sim
