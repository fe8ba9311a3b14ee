/* DriftReport on synthetic variants with known errors. */
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt_fog_nav/DriftReport.h>

#include <cmath>

using namespace mrpt_fog::nav;

namespace
{
/** Straight drive East at 10 m/s for 100 s, poses at 1 Hz. */
Trajectory straightTruth()
{
	Trajectory t;
	for (int k = 0; k <= 100; ++k)
	{
		TrajectoryPoint p;
		p.t_s = 1000.0 + k;
		p.x_m = 10.0 * k;
		t.push_back(p);
	}
	return t;
}
}  // namespace

// Variant "a": heading error growing at 0.01 deg/s (final +1 deg, max 1 deg), position offset
// constant 3-4-5 m (final = max = 5 m = 0.5 % of 1000 m). Variant "b": heading -2 deg at
// t = 50 s only, zero elsewhere; offset 2 m at the end only.
TEST(DriftReport, KnownErrors)
{
	const Trajectory truth = straightTruth();
	Trajectory a = truth, b = truth;
	for (auto& p : a)
	{
		p.yaw_rad = mrpt::DEG2RAD(0.01 * (p.t_s - 1000.0));
		p.x_m += 3.0;
		p.y_m += 4.0;
	}
	b[50].yaw_rad = mrpt::DEG2RAD(-2.0);
	b.back().y_m += 2.0;
	const DriftReport rep = computeDriftReport(truth, {{"a", a}, {"b", b}});
	EXPECT_NEAR(rep.distance_m, 1000.0, 1e-9);
	EXPECT_NEAR(rep.duration_s, 100.0, 1e-9);
	const DriftSeries& ra = rep.variant("a");
	EXPECT_NEAR(ra.heading_error_final_deg, 1.0, 1e-9);
	EXPECT_NEAR(ra.heading_error_max_deg, 1.0, 1e-9);
	EXPECT_NEAR(ra.position_error_final_m, 5.0, 1e-9);
	EXPECT_NEAR(ra.position_error_final_pct, 0.5, 1e-9);
	const DriftSeries& rb = rep.variant("b");
	EXPECT_NEAR(rb.heading_error_final_deg, 0.0, 1e-12);
	EXPECT_NEAR(rb.heading_error_max_deg, 2.0, 1e-9);
	EXPECT_NEAR(rb.heading_error_deg[50], -2.0, 1e-9);
	EXPECT_NEAR(rb.position_error_final_m, 2.0, 1e-9);
	EXPECT_NEAR(rb.position_error_max_m, 2.0, 1e-9);
	EXPECT_THROW(rep.variant("c"), std::out_of_range);
}

// Heading errors wrap: +179 deg truth vs -179 deg estimate is a 2 deg error, not 358 deg.
// A variant sampled at other times is interpolated at the truth's times.
TEST(DriftReport, WrapAndInterpolation)
{
	Trajectory truth = straightTruth();
	for (auto& p : truth) p.yaw_rad = mrpt::DEG2RAD(179.0);
	Trajectory v;
	for (int k = 0; k <= 200; ++k)
	{
		TrajectoryPoint p;
		p.t_s = 1000.0 + 0.5 * k;
		p.x_m = 5.0 * k;
		p.yaw_rad = mrpt::DEG2RAD(-179.0);
		v.push_back(p);
	}
	const DriftReport rep = computeDriftReport(truth, {{"v", v}});
	EXPECT_NEAR(rep.variant("v").heading_error_max_deg, 2.0, 1e-9);
	EXPECT_NEAR(rep.variant("v").position_error_max_m, 0.0, 1e-9);
	EXPECT_EQ(rep.variant("v").t_s.size(), truth.size());
}

TEST(DriftReport, BadInputThrows)
{
	const Trajectory truth = straightTruth();
	EXPECT_THROW(computeDriftReport(Trajectory(1), {}), std::invalid_argument);
	EXPECT_THROW(computeDriftReport(truth, {{"empty", Trajectory()}}), std::invalid_argument);
	Trajectory later(2);
	later[0].t_s = 5000;
	later[1].t_s = 5001;
	EXPECT_THROW(computeDriftReport(truth, {{"later", later}}), std::invalid_argument);
}
