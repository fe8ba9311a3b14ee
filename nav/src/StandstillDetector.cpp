/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt_fog_nav/StandstillDetector.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::nav
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kRadPerSecToDegPerHour = 180.0 / kPi * 3600.0;
}  // namespace

StandstillDetector::StandstillDetector(const StandstillOptions& options, double expected_rate_dph)
	: opt_(options), expected_dph_(expected_rate_dph)
{
	if (!(options.gyro_window_s > 0)) throw std::invalid_argument("standstill: the gyro window must be > 0 s");
	if (!(options.speed_mps >= 0) || !(options.wheel_yaw_rate_dph >= 0) || !(options.gyro_rate_dph >= 0))
		throw std::invalid_argument("standstill: thresholds must be >= 0");
	if (!std::isfinite(expected_rate_dph)) throw std::invalid_argument("standstill: the expected rate must be finite");
}

void StandstillDetector::addOdometry(double t_s, double x_m, double y_m, double yaw_rad)
{
	if (opt_.source == StandstillSource::Gyro) return;
	if (!std::isfinite(t_s) || (have_pose_ && !(t_s > last_t_))) return;
	if (have_pose_)
	{
		const double dt = t_s - last_t_;
		const double speed = std::hypot(x_m - last_x_, y_m - last_y_) / dt;
		const double yaw_rate_dph =
			std::abs(std::remainder(yaw_rad - last_yaw_, 2 * kPi)) / dt * kRadPerSecToDegPerHour;
		// NaN poses compare false: not still
		odo_.push_back({last_t_, t_s, speed < opt_.speed_mps && yaw_rate_dph < opt_.wheel_yaw_rate_dph});
	}
	have_pose_ = true;
	last_t_ = t_s, last_x_ = x_m, last_y_ = y_m, last_yaw_ = yaw_rad;
	while (!waiting_.empty())
	{
		bool still = false;
		if (!odometryDecides(waiting_.front().t_s, still)) break;
		ClassifiedRate c = waiting_.front();
		waiting_.pop_front();
		c.still = c.still && still;
		ready_.push_back(c);
	}
}

bool StandstillDetector::odometryDecides(double t_s, bool& still)
{
	// drop intervals that end before t (gyro samples come in time order)
	while (!odo_.empty() && odo_.front().t1_s < t_s) odo_.pop_front();
	if (odo_.empty())
	{
		if (finished_ || (have_pose_ && t_s <= last_t_))  // before the first interval, or no more odometry
		{
			still = false;
			return true;
		}
		return false;
	}
	still = odo_.front().t0_s < t_s && odo_.front().still;  // t <= t0 of the first interval: before the odometry
	return true;
}

void StandstillDetector::addRate(double t_s, double rate_dph, bool turn_on)
{
	if (!std::isfinite(t_s) || !(t_s > last_rate_t_)) return;
	ClassifiedRate c;
	c.turn_on = turn_on;
	c.t_s = t_s;
	c.rate_dph = rate_dph;
	c.dt_s = std::isfinite(last_rate_t_) ? t_s - last_rate_t_ : std::numeric_limits<double>::quiet_NaN();
	last_rate_t_ = t_s;
	// the gyro test over (t - window, t]
	bool gyro_still = std::isfinite(rate_dph);
	if (opt_.source != StandstillSource::Odometry)
	{
		const double d = std::isfinite(rate_dph) ? rate_dph - expected_dph_ : 0.0;
		window_.emplace_back(t_s, d);
		window_sum_ += d;
		while (!window_.empty() && window_.front().first <= t_s - opt_.gyro_window_s)
		{
			window_sum_ -= window_.front().second;
			window_.pop_front();
		}
		if (window_.size() == 1) window_sum_ = window_.front().second;  // no round-off build-up
		gyro_still = gyro_still && std::abs(window_sum_ / static_cast<double>(window_.size())) < opt_.gyro_rate_dph;
	}
	c.still = gyro_still;
	if (opt_.source == StandstillSource::Gyro)
	{
		ready_.push_back(c);
		return;
	}
	waiting_.push_back(c);
	while (!waiting_.empty())
	{
		bool still = false;
		if (!odometryDecides(waiting_.front().t_s, still)) break;
		ClassifiedRate w = waiting_.front();
		waiting_.pop_front();
		w.still = w.still && still;
		ready_.push_back(w);
	}
}

void StandstillDetector::finish()
{
	finished_ = true;
	while (!waiting_.empty())
	{
		bool still = false;
		odometryDecides(waiting_.front().t_s, still);
		ClassifiedRate w = waiting_.front();
		waiting_.pop_front();
		w.still = w.still && still;
		ready_.push_back(w);
	}
}

bool StandstillDetector::next(ClassifiedRate& out)
{
	if (ready_.empty()) return false;
	out = ready_.front();
	ready_.pop_front();
	return true;
}

}  // namespace mrpt_fog::nav
