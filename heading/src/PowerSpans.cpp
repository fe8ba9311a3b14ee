/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt_fog/obs/GyroPower.h>
#include <mrpt_fog_heading/PowerSpans.h>

#include <algorithm>
#include <cmath>

namespace mrpt_fog::heading
{
void PowerSpanBuilder::add(double t_s, double power)
{
	// A log gives every sample a power value or none (the readers refuse a mix), so a powered
	// sample right after an off one has power 1: isTurnOn.
	const bool gyro_on = !isGyroOff(power);
	if (!any_)
	{
		any_ = true;
		if (gyro_on) powered_.push_back({t_s, t_s, 1});
		else
		{
			GyroOffStretch s;
			s.off_s = s.on_s = t_s;
			s.from_start = true;
			s.samples = 1;
			off_.push_back(s);
		}
	}
	else if (gyro_on)
	{
		if (on_) powered_.back().t1_s = t_s, powered_.back().samples++;
		else
		{
			off_.back().on_s = t_s;  // the turn-on
			powered_.push_back({t_s, t_s, 1});
		}
	}
	else
	{
		if (on_)
		{
			GyroOffStretch s;
			s.off_s = last_t_;  // the last powered sample
			s.on_s = t_s;
			off_.push_back(s);
		}
		off_.back().samples++;
		off_.back().on_s = t_s;
	}
	on_ = gyro_on;
	last_t_ = t_s;
}

void PowerSpanBuilder::finish()
{
	if (finished_) return;
	finished_ = true;
	if (any_ && !on_) off_.back().to_end = true, off_.back().on_s = last_t_;
}

std::optional<std::pair<double, double>> navigationWindow(const PoweredSpan& span, double gyro_first_s,
														  double gyro_last_s, double odo_first_s, double odo_last_s,
														  double truth_first_s, double truth_last_s)
{
	const double t0 = std::max({span.t0_s, gyro_first_s, odo_first_s, truth_first_s});
	const double t1 = std::min({span.t1_s, gyro_last_s, odo_last_s, truth_last_s});
	if (!(t1 > t0)) return std::nullopt;
	return std::make_pair(t0, t1);
}

}  // namespace mrpt_fog::heading
