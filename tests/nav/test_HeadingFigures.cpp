/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
// HeadingFigures against a drive built here with known turns and a heading error of known
// drift and scale factor: e(t) = d t + s (psi(t) - psi(0)) (closed form, not from the code).
#include <gtest/gtest.h>
#include <mrpt_fog_nav/HeadingFigures.h>

#include <cmath>

using namespace mrpt_fog::nav;

namespace
{
/** 10 Hz truth: 200 s straight, then alternately a 90 deg turn at 9 deg/s (10 s, smooth
 * cosine rate profile) and a 120 s straight, 8 turns (4 left, 4 right), 200 s straight. */
Trajectory drive(std::vector<double>& psi_deg)
{
	Trajectory tr;
	double psi = 0, t = 0;
	const double dt = 0.1;
	auto push = [&](double rate_dps) {
		psi += rate_dps * dt;
		t += dt;
		TrajectoryPoint p;
		p.t_s = t;
		p.yaw_rad = std::remainder(psi * M_PI / 180.0, 2 * M_PI);
		tr.push_back(p);
		psi_deg.push_back(psi);
	};
	TrajectoryPoint p0;
	tr.push_back(p0);
	psi_deg.push_back(0);
	for (int i = 0; i < 2000; i++) push(0);
	for (int turn = 0; turn < 8; turn++)
	{
		const double sign = turn % 2 ? -1.0 : 1.0;
		// 90 deg in 10 s, rate 9 (1 - cos(2 pi u)) deg/s for u in [0, 1]
		for (int i = 1; i <= 100; i++) push(sign * 9.0 * (1 - std::cos(2 * M_PI * (i - 0.5) / 100.0)));
		for (int i = 0; i < (turn == 7 ? 2000 : 1200); i++) push(0);
	}
	return tr;
}
}  // namespace

TEST(HeadingFigures, RecoversDriftAndScaleFactorOfAKnownError)
{
	std::vector<double> psi;
	const Trajectory truth = drive(psi);
	const DriveSegments seg = segmentDrive(truth);
	EXPECT_EQ(seg.turns.size(), 8u);
	EXPECT_EQ(seg.straights.size(), 9u);
	const double d_dph = 0.05, s_ppm = -445.0;
	std::vector<double> t, e;
	double ss = 0, emax = 0;
	for (std::size_t i = 0; i < truth.size(); i++)
	{
		t.push_back(truth[i].t_s);
		e.push_back(d_dph / 3600.0 * truth[i].t_s + 1e-6 * s_ppm * (psi[i] - psi[0]));
		ss += e.back() * e.back();
		emax = std::max(emax, std::abs(e.back()));
	}
	const HeadingFigures f = computeHeadingFigures(t, e, truth, seg);
	EXPECT_NEAR(f.heading_drift_between_turns_dph, d_dph, 1e-9);
	EXPECT_NEAR(f.turn_scale_factor_ppm, s_ppm, 1e-6);
	EXPECT_NEAR(f.heading_error_rms_deg, std::sqrt(ss / static_cast<double>(e.size())), 1e-12);
	EXPECT_DOUBLE_EQ(f.heading_error_max_deg, emax);
	EXPECT_DOUBLE_EQ(f.heading_error_final_deg, std::abs(e.back()));
	EXPECT_EQ(f.turns, 8u);
	EXPECT_NEAR(f.turned_deg, 720.0, 1e-6);
}

// A drive without turns: drift defined, turn scale factor NaN (not a made-up 0).
TEST(HeadingFigures, NoTurnGivesNaNScaleFactor)
{
	Trajectory truth;
	std::vector<double> t, e;
	for (int i = 0; i <= 6000; i++)
	{
		TrajectoryPoint p;
		p.t_s = 0.1 * i;
		truth.push_back(p);
		t.push_back(p.t_s);
		e.push_back(0.01 / 3600.0 * p.t_s);
	}
	const HeadingFigures f = computeHeadingFigures(t, e, truth, segmentDrive(truth));
	EXPECT_NEAR(f.heading_drift_between_turns_dph, 0.01, 1e-9);
	EXPECT_TRUE(std::isnan(f.turn_scale_factor_ppm));
	EXPECT_EQ(f.turns, 0u);
	EXPECT_THROW(computeHeadingFigures({1.0}, {0.0}, truth, {}), std::invalid_argument);
}
