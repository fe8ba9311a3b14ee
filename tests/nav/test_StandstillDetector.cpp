/* StandstillDetector and FieldBiasRefiner on motions with known truth (stops, turning in
 * place, a turntable, straight driving) and gyro samples with a known offset and noise. */
#include <gtest/gtest.h>
#include <mrpt_fog_nav/FieldBiasRefiner.h>
#include <mrpt_fog_nav/StandstillDetector.h>

#include <cmath>
#include <functional>
#include <random>
#include <vector>

using namespace mrpt_fog::nav;

namespace
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kDt = 0.1;  // 10 Hz gyro and odometry
constexpr double kEarthUp_dph = 9.668;

/** A planar motion by phases: speed [m/s] and yaw rate [deg/s] of the vehicle, and the
 * platform's own yaw rate under it [deg/s] (a turntable: the wheels do not see it). */
struct Phase
{
	double until_s, speed_mps, wheel_yaw_dps, platform_yaw_dps;
};

struct Motion
{
	std::vector<double> t, x, y, yaw_wheels, gyro_true_dph;
	std::vector<bool> truly_still;  //!< no rotation and no translation over the sample's interval
};

Motion makeMotion(const std::vector<Phase>& phases)
{
	Motion m;
	double x = 0, y = 0, yaw = 0;
	m.t.push_back(0), m.x.push_back(0), m.y.push_back(0), m.yaw_wheels.push_back(0), m.gyro_true_dph.push_back(0);
	m.truly_still.push_back(false);
	for (int k = 1; k * kDt <= phases.back().until_s + 1e-9; k++)
	{
		const double t = k * kDt;
		const Phase* p = &phases.back();
		for (const auto& ph : phases)
			if (t <= ph.until_s + 1e-9)
			{
				p = &ph;
				break;
			}
		yaw += p->wheel_yaw_dps * kDt * kPi / 180;
		x += p->speed_mps * kDt * std::cos(yaw), y += p->speed_mps * kDt * std::sin(yaw);
		m.t.push_back(t), m.x.push_back(x), m.y.push_back(y), m.yaw_wheels.push_back(yaw);
		m.gyro_true_dph.push_back((p->wheel_yaw_dps + p->platform_yaw_dps) * 3600.0);
		m.truly_still.push_back(p->speed_mps == 0 && p->wheel_yaw_dps == 0 && p->platform_yaw_dps == 0);
	}
	return m;
}

std::vector<bool> classify(const Motion& m, StandstillSource src, bool odometry_first)
{
	StandstillOptions o;
	o.source = src;
	StandstillDetector d(o, kEarthUp_dph);
	std::vector<bool> out;
	ClassifiedRate c;
	if (odometry_first)
		for (std::size_t k = 0; k < m.t.size(); k++) d.addOdometry(m.t[k], m.x[k], m.y[k], m.yaw_wheels[k]);
	for (std::size_t k = 0; k < m.t.size(); k++)
	{
		d.addRate(m.t[k], m.gyro_true_dph[k] + kEarthUp_dph);
		if (!odometry_first) d.addOdometry(m.t[k], m.x[k], m.y[k], m.yaw_wheels[k]);
		while (d.next(c)) out.push_back(c.still);
	}
	d.finish();
	while (d.next(c)) out.push_back(c.still);
	return out;
}

std::size_t countStill(const std::vector<bool>& v, std::size_t from, std::size_t to)
{
	std::size_t n = 0;
	for (std::size_t k = from; k < to; k++) n += v[k];
	return n;
}
}  // namespace

// Drive 10 s, stop 20 s, drive 10 s: every sample of the stop is still for each source, none of
// the driving samples is for the odometry (the gyro alone cannot tell straight driving from a stop).
TEST(StandstillDetector, StopBetweenDrivesIsFoundBySeveralSources)
{
	const Motion m = makeMotion({{10, 5, 0, 0}, {30, 0, 0, 0}, {40, 5, 0, 0}});
	for (auto src : {StandstillSource::Odometry, StandstillSource::OdometryAndGyro})
	{
		const auto s = classify(m, src, false);
		ASSERT_EQ(s.size(), m.t.size());
		for (std::size_t k = 1; k < m.t.size(); k++) EXPECT_EQ(s[k], m.truly_still[k]) << "t = " << m.t[k];
	}
	const auto g = classify(m, StandstillSource::Gyro, false);
	EXPECT_EQ(countStill(g, 101, 301), 200u);  // the stop
	EXPECT_EQ(countStill(g, 1, 100), 99u);  // straight driving: zero yaw rate, "still" to the gyro
}

// Turning in place at 10 deg/s: no wheel speed, but the wheels' yaw rate and the gyro see it.
TEST(StandstillDetector, TurningInPlaceIsNotStill)
{
	const Motion m = makeMotion({{10, 0, 0, 0}, {20, 0, 10, 0}, {30, 0, 0, 0}});
	for (auto src : {StandstillSource::Odometry, StandstillSource::Gyro, StandstillSource::OdometryAndGyro})
	{
		const auto s = classify(m, src, false);
		// the gyro's 1 s window lags the end of the turn by up to 1 s
		EXPECT_EQ(countStill(s, 101, 201), 0u) << static_cast<int>(src);
		EXPECT_GE(countStill(s, 211, 301), 90u) << static_cast<int>(src);
	}
}

// A turntable (or ferry) rotates the parked vehicle at 0.1 deg/s: the wheels are blind to it;
// the gyro sees it, so the default (both) is not fooled.
TEST(StandstillDetector, TurntableFoolsTheWheelsOnly)
{
	const Motion m = makeMotion({{10, 0, 0, 0}, {40, 0, 0, 0.1}});
	const auto odo = classify(m, StandstillSource::Odometry, false);
	const auto both = classify(m, StandstillSource::OdometryAndGyro, false);
	EXPECT_EQ(countStill(odo, 111, 401), 290u);  // wrong, as documented
	EXPECT_EQ(countStill(both, 111, 401), 0u);
}

// The decisions depend on the samples' times, not on how the log interleaves the streams.
TEST(StandstillDetector, SameAnswerWhateverTheInterleaving)
{
	const Motion m = makeMotion({{10, 5, 3, 0}, {25, 0, 0, 0}, {26, 0, 20, 0}, {50, 0, 0, 0}, {60, 3, 0, 0}});
	EXPECT_EQ(classify(m, StandstillSource::OdometryAndGyro, false), classify(m, StandstillSource::OdometryAndGyro, true));
}

namespace
{
struct RefineRun
{
	std::vector<RefinedRate> out;
	std::vector<double> in;
	std::vector<StandstillUpdate> updates;
	std::size_t short_standstills = 0;
	double offset = 0, sigma = 0;
	bool applied = false;
};

RefineRun refine(const Motion& m, double offset_dph, double arw, std::uint64_t seed, FieldRefinementOptions o)
{
	o.expected_rate_dph = kEarthUp_dph;
	o.noise.arw_deg_rt_h = arw;
	FieldBiasRefiner r(o, 0.0);
	std::mt19937_64 rng(seed);
	std::normal_distribution<double> w(0.0, 60.0 * arw / std::sqrt(kDt));
	RefineRun run;
	RefinedRate x;
	for (std::size_t k = 0; k < m.t.size(); k++)
	{
		const double g = m.gyro_true_dph[k] + kEarthUp_dph + offset_dph + w(rng);
		run.in.push_back(g);
		r.addRate(m.t[k], g);
		r.addOdometry(m.t[k], m.x[k], m.y[k], m.yaw_wheels[k]);
		while (r.next(x)) run.out.push_back(x);
	}
	r.finish();
	while (r.next(x)) run.out.push_back(x);
	run.updates = r.updates();
	run.short_standstills = r.shortStandstills();
	run.offset = r.filter().offset_dph();
	run.sigma = r.filter().offset_sigma_dph();
	run.applied = r.applied();
	return run;
}
}  // namespace

// No standstill: every sample passes unchanged (bit for bit), and nothing is reported.
TEST(FieldBiasRefiner, DriveWithoutStandstillIsUnchanged)
{
	const Motion m = makeMotion({{60, 5, 0, 0}, {90, 5, 2, 0}, {120, 5, 0, 0}});
	const RefineRun r = refine(m, 0.3, 0.001, 3, {});
	ASSERT_EQ(r.out.size(), r.in.size());
	for (std::size_t k = 0; k < r.in.size(); k++) EXPECT_EQ(r.out[k].rate_dph, r.in[k]);
	EXPECT_TRUE(r.updates.empty());
	EXPECT_EQ(r.offset, 0.0);
}

// A 120 s stop learns a +0.3 deg/h offset to within 4 posterior sigmas, the sigma agrees with the
// closed form for the samples used (B = 0 here), and only samples after the update are corrected.
TEST(FieldBiasRefiner, LongStopLearnsTheOffset)
{
	const Motion m = makeMotion({{121, 0, 0, 0}, {200, 5, 1, 0}});
	FieldRefinementOptions o;
	o.noise.bias_instability_dph = 0;
	o.noise.rrw_deg_h_rt_h = 0;
	o.prior_sigma_dph = 1.0;
	const RefineRun r = refine(m, 0.3, 0.002, 5, o);
	ASSERT_EQ(r.updates.size(), 1u);
	const StandstillUpdate& u = r.updates.front();
	// samples used: after the first guard (1 s), up to guard before the motion
	EXPECT_NEAR(u.first_used_s, 1.1, 1e-9);
	EXPECT_NEAR(u.last_used_s, 120.0, 1e-9);
	const double R = std::pow(60.0 * 0.002 / std::sqrt(kDt), 2);
	const double P = 1.0 / (1.0 + static_cast<double>(u.samples) / R);
	EXPECT_NEAR(u.sigma_after_dph, std::sqrt(P), 1e-9);
	EXPECT_NEAR(u.offset_after_dph, 0.3, 4 * std::sqrt(P));
	// nothing corrected before min_still_s (10 s) have passed
	for (const auto& x : r.out)
		if (x.t_s < 10.0) EXPECT_EQ(x.correction_dph, 0.0);
	EXPECT_NEAR(r.out.back().correction_dph, r.offset, 1e-12);
}

// A 6 s stop is shorter than min_still_s: it changes nothing. With a tight prior (an offset
// known better than a 20 s stop can measure), a 20 s stop changes nothing either.
TEST(FieldBiasRefiner, ShortStandstillChangesNothing)
{
	const Motion shortstop = makeMotion({{30, 5, 0, 0}, {36, 0, 0, 0}, {60, 5, 0, 0}});
	const RefineRun a = refine(shortstop, 0.3, 0.001, 7, {});
	EXPECT_TRUE(a.updates.empty());
	EXPECT_EQ(a.short_standstills, 1u);
	for (std::size_t k = 0; k < a.in.size(); k++) EXPECT_EQ(a.out[k].rate_dph, a.in[k]);

	const Motion stop20 = makeMotion({{30, 5, 0, 0}, {50, 0, 0, 0}, {80, 5, 0, 0}});
	FieldRefinementOptions tight;
	tight.prior_sigma_dph = 0.005;  // the bias instability alone (B = 0.005) cannot be beaten
	const RefineRun b = refine(stop20, 0.0, 0.001, 7, tight);
	EXPECT_TRUE(b.updates.empty());
	EXPECT_EQ(b.short_standstills, 1u);
}

// A calibration the standstills do not contradict is left alone. With no offset the estimate is
// noise; the 3-sigma test looks twice per standstill (4 looks here, 0.27 % each for a Gaussian):
// over 400 noise seeds at most 3 % of the runs may apply it (expected about 1 %), and where it
// is not applied the output is the input bit for bit although the filter ran. The plain filter
// (significance 0) always applies its noisy estimate.
TEST(FieldBiasRefiner, OffsetWithinItsUncertaintyIsNotApplied)
{
	const Motion m = makeMotion({{121, 0, 0, 0}, {200, 5, 1, 0}, {260, 0, 0, 0}, {300, 5, 0, 0}});
	std::size_t applied = 0;
	const std::size_t runs = 400;
	for (std::uint64_t seed = 1000; seed < 1000 + runs; seed++)
	{
		const RefineRun g = refine(m, 0.0, 0.001, seed, {});
		ASSERT_EQ(g.updates.size(), 2u);
		if (g.applied)
		{
			applied++;
			continue;
		}
		for (std::size_t k = 0; k < g.in.size(); k++) ASSERT_EQ(g.out[k].rate_dph, g.in[k]);
	}
	EXPECT_LE(applied, runs * 3 / 100);
	FieldRefinementOptions plain;
	plain.significance_sigma = 0;
	const RefineRun p = refine(m, 0.0, 0.001, 9, plain);
	EXPECT_TRUE(p.applied);
	EXPECT_NE(p.out.back().rate_dph, p.in.back());
	EXPECT_NEAR(p.out.back().correction_dph, p.offset, 1e-3);  // c + g, g decayed over 40 s
}
