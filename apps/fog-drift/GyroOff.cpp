/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "GyroOff.h"

#include <algorithm>
#include <cmath>

namespace mrpt_fog::drift
{
TruthYawAt::TruthYawAt(std::vector<double> q) : q_(std::move(q)), values_(q_.size(), std::numeric_limits<double>::quiet_NaN())
{
}

void TruthYawAt::add(double t_s, double yaw_rad)
{
	// nav/HeadingFigures.cpp's unwrapping: the front yaw plus the wrapped differences
	if (n_ == 0) front_yaw_rad_ = yaw_rad;
	else acc_rad_ += std::remainder(yaw_rad - prev_yaw_rad_, 2 * M_PI);
	prev_yaw_rad_ = yaw_rad;
	const double y = (front_yaw_rad_ + acc_rad_) * streaming_detail::kRadToDeg;
	while (next_ < q_.size() && q_[next_] <= t_s)
	{
		const double x = q_[next_];
		if (x == t_s) values_[next_] = y;
		else if (n_ > 0 && x > prev_t_) values_[next_] = prev_y_deg_ + (x - prev_t_) / (t_s - prev_t_) * (y - prev_y_deg_);
		// else: before the truth (NaN)
		next_++;
	}
	prev_t_ = t_s, prev_y_deg_ = y;
	n_++;
}

void TruthYawAt::finish() { next_ = q_.size(); }  // the queries after the truth stay NaN

std::vector<double> stretchQueryTimes(const std::vector<GyroOffStretch>& off)
{
	std::vector<double> q;
	for (const auto& s : off) q.push_back(s.off_s), q.push_back(s.on_s);
	return q;  // sorted: the stretches are disjoint and in time order
}

void setTruthHeadingChanges(std::vector<GyroOffStretch>& off, const TruthYawAt& yaw)
{
	for (std::size_t i = 0; i < off.size(); i++)
		off[i].truth_heading_change_deg = yaw.value(2 * i + 1) - yaw.value(2 * i);  // NaN when either is
}

void cutSegmentsAtGyroOff(nav::DriveSegments& seg, std::vector<TurnSpan>* turns, const std::vector<GyroOffStretch>& off,
						  const nav::HeadingFigureOptions& o)
{
	if (off.empty()) return;
	std::vector<nav::DriveSegments::Span> straights;
	for (const auto& s : seg.straights)
	{
		double a = s.t0_s;
		for (const auto& g : off)
		{
			if (g.on_s <= a || g.off_s >= s.t1_s) continue;  // the open interval (off, on) misses [a, t1]
			if (g.off_s - a >= o.min_straight_s) straights.push_back({a, g.off_s});
			a = std::max(a, g.on_s);
		}
		if (s.t1_s - a >= o.min_straight_s) straights.push_back({a, s.t1_s});
	}
	seg.straights = std::move(straights);
	const auto overlaps = [&](double t0, double t1) {
		for (const auto& g : off)
			if (t0 < g.on_s && t1 > g.off_s) return true;
		return false;
	};
	std::vector<nav::DriveSegments::Span> kept;
	std::vector<TurnSpan> kept_spans;
	for (std::size_t i = 0; i < seg.turns.size(); i++)
	{
		if (overlaps(seg.turns[i].t0_s, seg.turns[i].t1_s)) continue;
		kept.push_back(seg.turns[i]);
		if (turns) kept_spans.push_back((*turns)[i]);
	}
	seg.turns = std::move(kept);
	if (turns) *turns = std::move(kept_spans);
}

}  // namespace mrpt_fog::drift
