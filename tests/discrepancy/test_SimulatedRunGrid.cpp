/* mrpt_fog: the profile grid of `fog-discrepancy --sim` on a run sampled every 0.1 s, every sample a
 * row (--block-s 0): the 10 Hz warm-up run (108 001 samples) used to fail at its last sample ("not
 * on the 0.1 s grid": the median single step, 0.1 plus or minus an ulp, is off the grid by 1e-3 of a
 * step after 1e5 steps). Truth: sample k of fog-sim's run is at k / rate_hz, simulator step k. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/SimulatedRun.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

TEST(SimulatedRunGrid, TenHertzRunSampleBySampleMapsEverySampleToItsStep)
{
	sim::SimSettings s;
	s.rate_hz = 10.0;
	const FogSeries run = sim::simulateChamber(sim::ChamberProfile::preset("warmup"), sim::FogDevice::defaultDevice(), s);
	ASSERT_EQ(run.size(), 108001u);
	SimulatorConfig cfg;
	cfg.profile = "warmup";
	const ChamberDrive d = chamberDriveForRun(run, cfg);
	EXPECT_EQ(d.rate_hz, 10.0);
	ASSERT_EQ(d.sim_index.size(), run.size());
	for (std::size_t k = 0; k < run.size(); k++) ASSERT_EQ(d.sim_index[k], k) << "t = " << run.time_s[k];

	// the same times as a rawlog stores them (100 ns ticks from a 1.7e9 s epoch, read back)
	FogSeries ticks = run;
	const double epoch = 1714521600.0;
	for (auto& t : ticks.time_s) t = std::llround((epoch + t) * 1e7) * 1e-7 - epoch;
	const ChamberDrive e = chamberDriveForRun(ticks, cfg);
	for (std::size_t k = 0; k < run.size(); k++) ASSERT_EQ(e.sim_index[k], k) << "t = " << ticks.time_s[k];
	EXPECT_NEAR(e.rate_hz, 10.0, 1e-9);

	// a run off the profile's grid is still refused
	FogSeries off = run;
	off.time_s[5000] += 0.03;
	EXPECT_THROW(chamberDriveForRun(off, cfg), std::invalid_argument);
}
