/* mrpt_fog: tests of the chamber runner and the default device. */
#include <gtest/gtest.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <chrono>
#include <cmath>
#include <iostream>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

TEST(ChamberRun, DefaultDeviceSeedProfileUncompensatedNearSeedFigures)
{
	// Seed Table 1, uncompensated: 0.114857 deg/h stability (std of 100 s averages) and
	// 0.5082 deg/h range (max - min of the averages); the default device must land within
	// +-30 % of both (issue 4). This is the only place the default device was matched.
	const auto profile = ChamberProfile::preset("seed");
	SimSettings s;
	const auto t0 = std::chrono::steady_clock::now();
	const FogSeries run = simulateChamber(profile, FogDevice::defaultDevice(), s);
	const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
	const BiasStats st = biasStats(run.time_s, run.rate_dph[2], 100.0);
	std::cout << "seed profile, default device, seed " << s.seed << ", 10 Hz: stability " << st.stability_dph
			  << " deg/h, range " << st.range_dph << " deg/h, " << run.size() << " samples in " << elapsed << " s\n";
	EXPECT_EQ(run.size(), 243001u);
	EXPECT_NEAR(st.stability_dph, 0.114857, 0.3 * 0.114857);
	EXPECT_NEAR(st.range_dph, 0.5082, 0.3 * 0.5082);
}
