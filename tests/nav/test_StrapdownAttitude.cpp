/* Tests of StrapdownAttitude in the style of basalt: a known smooth motion, exact rates
 * synthesised from its closed form, integration, comparison with the truth. */
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt_fog_nav/EarthModel.h>
#include <mrpt_fog_nav/Rotation.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>

#include <cmath>
#include <cstdio>

using namespace mrpt_fog::nav;

namespace
{
/** Angle [rad] of the rotation between two attitudes. */
double angleBetween(const Eigen::Quaterniond& a, const Eigen::Quaterniond& b)
{
	return quatToRotvec(a.conjugate() * b).norm();
}

Eigen::Matrix3d skew(const Eigen::Vector3d& v)
{
	Eigen::Matrix3d S;
	S << 0, -v.z(), v.y(), v.z(), 0, -v.x(), -v.y(), v.x(), 0;
	return S;
}

/** A smooth 3D motion given by its rotation vector phi(t) (q = exp(phi)); the body rate is
 * omega = J_r(phi) * dphi/dt with the closed-form right Jacobian of SO(3). */
struct SmoothMotion
{
	Eigen::Vector3d phi(double t) const
	{
		return {0.3 * std::sin(0.7 * t), 0.2 * std::sin(1.1 * t + 0.4), 0.5 * t + 0.4 * std::sin(0.3 * t)};
	}
	Eigen::Vector3d dphi(double t) const
	{
		return {0.3 * 0.7 * std::cos(0.7 * t), 0.2 * 1.1 * std::cos(1.1 * t + 0.4), 0.5 + 0.4 * 0.3 * std::cos(0.3 * t)};
	}
	Eigen::Quaterniond q(double t) const
	{
		const Eigen::Vector3d p = phi(t);
		return Eigen::Quaterniond(Eigen::AngleAxisd(p.norm(), p.normalized()));
	}
	Eigen::Vector3d omega(double t) const
	{
		const Eigen::Vector3d p = phi(t);
		const double th = p.norm();
		const Eigen::Matrix3d S = skew(p);
		const Eigen::Matrix3d Jr = Eigen::Matrix3d::Identity() - (1 - std::cos(th)) / (th * th) * S +
								   (th - std::sin(th)) / (th * th * th) * S * S;
		return Jr * dphi(t);
	}
};

/** Integrates SmoothMotion's exact rates over [1, 1 + duration] s at step dt; returns the
 * final attitude error [rad]. */
double smoothMotionError(double dt, double duration)
{
	SmoothMotion m;
	StrapdownOptions opt;
	opt.remove_earth_rate = false;
	opt.sampling = RateSampling::Instantaneous;  // exact rates at the sample instants
	StrapdownAttitude att(opt);
	const double t0 = 1.0;
	att.initialize(t0, m.q(t0));
	att.updateRate(t0, m.omega(t0));
	const int n = static_cast<int>(std::lround(duration / dt));
	for (int k = 1; k <= n; ++k) att.updateRate(t0 + k * dt, m.omega(t0 + k * dt));
	return angleBetween(att.attitude(), m.q(t0 + n * dt));
}
}  // namespace

// A generic smooth 3-axis motion (yaw turning 0.5 rad/s with wobbles in all axes), sampled at
// 100 Hz for 60 s. Trapezoidal increments plus the coning term are second-order accurate,
// so the error is O(dt^2): halving dt must divide it by about 4 (we require > 3), and at
// 100 Hz it must stay below 1e-4 rad after 60 s (measured about 3e-6 rad; the bound is the
// trapezoid truncation estimate T * dt^2 / 12 * max|omega''| ~ 60 * 1e-4 / 12 * 0.2 = 1e-4).
TEST(StrapdownAttitude, SmoothMotionExactRates_SecondOrder)
{
	const double e1 = smoothMotionError(0.01, 60.0);
	const double e2 = smoothMotionError(0.005, 60.0);
	std::printf("smooth motion: error %.3g rad at dt=0.01 s, %.3g rad at dt=0.005 s\n", e1, e2);
	EXPECT_LT(e1, 1e-4);
	EXPECT_GT(e1 / e2, 3.0) << "e(dt)=" << e1 << " e(dt/2)=" << e2;
}

// Interval-average samples are exact increments for a pure yaw motion: the result must match
// to rounding (1e-9 rad after 10000 steps).
TEST(StrapdownAttitude, PureYawIntervalAverageIsExact)
{
	auto yaw = [](double t) { return 0.8 * std::sin(0.5 * t) + 0.05 * t; };
	StrapdownOptions opt;
	opt.remove_earth_rate = false;
	opt.sampling = RateSampling::IntervalAverage;
	StrapdownAttitude att(opt, StrapdownAttitude::Mode::VerticalOnly);
	const double dt = 0.1;
	att.initialize(0.0, quatFromYawPitchRoll(yaw(0), 0, 0));
	for (int k = 1; k <= 10000; ++k)
		att.updateRateZ(k * dt, (yaw(k * dt) - yaw((k - 1) * dt)) / dt);
	EXPECT_NEAR(wrapToPi(att.yaw() - yaw(10000 * dt)), 0.0, 1e-9);
}

namespace
{
/** Classical coning motion: q(t) = [cos(a/2), sin(a/2) cos(W t), sin(a/2) sin(W t), 0];
 * body rate (closed form) omega = (-W sin a sin Wt, W sin a cos Wt, -2 W sin^2(a/2)).
 * Exact increments over (t0, t1] are the integrals of omega. Returns the attitude error [rad]
 * after `cycles` cone periods with n_per_cycle updates per period. */
double coningError(bool coning_correction, int n_per_cycle, int cycles)
{
	const double a = mrpt::DEG2RAD(1.0), W = 2 * M_PI * 2.0;  // 1 deg half-angle, 2 Hz
	auto q = [&](double t) {
		return Eigen::Quaterniond(std::cos(a / 2), std::sin(a / 2) * std::cos(W * t), std::sin(a / 2) * std::sin(W * t), 0);
	};
	auto increment = [&](double t0, double t1) {
		return Eigen::Vector3d(std::sin(a) * (std::cos(W * t1) - std::cos(W * t0)),
							   std::sin(a) * (std::sin(W * t1) - std::sin(W * t0)),
							   -2 * W * std::pow(std::sin(a / 2), 2) * (t1 - t0));
	};
	StrapdownOptions opt;
	opt.remove_earth_rate = false;
	opt.coning_correction = coning_correction;
	StrapdownAttitude att(opt);
	const double T = (2 * M_PI / W) / n_per_cycle;
	att.initialize(0.0, q(0.0));
	const int n = n_per_cycle * cycles;
	for (int k = 1; k <= n; ++k) att.updateIncrement(k * T, increment((k - 1) * T, k * T));
	return angleBetween(att.attitude(), q(n * T));
}
}  // namespace

// Coning: the uncorrected algorithm accumulates a drift about z, the classical coning error
// of rate W a^2 / 2 * (1 - sin(W T) / (W T)) for a small half-angle a (~ W a^2 (W T)^2 / 12).
// With a 1 deg cone at 2 Hz, 50 updates per cycle and 200 cycles (100 s) that is 5.04e-4 rad;
// the measured uncorrected error must match it within 3 % (the small-angle approximation).
// The two-sample correction cancels it to the next order: the corrected error must be at
// least 100x smaller and fall faster than second order (> 6x) when T is halved.
TEST(StrapdownAttitude, ConingClosedForm)
{
	const double a = mrpt::DEG2RAD(1.0), W = 2 * M_PI * 2.0, T = (2 * M_PI / W) / 50, duration = 100.0;
	const double expected_raw = duration * W * a * a / 2 * (1 - std::sin(W * T) / (W * T));
	const double raw = coningError(false, 50, 200);
	const double corr = coningError(true, 50, 200);
	const double corr_half = coningError(true, 100, 200);
	std::printf("coning: closed form %.4g rad, uncorrected %.4g rad, corrected %.4g rad (T/2: %.4g rad)\n",
				expected_raw, raw, corr, corr_half);
	EXPECT_NEAR(raw, expected_raw, 0.03 * expected_raw);
	EXPECT_LT(corr, raw / 100) << "raw=" << raw << " corrected=" << corr;
	EXPECT_GT(corr / corr_half, 6.0) << "corrected(T)=" << corr << " corrected(T/2)=" << corr_half;
}

// A stationary gyro triad at latitude 40 deg, yawed 30 deg from East, senses the Earth rate
// omega_b = C_bn * Omega (0, cos lat, sin lat). With Earth-rate removal the attitude must not
// move (1 h at 10 Hz, < 1e-9 rad); without it the yaw drifts by Omega sin(lat) * 1 h =
// 9.668 deg (closed form, to 1e-6 deg), and the horizontal component tilts the triad.
TEST(StrapdownAttitude, StationaryEarthRateRemoved_ThreeAxis)
{
	const double lat = mrpt::DEG2RAD(40.0);
	const Eigen::Quaterniond q0 = quatFromYawPitchRoll(mrpt::DEG2RAD(30.0), 0, 0);
	const Eigen::Vector3d omega_b = q0.conjugate() * earthRateEnu(lat);
	StrapdownOptions opt;
	opt.latitude_rad = lat;
	opt.sampling = RateSampling::Instantaneous;
	StrapdownAttitude att(opt);
	att.initialize(0.0, q0);
	for (int k = 0; k <= 36000; ++k) att.updateRate(k * 0.1, omega_b);
	EXPECT_LT(angleBetween(att.attitude(), q0), 1e-9);
}

TEST(StrapdownAttitude, StationaryVerticalGyroEarthRate)
{
	const double lat = mrpt::DEG2RAD(40.0);
	const double omega_up = earth::kRotationRate_rad_s * std::sin(lat);
	for (const bool remove : {true, false})
	{
		StrapdownOptions opt;
		opt.latitude_rad = lat;
		opt.remove_earth_rate = remove;
		opt.sampling = RateSampling::Instantaneous;
		StrapdownAttitude att(opt, StrapdownAttitude::Mode::VerticalOnly);
		att.initialize(0.0, quatFromYawPitchRoll(0.5, 0, 0));
		for (int k = 0; k <= 36000; ++k) att.updateRateZ(k * 0.1, omega_up);
		const double drift_deg = mrpt::RAD2DEG(wrapToPi(att.yaw() - 0.5));
		if (remove)
			EXPECT_NEAR(drift_deg, 0.0, 1e-9);
		else
			EXPECT_NEAR(drift_deg, 15.041067 * std::sin(lat), 1e-6);  // 9.668 deg in 1 h
	}
}

// A vehicle holding heading East along a parallel at 45 deg latitude at 20 m/s: its vertical
// gyro senses Omega sin(lat) + vE tan(lat) / RN (transport rate, 0.65 deg/h here). With both
// removed the heading stays at 0 (< 1e-9 rad after 1 h); without the transport term it drifts
// by exactly vE tan(lat)/RN * 1 h.
TEST(StrapdownAttitude, TransportRateAlongParallel)
{
	const double lat = mrpt::DEG2RAD(45.0), vE = 20.0;
	const Eigen::Vector3d vel(vE, 0, 0);
	const double rn = earthRadii(lat).prime_vertical_m;
	const double omega_up = earth::kRotationRate_rad_s * std::sin(lat) + vE * std::tan(lat) / rn;
	for (const bool transport : {true, false})
	{
		StrapdownOptions opt;
		opt.latitude_rad = lat;
		opt.use_transport_rate = transport;
		opt.sampling = RateSampling::Instantaneous;
		StrapdownAttitude att(opt, StrapdownAttitude::Mode::VerticalOnly);
		att.initialize(0.0, Eigen::Quaterniond::Identity());
		for (int k = 0; k <= 36000; ++k) att.updateRateZ(k * 0.1, omega_up, vel);
		const double expected = transport ? 0.0 : vE * std::tan(lat) / rn * 3600.0;
		EXPECT_NEAR(att.yaw(), expected, 1e-9);
	}
}

TEST(StrapdownAttitude, BadInputThrows)
{
	StrapdownOptions inst;
	inst.sampling = RateSampling::Instantaneous;
	StrapdownAttitude att(inst);
	EXPECT_THROW(att.updateRateZ(1.0, 0.0), std::invalid_argument);  // before initialize
	att.initialize(1.0, Eigen::Quaterniond::Identity());
	EXPECT_THROW(att.updateRateZ(0.5, 0.0), std::invalid_argument);  // time goes back
	EXPECT_THROW(att.updateRateZ(2.0, std::nan("")), std::invalid_argument);
	StrapdownOptions bad;
	bad.latitude_rad = 2.0;
	EXPECT_THROW(StrapdownAttitude{bad}, std::invalid_argument);
}

// No silent default for the rate sampling: updateRate() without a choice throws and says what
// to choose; updateIncrement() does not need it.
TEST(StrapdownAttitude, UnspecifiedSamplingThrows)
{
	StrapdownOptions opt;
	opt.remove_earth_rate = false;
	StrapdownAttitude att(opt);
	att.initialize(0.0, Eigen::Quaterniond::Identity());
	try
	{
		att.updateRateZ(0.1, 0.2);
		FAIL() << "updateRate with RateSampling::Unspecified must throw";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("IntervalAverage"), std::string::npos) << e.what();
	}
	att.updateIncrement(0.1, Eigen::Vector3d(0, 0, 0.02));
	EXPECT_NEAR(att.yaw(), 0.02, 1e-15);
	EXPECT_EQ(rateSamplingFromString("average"), RateSampling::IntervalAverage);
	EXPECT_EQ(rateSamplingFromString("instantaneous"), RateSampling::Instantaneous);
	EXPECT_THROW(rateSamplingFromString("mean"), std::invalid_argument);
	EXPECT_STREQ(rateSamplingName(RateSampling::IntervalAverage), "average");
}

// Interval-average stream whose first sample carries the initialisation time (as fog-sim's
// t = 0 sample does): it is accepted and contributes nothing (it averages the interval before
// the start), so the yaw is the exact sum of the later samples' increments. The first sample
// is given a large rate so that integrating it over any interval would show. A second sample at
// the same time is still an error.
TEST(StrapdownAttitude, IntervalAverageFirstSampleAtInitialisationTime)
{
	StrapdownOptions opt;
	opt.remove_earth_rate = false;
	opt.sampling = RateSampling::IntervalAverage;
	StrapdownAttitude att(opt, StrapdownAttitude::Mode::VerticalOnly);
	att.initialize(5.0, Eigen::Quaterniond::Identity());
	att.updateRateZ(5.0, 100.0);
	EXPECT_EQ(att.yaw(), 0.0);
	att.updateRateZ(5.1, 0.3);
	att.updateRateZ(5.3, -0.1);
	EXPECT_NEAR(att.yaw(), 0.3 * 0.1 - 0.1 * 0.2, 1e-15);
	EXPECT_THROW(att.updateRateZ(5.3, 0.0), std::invalid_argument);
	// After initialize() again the rule applies again.
	att.initialize(6.0, Eigen::Quaterniond::Identity());
	EXPECT_NO_THROW(att.updateRateZ(6.0, 1.0));
	EXPECT_EQ(att.yaw(), 0.0);
}
