/* mrpt_fog: tests of the closed-form vehicle trajectory. */
#include <gtest/gtest.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/DriveTrajectory.h>

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

TEST(DriveTrajectory, ClosedFormMatchesFineNumericalIntegration)
{
	// Accelerating turn, braking turn, straight: integrate x' = v cos(yaw), y' = v sin(yaw)
	// with RK4 at 1 ms from the segment definitions alone and compare.
	const std::vector<DriveSegment> segs = {{20.0, 10.0, 15.0}, {15.0, 4.0, -10.0}, {30.0, 12.0, 0.0}};
	const DriveTrajectory traj(segs, 2.0);
	double x = 0, y = 0, yaw = 0, t = 0, v0 = 2.0;
	const double h = 1e-3;
	for (const auto& g : segs)
	{
		const double a = (g.speed_end_mps - v0) / g.duration_s, w = g.yaw_rate_dps * units::kDegToRad;
		const int n = static_cast<int>(std::round(g.duration_s / h));
		for (int i = 0; i < n; i++)
		{
			const double tl = i * h;
			auto f = [&](double s, double yw, double& dx, double& dy) {
				dx = (v0 + a * s) * std::cos(yw);
				dy = (v0 + a * s) * std::sin(yw);
			};
			double k1x, k1y, k2x, k2y, k4x, k4y;
			f(tl, yaw, k1x, k1y);
			f(tl + h / 2, yaw + w * h / 2, k2x, k2y);
			f(tl + h, yaw + w * h, k4x, k4y);
			x += h / 6 * (k1x + 4 * k2x + k4x);
			y += h / 6 * (k1y + 4 * k2y + k4y);
			yaw += w * h;
		}
		t += g.duration_s;
		v0 = g.speed_end_mps;
		const PlanarState s = traj.at(t);
		EXPECT_NEAR(s.x_m, x, 1e-7);
		EXPECT_NEAR(s.y_m, y, 1e-7);
		EXPECT_NEAR(s.yaw_rad, yaw, 1e-9);
	}
	EXPECT_DOUBLE_EQ(traj.duration_s(), 65.0);
	EXPECT_NEAR(traj.at(65.0).distance_m, 0.5 * (2 + 10) * 20 + 0.5 * (10 + 4) * 15 + 0.5 * (4 + 12) * 30, 1e-9);
}

TEST(DriveTrajectory, RandomDriveIsRealisticAndExactLength)
{
	const DriveTrajectory d = DriveTrajectory::randomDrive(20240501, 3600.0);
	EXPECT_DOUBLE_EQ(d.duration_s(), 3600.0);
	int turns = 0, stops = 0;
	double v_prev = 0, vmax = 0;
	for (const auto& g : d.segments())
	{
		if (g.yaw_rate_dps != 0) turns++;
		if (g.speed_end_mps == 0 && v_prev == 0) stops++;
		// lateral acceleration during turns at most 2.5 m/s2
		EXPECT_LE(std::abs(g.yaw_rate_dps) * units::kDegToRad * std::max(g.speed_end_mps, v_prev), 2.5 + 1e-9);
		vmax = std::max(vmax, g.speed_end_mps);
		v_prev = g.speed_end_mps;
	}
	EXPECT_GT(turns, 10);
	EXPECT_GT(stops, 2);
	EXPECT_GT(vmax, 12.0);
	EXPECT_LE(vmax, 20.0);
	EXPECT_DOUBLE_EQ(d.at(60.0).speed_mps, 0.0);  // starts with a stop
	EXPECT_THROW(DriveTrajectory({{-1, 0, 0}}), std::invalid_argument);
}
