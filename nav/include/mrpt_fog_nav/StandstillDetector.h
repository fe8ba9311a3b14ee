/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file StandstillDetector.h
 * Which gyro samples were taken while the vehicle did not rotate, from the wheel odometry, the
 * gyro's own signal, or both. Samples come out in time order, each once what decides it is
 * known (the odometry interval that covers it), so the answer depends on the samples' times
 * only, not on the order in which a log interleaves the two streams.
 *
 * How robust each source is:
 *  - Odometry: still when the wheel speed and the wheel yaw rate (both from consecutive
 *    odometry poses over the interval that covers the gyro sample) are below their thresholds.
 *    A vehicle turning in place has no speed but a wheel yaw rate, so it is not still; an
 *    odometry that reports speed only would miss it. The wheels do not see a vehicle rotated
 *    on a turntable, a ferry or a lift, nor a towed one.
 *  - Gyro: still when the mean of (rate - expected rate) over the last window is below a
 *    threshold. It sees any rotation above the threshold, turning in place included, but it
 *    cannot tell "not rotating" from "driving straight", and a slow rotation under the
 *    threshold (a ship, a swaying mast) passes for bias: what it admits is biased by up to the
 *    threshold. Use it alone only where the platform is known to be rigidly parked.
 *  - Both (the default): the wheels say stopped and the gyro sees no rotation.
 * Samples without a decision (before the first odometry interval, after the last one) are not
 * still. */

#include <cstddef>
#include <deque>
#include <limits>

namespace mrpt_fog::nav
{
enum class StandstillSource : unsigned char
{
	Odometry,  //!< wheel speed and wheel yaw rate
	Gyro,  //!< the gyro's own rate
	OdometryAndGyro  //!< both must agree
};

struct StandstillOptions
{
	StandstillSource source = StandstillSource::OdometryAndGyro;
	double speed_mps = 0.01;  //!< wheel speed below this [m/s]
	double wheel_yaw_rate_dph = 36.0;  //!< wheel yaw rate below this [deg/h] (0.01 deg/s)
	double gyro_rate_dph = 10.0;  //!< |window mean of rate - expected| below this [deg/h]
	double gyro_window_s = 1.0;  //!< the gyro test's window [s]
};

/** A gyro sample with its decision. */
struct ClassifiedRate
{
	double t_s = 0;
	double rate_dph = 0;
	double dt_s = std::numeric_limits<double>::quiet_NaN();  //!< since the previous sample (NaN: first)
	bool still = false;
	bool turn_on = false;  //!< the gyro was (re)powered at this sample (passed through)
};

class StandstillDetector
{
   public:
	/** expected_rate_dph: what the gyro reads when not rotating (the Earth rate's component on
	 * its axis, plus any known bias). Throws std::invalid_argument on a non-positive window or
	 * negative threshold. */
	StandstillDetector(const StandstillOptions& options, double expected_rate_dph);

	/** An odometry pose (cumulative, as CObservationOdometry holds it) at t_s [s]. Times must
	 * increase; a repeated or earlier time is ignored. */
	void addOdometry(double t_s, double x_m, double y_m, double yaw_rad);
	/** A gyro sample: the mean rate over the interval ending at t_s [deg/h]. Times must
	 * increase; a repeated or earlier time is ignored. A non-finite rate is passed on as not
	 * still. turn_on marks the first sample after a power-on (passed through to the output). */
	void addRate(double t_s, double rate_dph, bool turn_on = false);
	/** No more input: every sample waiting for odometry is decided (not still). */
	void finish();
	/** The next decided sample, in time order; false when none is ready. */
	bool next(ClassifiedRate& out);

	const StandstillOptions& options() const { return opt_; }

   private:
	struct OdoInterval
	{
		double t0_s, t1_s;
		bool still;
	};
	bool odometryDecides(double t_s, bool& still);

	StandstillOptions opt_;
	double expected_dph_;
	bool finished_ = false;
	// odometry
	bool have_pose_ = false;
	double last_t_ = 0, last_x_ = 0, last_y_ = 0, last_yaw_ = 0;
	std::deque<OdoInterval> odo_;
	// gyro
	double last_rate_t_ = -std::numeric_limits<double>::infinity();
	std::deque<ClassifiedRate> waiting_;  //!< gyro test done, odometry decision pending
	std::deque<std::pair<double, double>> window_;  //!< (t, rate - expected) of the gyro window
	double window_sum_ = 0;
	std::deque<ClassifiedRate> ready_;
};

}  // namespace mrpt_fog::nav
