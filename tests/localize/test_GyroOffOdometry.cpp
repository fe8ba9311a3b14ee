/* mrpt_fog: fog-localize's odometry on a drive with the gyro off in places (GyroOffOdometry.h),
 * against closed-form poses: two powered spans dead-reckoned in frames of their own, a gap with
 * the wheel odometry alone on a circle. The relative poses are computed here by hand, not with
 * CPose2D's operators. */
#include <gtest/gtest.h>

#include "GyroOffOdometry.h"

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::localize;

namespace
{
struct P
{
	double x, y, phi;
};
double wrap(double a) { return std::remainder(a, 2 * M_PI); }
/** b relative to a, by hand */
P rel(const P& a, const P& b)
{
	const double c = std::cos(a.phi), s = std::sin(a.phi), dx = b.x - a.x, dy = b.y - a.y;
	return {c * dx + s * dy, -s * dx + c * dy, wrap(b.phi - a.phi)};
}
P of(const mrpt::poses::CPose2D& p) { return {p.x(), p.y(), p.phi()}; }
// span A (0..10 s): a straight line along x at 2 m/s from (5, -3), heading 0
P spanA(double t) { return {5 + 2 * t, -3, 0}; }
// span B (20..30 s): in a frame of its own (as re-aligned from the truth at its start): a turn
// at 0.1 rad/s from (100, 50), heading 1 rad
P spanB(double t)
{
	const double w = 0.1, v = 2, a = 1.0 + w * (t - 20);
	return {100 + v / w * (std::sin(a) - std::sin(1.0)), 50 - v / w * (std::cos(a) - std::cos(1.0)), wrap(a)};
}
// the wheel odometry (0..30 s): a circle of radius 40 m at 2 m/s, heading 0.05 t
P wheel(double t) { return {40 * std::sin(0.05 * t), 40 * (1 - std::cos(0.05 * t)), wrap(0.05 * t)}; }

nav::Trajectory sampled(P (*f)(double), double t0, double t1)
{
	nav::Trajectory tr;
	for (double t = t0; t <= t1 + 1e-9; t += 0.5)
	{
		nav::TrajectoryPoint p;
		p.t_s = t;
		const P q = f(t);
		p.x_m = q.x, p.y_m = q.y, p.yaw_rad = q.phi;
		tr.push_back(p);
	}
	return tr;
}
heading::OdometryPoses wheelPoses()
{
	heading::OdometryPoses w;
	for (double t = 0; t <= 30 + 1e-9; t += 0.5)
	{
		const P q = wheel(t);
		w.t_s.push_back(t), w.x_m.push_back(q.x), w.y_m.push_back(q.y), w.phi_rad.push_back(q.phi);
	}
	return w;
}
void expectNear(const P& a, const P& b, const char* what, double t)
{
	EXPECT_NEAR(a.x, b.x, 1e-9) << what << " at t = " << t;
	EXPECT_NEAR(a.y, b.y, 1e-9) << what << " at t = " << t;
	EXPECT_NEAR(wrap(a.phi - b.phi), 0.0, 1e-12) << what << " at t = " << t;
}
}  // namespace

TEST(GyroOffOdometry, GyroStepsFollowTheirSpanWheelStepsTheWheelsAcrossTheGap)
{
	const std::vector<nav::Trajectory> spans = {sampled(spanA, 0, 10), sampled(spanB, 20, 30)};
	std::vector<double> scans;
	for (double t = 0.5; t < 30; t += 1.0) scans.push_back(t);  // on the samples: no interpolation error
	const ScanOdometry o = odometryAtScans(spans, wheelPoses(), scans, mrpt::poses::CPose2D());
	ASSERT_EQ(o.poses.size(), scans.size());
	ASSERT_EQ(o.step.size(), scans.size());
	// the first span as dead-reckoned (a drive powered throughout is unchanged)
	for (std::size_t k = 0; k < scans.size() && scans[k] <= 10; k++) expectNear(of(o.poses[k]), spanA(scans[k]), "span A pose", scans[k]);
	// steps from scan 10.5 (first outside span A) to scan 20.5 (first inside span B): the wheels
	std::size_t wheel_steps = 0;
	for (std::size_t k = 1; k < scans.size(); k++)
	{
		const bool expect_wheel = scans[k] > 10 && scans[k - 1] < 20;
		EXPECT_EQ(o.step[k] == StepSource::WheelOnly, expect_wheel) << "t = " << scans[k];
		wheel_steps += expect_wheel;
		const P got = rel(of(o.poses[k - 1]), of(o.poses[k]));
		if (expect_wheel) expectNear(got, rel(wheel(scans[k - 1]), wheel(scans[k])), "wheel increment", scans[k]);
		else if (scans[k] < 10) expectNear(got, rel(spanA(scans[k - 1]), spanA(scans[k])), "span A increment", scans[k]);
		else expectNear(got, rel(spanB(scans[k - 1]), spanB(scans[k])), "span B increment", scans[k]);
	}
	EXPECT_EQ(wheel_steps, 11u);
	EXPECT_EQ(o.wheel_only_steps, 11u);
}

TEST(GyroOffOdometry, PoweredThroughoutIsTheTrajectoryItself)
{
	const std::vector<nav::Trajectory> spans = {sampled(spanB, 20, 30)};
	std::vector<double> scans;
	for (double t = 20.25; t < 30; t += 0.7) scans.push_back(t);  // between samples: interpolated
	const ScanOdometry o = odometryAtScans(spans, wheelPoses(), scans, mrpt::poses::CPose2D());
	EXPECT_EQ(o.wheel_only_steps, 0u);
	for (std::size_t k = 0; k < scans.size(); k++)
	{
		const nav::TrajectoryPoint p = nav::interpolate(spans.front(), scans[k]);
		EXPECT_EQ(o.poses[k].x(), p.x_m);
		EXPECT_EQ(o.poses[k].y(), p.y_m);
		EXPECT_EQ(o.poses[k].phi(), p.yaw_rad);
	}
}

TEST(GyroOffOdometry, WheelPoseInterpolatesHeadingOnTheShortArcAndRefusesBadInput)
{
	heading::OdometryPoses w;
	w.t_s = {0, 1};
	w.x_m = {0, 2};
	w.y_m = {0, 4};
	w.phi_rad = {3.0, -3.0};  // 0.283 rad apart across +-pi
	const mrpt::poses::CPose2D m = wheelPoseAt(w, 0.5);
	EXPECT_NEAR(m.x(), 1.0, 1e-12);
	EXPECT_NEAR(m.y(), 2.0, 1e-12);
	EXPECT_NEAR(std::abs(m.phi()), M_PI, 1e-12);
	EXPECT_THROW(odometryAtScans({}, w, {0.5}, mrpt::poses::CPose2D()), std::invalid_argument);
	EXPECT_THROW(odometryAtScans({}, heading::OdometryPoses{}, {0.1, 0.5}, mrpt::poses::CPose2D()), std::invalid_argument);
}
