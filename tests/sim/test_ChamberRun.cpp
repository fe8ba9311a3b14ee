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

TEST(ChamberRun, SameSeedSameRunOtherSeedOtherNoise)
{
	auto profile = ChamberProfile::preset("warmup");
	SimSettings s;
	s.rate_hz = 1.0;
	const FogSeries a = simulateChamber(profile, FogDevice::defaultDevice(), s);
	const FogSeries b = simulateChamber(profile, FogDevice::defaultDevice(), s);
	EXPECT_EQ(a.rate_dph[2], b.rate_dph[2]);
	EXPECT_EQ(a.temp_C, b.temp_C);
	EXPECT_EQ(a.metadata, b.metadata);
	s.seed = 7;
	const FogSeries c = simulateChamber(profile, FogDevice::defaultDevice(), s);
	EXPECT_NE(a.rate_dph[2], c.rate_dph[2]);
	EXPECT_EQ(c.metadataValue("sim.seed"), "7");
}

TEST(ChamberRun, LayoutAndMetadata)
{
	SimSettings s;
	s.rate_hz = 0.5;
	const FogSeries r = simulateChamber(ChamberProfile::preset("rich"), FogDevice::defaultDevice(), s);
	EXPECT_NO_THROW(r.validate());
	EXPECT_EQ(r.thermistorCount(), 4u);
	EXPECT_EQ(r.table_rate_dph.size(), r.size());  // rich uses the rate table and field
	EXPECT_EQ(r.field_uT.size(), r.size());
	EXPECT_EQ(r.power.size(), r.size());
	EXPECT_EQ(r.metadataValue("sim.profile"), "rich");
	EXPECT_EQ(r.metadataValue("latitude_deg"), "40");
	EXPECT_EQ(r.metadataValue("sim.device.coil.pattern"), "quadrupolar");
	// powered-off samples report 0 and power 0
	bool saw_off = false;
	for (std::size_t k = 0; k < r.size(); k++)
		if (r.power[k] == 0)
		{
			saw_off = true;
			EXPECT_EQ(r.rate_dph[2][k], 0.0);
		}
	EXPECT_TRUE(saw_off);
	s.rate_hz = 0;
	EXPECT_THROW(simulateChamber(ChamberProfile::preset("seed"), FogDevice::defaultDevice(), s), std::invalid_argument);
}
