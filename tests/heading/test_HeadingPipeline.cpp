/* Tests of the heading pipeline against closed forms (a circle driven at constant yaw rate and
 * speed), the Earth-rate rule's numbers, the gyro-off rule and the rate-correction stage. */
#include <gtest/gtest.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/CalibrationEarthRate.h>
#include <mrpt_fog_heading/HeadingPipeline.h>
#include <mrpt_fog_heading/TruthComparison.h>
#include <mrpt_fog_nav/Rotation.h>

#include <cmath>
#include <vector>

using namespace mrpt_fog;
using namespace mrpt_fog::heading;

namespace
{
constexpr double kLat = 45.0;

FogSeries header(bool power = false)
{
	FogSeries h;
	h.sensor_label = "FOG";
	h.epoch_s = 1000.0;
	h.has_axis = {false, false, true};
	if (power) h.power.assign(1, NAN);
	return h;
}

/** A circle: yaw rate w [rad/s], speed v [m/s], FOG at 10 Hz (interval averages, the Earth rate
 * included as a still FOG senses it), odometry at 2 Hz (exact wheel poses). */
struct Circle
{
	double w = 0.05, v = 5.0, yaw0 = 0.3;
	double yaw(double t) const { return yaw0 + w * t; }
	double x(double t) const { return v / w * (std::sin(yaw(t)) - std::sin(yaw0)); }
	double y(double t) const { return -v / w * (std::cos(yaw(t)) - std::cos(yaw0)); }
};

double earthUp_dph() { return units::kEarthRate_dph * std::sin(kLat * units::kDegToRad); }

PipelineOptions options()
{
	PipelineOptions o;
	o.latitude_deg = kLat;
	return o;
}

/** Feeds the circle for duration_s; power(t) gives the power column (NaN: none). */
template <class Power, class Sink>
void drive(HeadingPipeline& p, const Circle& c, double duration_s, double gyro_bias_dph, Power power, Sink sink)
{
	const double epoch = 1000.0;
	for (int k = 0; k <= duration_s * 10; k++)
	{
		const double t = k * 0.1;
		if (k % 5 == 0) p.addOdometry(epoch + t, c.x(t), c.y(t), mrpt_fog::nav::wrapToPi(c.yaw(t)));
		FogSample s;
		s.time_s = t;
		const double pw = power(t);
		s.power = pw;
		s.rate_dph[2] = pw == 0.0 ? NAN : c.w * units::kRadPerSecToDegPerHour + earthUp_dph() + gyro_bias_dph;
		p.addFog(s);
		DeadReckonedPose q;
		while (p.popPose(q)) sink(q);
	}
	p.finish();
	DeadReckonedPose q;
	while (p.popPose(q)) sink(q);
}
}  // namespace

TEST(HeadingPipeline, CircleClosedForm)
{
	const Circle c;
	HeadingPipeline p(header(), options());
	std::size_t n = 0;
	double last_t = -1;
	drive(p, c, 60.0, 0.0, [](double) { return NAN; }, [&](const DeadReckonedPose& q) {
		const double t = q.t_s - 1000.0;
		EXPECT_GT(q.t_s, last_t);
		last_t = q.t_s;
		EXPECT_NEAR(mrpt_fog::nav::wrapToPi(q.heading_rad - c.yaw(t)), 0.0, 1e-9) << t;
		EXPECT_NEAR(q.x_m, c.x(t), 1e-6) << t;  // sinc chords are exact on a circle
		EXPECT_NEAR(q.y_m, c.y(t), 1e-6) << t;
		EXPECT_EQ(q.source, HeadingSource::Gyro);
		n++;
	});
	EXPECT_EQ(n, 121u);  // every odometry sample gives a pose
	EXPECT_EQ(p.counters().wheel_poses, 0u);
	// the yaw rate against the local level: the Earth rate removed
	EXPECT_NEAR(p.lastStep().yaw_rate_rad_s, c.w, 1e-12);
}

TEST(HeadingPipeline, GyroOffStretchUsesTheWheels)
{
	Circle c;
	HeadingPipeline p(header(true), options());
	// off from 20 s to 30 s; the wheels are exact here, so the heading stays on the circle
	std::size_t wheel = 0, n = 0;
	drive(p, c, 60.0, 0.0, [](double t) { return (t >= 20.0 && t < 30.0) ? 0.0 : 1.0; },
		  [&](const DeadReckonedPose& q) {
			  const double t = q.t_s - 1000.0;
			  if (q.source == HeadingSource::Wheels)
			  {
				  wheel++;
				  EXPECT_TRUE(t > 19.9 && t < 30.1) << t;  // 30.0 comes just before the turn-on sample
			  }
			  // after the turn-on the gyro goes on from the last wheel pose: at most one odometry
			  // interval (0.5 s) of rotation is unseen
			  EXPECT_NEAR(mrpt_fog::nav::wrapToPi(q.heading_rad - c.yaw(t)), 0.0, t < 30.0 ? 1e-9 : c.w * 0.5 + 1e-9) << t;
			  n++;
		  });
	EXPECT_EQ(n, 121u);
	EXPECT_EQ(wheel, 21u);  // 20.0, 20.5, ..., 30.0
	EXPECT_EQ(p.counters().turn_ons, 1u);
	EXPECT_EQ(p.counters().gyro_off_samples, 100u);
}

namespace
{
/** Removes a known constant offset: what an in-field bias estimator would converge to. */
struct KnownOffset : RateCorrection
{
	double offset_dph;
	std::size_t calls = 0, odometry = 0;
	explicit KnownOffset(double o) : offset_dph(o) {}
	double correct(const RateCorrectionInput& in) override
	{
		calls++;
		EXPECT_NEAR(in.still_reading_dph, earthUp_dph(), 1e-12);  // no calibration: nothing added back
		return in.compensated_dph - offset_dph;
	}
	void noteOdometry(const WheelOdometry&) override { odometry++; }
};
}  // namespace

TEST(HeadingPipeline, RateCorrectionStageIsCalledPerSample)
{
	const Circle c;
	const double bias = 36.0;  // deg/h: 0.6 deg over 60 s if not removed
	double err_uncorrected = 0, err_corrected = 0;
	{
		HeadingPipeline p(header(), options());
		drive(p, c, 60.0, bias, [](double) { return NAN; },
			  [&](const DeadReckonedPose& q) { err_uncorrected = mrpt_fog::nav::wrapToPi(q.heading_rad - c.yaw(q.t_s - 1000.0)); });
	}
	HeadingPipeline p(header(), options());
	auto corr = std::make_shared<KnownOffset>(bias);
	p.setRateCorrection(corr);
	drive(p, c, 60.0, bias, [](double) { return NAN; },
		  [&](const DeadReckonedPose& q) { err_corrected = mrpt_fog::nav::wrapToPi(q.heading_rad - c.yaw(q.t_s - 1000.0)); });
	EXPECT_NEAR(err_uncorrected * units::kRadToDeg, bias * 60.0 / 3600.0, 1e-9);
	EXPECT_NEAR(err_corrected, 0.0, 1e-9);
	EXPECT_EQ(corr->calls, 601u);
	EXPECT_EQ(corr->odometry, 121u);
}

TEST(HeadingPipeline, RealignFromAnExternalHeading)
{
	// The gyro is off from 20 s to 30 s; at the turn-on (30.0 s) the caller re-aligns from the
	// circle's own heading and position (as fog-drift does from its truth): from there the poses
	// are on the circle again to the closed form's precision (the turn-on rule alone leaves up to
	// one odometry interval of rotation unseen: GyroOffStretchUsesTheWheels).
	const Circle c;
	PipelineOptions o = options();
	o.alignment = Alignment::ByCaller;
	HeadingPipeline p(header(true), o);
	const double epoch = 1000.0;
	p.align(epoch, c.yaw(0), c.x(0), c.y(0));
	std::size_t after = 0;
	const auto check = [&](const DeadReckonedPose& q) {
		const double t = q.t_s - epoch;
		if (t < 30.0 - 1e-9) return;
		after++;
		EXPECT_EQ(q.source, HeadingSource::Gyro) << t;
		EXPECT_NEAR(mrpt_fog::nav::wrapToPi(q.heading_rad - c.yaw(t)), 0.0, 1e-9) << t;
		EXPECT_NEAR(q.x_m, c.x(t), 1e-6) << t;
		EXPECT_NEAR(q.y_m, c.y(t), 1e-6) << t;
	};
	for (int k = 0; k <= 600; k++)
	{
		const double t = k * 0.1;
		const bool off = k >= 200 && k < 300;
		if (k == 300) p.realign(epoch + t, c.yaw(t), c.x(t), c.y(t));
		if (k % 5 == 0) p.addOdometry(epoch + t, c.x(t), c.y(t), mrpt_fog::nav::wrapToPi(c.yaw(t)));
		FogSample s;
		s.time_s = t;
		s.power = off ? 0.0 : 1.0;
		s.rate_dph[2] = off ? NAN : c.w * units::kRadPerSecToDegPerHour + earthUp_dph();
		const RateStep& r = p.addFog(s);
		if (!off) EXPECT_NEAR(mrpt_fog::nav::wrapToPi(mrpt_fog::nav::yawOf(p.attitude()) - r.heading_rad), 0.0, 1e-12);
		DeadReckonedPose q;
		while (p.popPose(q)) check(q);
	}
	p.finish();
	DeadReckonedPose q;
	while (p.popPose(q)) check(q);
	EXPECT_EQ(after, 61u);  // 30.0, 30.5, ..., 60.0
	EXPECT_THROW(p.realign(epoch + 10.0, 0.0, 0.0, 0.0), std::runtime_error);  // before the last FOG sample
}

TEST(HeadingPipeline, BadInputThrows)
{
	HeadingPipeline p(header(), options());
	FogSample s;
	s.time_s = 1.0;
	s.rate_dph[2] = 1.0;
	p.addFog(s);
	EXPECT_THROW(p.addFog(s), std::runtime_error);  // repeated time
	s.time_s = 2.0;
	s.rate_dph[2] = NAN;
	EXPECT_THROW(p.addFog(s), std::runtime_error);  // NaN while powered
	PipelineOptions o;  // no latitude
	EXPECT_THROW(HeadingPipeline(header(), o), std::invalid_argument);
}

TEST(HeadingPipeline, OdometryFarBehindTheGyroThrows)
{
	HeadingPipeline p(header(), options());
	p.addOdometry(1000.0, 0, 0, 0);
	FogSample s;
	for (int k = 1; k <= 200; k++)
	{
		s.time_s = k * 0.1;
		s.rate_dph[2] = earthUp_dph();
		p.addFog(s);
	}
	// 15 s behind the FOG, beyond the default 10 s: the attitudes at its time are gone
	EXPECT_THROW(p.addOdometry(1005.0, 1, 0, 0), std::runtime_error);
	p.addOdometry(1000.0, 2, 0, 0);  // not after the previous odometry: skipped
	EXPECT_EQ(p.counters().odometry_skipped, 1u);
}

TEST(CalibrationEarthRate, TheRule)
{
	Calibration cal;
	cal.latitude_deg = 30.0;
	cal.earth_rate = EarthRateHandling::InBias;
	CalibrationEarthRate r = calibrationEarthRate(cal, 45.0);
	EXPECT_EQ(r.source, LatitudeSource::Calibration);
	EXPECT_NEAR(r.add_back_dph, 15.041067 * 0.5, 1e-5);  // Omega = 7.292115e-5 rad/s = 15.041067 deg/h
	cal.latitude_deg = NAN;
	r = calibrationEarthRate(cal, 45.0);
	EXPECT_EQ(r.source, LatitudeSource::Drive);
	EXPECT_NEAR(r.add_back_dph, 15.041067 * std::sqrt(0.5), 1e-5);
	CalibrationEarthRateOptions o;
	o.calibration_latitude_deg = -90.0;
	EXPECT_NEAR(calibrationEarthRate(cal, 45.0, o).add_back_dph, -15.041067, 1e-5);
	o.bias_without_earth_rate = true;
	EXPECT_EQ(calibrationEarthRate(cal, 45.0, o).add_back_dph, 0.0);
	cal.earth_rate = EarthRateHandling::InTableRate;
	EXPECT_EQ(calibrationEarthRate(cal, 45.0).add_back_dph, 0.0);
	o = {};
	o.calibration_latitude_deg = 91.0;
	EXPECT_THROW(calibrationEarthRate(cal, 45.0, o), std::invalid_argument);
}

TEST(TruthComparison, RigidFrameAndKnownErrors)
{
	TruthComparison cmp(true);
	// truth along x; the estimate in a frame rotated by 90 deg and shifted, with a heading error
	// growing 0.01 deg per second
	for (int k = 0; k <= 100; k++)
	{
		const double t = k;
		cmp.addTruth(t, t, 0.0, 0.0);
		const double e = 0.01 * t * units::kDegToRad;
		if (k % 2 == 0) cmp.addEstimate(t + 0.5, 10.0, 5.0 + (t + 0.5), M_PI / 2 + e);
	}
	const TrackErrors r = cmp.finish();
	EXPECT_EQ(r.compared, 50u);
	EXPECT_EQ(r.not_compared, 1u);  // t = 100.5 is after the truth
	EXPECT_NEAR(r.heading_final_deg, 0.01 * 98, 1e-9);
	EXPECT_NEAR(r.position_max_m, 0.0, 1e-9);
}
