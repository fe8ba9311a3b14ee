/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/TruthComparison.h>
#include <mrpt_fog_nav/Rotation.h>

#include <algorithm>
#include <cmath>

namespace mrpt_fog::heading
{
TruthComparison::TruthComparison(bool align_at_first_estimate, double max_duration_s)
	: align_(align_at_first_estimate), max_duration_s_(max_duration_s)
{
}

void TruthComparison::addTruth(double t, double x, double y, double yaw)
{
	if (!truth_.empty() && !(t > truth_.back().t)) return;
	truth_.push_back({t, x, y, yaw});
	pump(false);
}

void TruthComparison::addEstimate(double t, double x, double y, double yaw)
{
	if (!est_.empty() && !(t > est_.back().t)) return;
	est_.push_back({t, x, y, yaw});
	pump(false);
}

void TruthComparison::pump(bool done)
{
	while (!est_.empty())
	{
		const Pose e = est_.front();
		if (truth_.empty())
		{
			if (!done) return;
			out_.not_compared++;
			est_.pop_front();
			continue;
		}
		if (e.t < truth_.front().t || (done && e.t > truth_.back().t))
		{
			out_.not_compared++;
			est_.pop_front();
			continue;
		}
		if (e.t > truth_.back().t) return;  // wait for the truth after it
		std::size_t i1 = 0;
		while (i1 < truth_.size() && truth_[i1].t < e.t) i1++;
		Pose tr = truth_[i1];
		if (truth_[i1].t > e.t)
		{
			const Pose& a = truth_[i1 - 1];
			const Pose& b = truth_[i1];
			const double f = (e.t - a.t) / (b.t - a.t);
			tr = {e.t, a.x + f * (b.x - a.x), a.y + f * (b.y - a.y), a.yaw + f * nav::wrapToPi(b.yaw - a.yaw)};
		}
		compare(e, tr);
		est_.pop_front();
		while (truth_.size() > 1 && truth_[1].t <= e.t) truth_.pop_front();
	}
}

void TruthComparison::compare(const Pose& e, const Pose& tr)
{
	if (!aligned_)
	{
		aligned_ = true;
		out_.t_first_s = e.t;
		if (align_)
		{
			dyaw_ = nav::wrapToPi(tr.yaw - e.yaw);
			c_ = std::cos(dyaw_), s_ = std::sin(dyaw_);
			tx_ = tr.x - (c_ * e.x - s_ * e.y);
			ty_ = tr.y - (s_ * e.x + c_ * e.y);
		}
	}
	if (e.t - out_.t_first_s > max_duration_s_)
	{
		out_.not_compared++;
		return;
	}
	const double x = c_ * e.x - s_ * e.y + tx_, y = s_ * e.x + c_ * e.y + ty_;
	const double dh = nav::wrapToPi(e.yaw + dyaw_ - tr.yaw) * units::kRadToDeg;
	const double dp = std::hypot(x - tr.x, y - tr.y);
	sum_h2_ += dh * dh, sum_p2_ += dp * dp;
	max_h_ = std::max(max_h_, std::abs(dh)), max_p_ = std::max(max_p_, dp);
	out_.compared++;
	out_.t_last_s = e.t;
	out_.heading_final_deg = dh;
	out_.position_final_m = dp;
}

TrackErrors TruthComparison::finish()
{
	pump(true);
	if (out_.compared > 0)
	{
		const double n = static_cast<double>(out_.compared);
		out_.heading_rms_deg = std::sqrt(sum_h2_ / n);
		out_.position_rms_m = std::sqrt(sum_p2_ / n);
		out_.heading_max_deg = max_h_;
		out_.position_max_m = max_p_;
	}
	return out_;
}

}  // namespace mrpt_fog::heading
