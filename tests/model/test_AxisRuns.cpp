/* mrpt_fog: tests of the per-axis runs of a multi-axis FOG (model/AxisRuns.h). */
#include <gtest/gtest.h>
#include <mrpt_fog/model/AxisRuns.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>

#include <cmath>
#include <numeric>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
// Per-axis truths of the synthetic coil (other Shupe and gradient sensitivities per axis).
fogtest::CoilTruth truthOf(int axis)
{
	fogtest::CoilTruth t;
	if (axis == 0) t.shupe_i1 = -30, t.shupe_o2 = 20, t.grad = -0.02;
	if (axis == 1) t.shupe_i2 = 90, t.static_lin = -0.004;
	return t;
}

/** A triad run: axis a = the synthetic coil with truthOf(a) and its own noise seed, plus the
 * constant Earth-rate projection earth[a] (stated in the metadata when `state`). */
FogSeries triadRun(const std::string& profile, unsigned seed, const double earth[3], bool state)
{
	FogSeries s = fogtest::makeCoilRun(profile, seed, 0.003, truthOf(2));
	for (int a = 0; a < 2; a++) s.rate_dph[a] = fogtest::makeCoilRun(profile, seed + 10 + a, 0.003, truthOf(a)).rate_dph[2];
	s.has_axis = {true, true, true};
	for (int a = 0; a < 3; a++)
	{
		for (double& v : s.rate_dph[a]) v += earth[a];
		if (state) s.setMetadata(std::string("earth_rate_dph.") + "xyz"[a], std::to_string(earth[a]));
	}
	return s;
}

FitOptions quick()
{
	FitOptions o;
	o.stability_resamples = 0;
	o.fallbacks = false;
	return o;
}

double mean(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0) / static_cast<double>(v.size()); }
}  // namespace

// Known truth: the calibration of a triad's axis is the single-axis calibration of that axis'
// data without the Earth rate (the stated projection is removed before the fit), and on a
// held-out run the compensated output keeps exactly the Earth rate the axis sees.
TEST(AxisRuns, TriadAxisCalibrationIsTheSingleAxisOneWithTheStatedEarthRateRemoved)
{
	const double earth[3] = {0.0, 11.522, 9.668}, none[3] = {0, 0, 0};
	std::vector<FogSeries> runs{triadRun("A", 1, earth, true)};
	std::vector<FogSeries> bare{triadRun("A", 1, none, false)};
	const FogSeries b = triadRun("B", 2, earth, true);
	for (GyroAxis axis : {GyroAxis::X, GyroAxis::Y, GyroAxis::Z})
	{
		const std::size_t a = static_cast<std::size_t>(axis);
		AxisRunSet set = runsForAxis(runs, {"A"}, axis);
		ASSERT_EQ(set.runs.size(), 1u);
		EXPECT_TRUE(set.earth_rate_removed);
		EXPECT_TRUE(set.runs[0].has_axis[a]);
		EXPECT_EQ(set.runs[0].primaryAxis(), axis);
		const Calibration cal = fitCalibration(set.runs, "multipoint", quick());
		EXPECT_EQ(cal.axis, axis);

		AxisRunSet bare_set = runsForAxis(bare, {"A"}, axis);
		EXPECT_FALSE(bare_set.earth_rate_removed);
		const Calibration ref = fitCalibration(bare_set.runs, "multipoint", quick());
		ASSERT_EQ(cal.model.features.termNames(), ref.model.features.termNames());
		for (std::size_t i = 0; i < cal.model.coef_dph.size(); i++)
			EXPECT_NEAR(cal.model.coef_dph[i], ref.model.coef_dph[i], 1e-9 * (1 + std::abs(ref.model.coef_dph[i])));

		std::vector<FogSeries> bv{b};
		const AxisRunSet held = runsForAxis(bv, {"B"}, axis);
		// runsForAxis removed the Earth rate from B too: compensated ~ 0 there; on B as
		// recorded (Earth rate in the output) the compensated mean is the axis' projection.
		FogSeries b_axis = held.runs[0];
		b_axis.rate_dph[a] = b.rate_dph[a];
		const CompensatedSeries c = compensate(cal, b_axis);
		std::vector<double> settled(c.compensated_dph.begin() + 300, c.compensated_dph.end());
		EXPECT_NEAR(mean(settled), earth[a], 0.01) << axisLetter(axis);
	}
}

TEST(AxisRuns, RateTableRunServesOnlyItsTableAxis)
{
	const double earth[3] = {0.0, 11.522, 9.668};
	FogSeries table = triadRun("A", 3, earth, false);
	table.table_rate_dph.assign(table.size(), 0.0);
	for (std::size_t k = 1000; k < 1300; k++) table.table_rate_dph[k] = 36000.0;
	table.setMetadata("table_axis", "y");
	std::vector<FogSeries> runs{table};
	EXPECT_EQ(tableAxis(table), GyroAxis::Y);
	const AxisRunSet x = runsForAxis(runs, {"rt"}, GyroAxis::X);
	EXPECT_TRUE(x.runs.empty());
	ASSERT_EQ(x.skipped.size(), 1u);
	EXPECT_NE(x.skipped[0].find("rt: its table turns about y"), std::string::npos) << x.skipped[0];
	EXPECT_EQ(runsForAxis(runs, {"rt"}, GyroAxis::Y).runs.size(), 1u);
	// a single-axis run without table_axis: its table turns about its own axis
	FogSeries one = fogtest::makeCoilRun("A", 4);
	EXPECT_EQ(tableAxis(one), GyroAxis::Z);
	one.setMetadata("table_axis", "w");
	EXPECT_THROW(tableAxis(one), std::invalid_argument);
}

TEST(AxisRuns, MixOfStatedAndUnstatedEarthRateIsRefusedNamingTheRun)
{
	const double earth[3] = {0.0, 11.522, 9.668};
	std::vector<FogSeries> runs{triadRun("A", 5, earth, true), triadRun("B", 6, earth, false)};
	try
	{
		runsForAxis(runs, {"a.rawlog", "b.rawlog"}, GyroAxis::Y);
		FAIL() << "no error";
	}
	catch (const std::invalid_argument& e)
	{
		const std::string m = e.what();
		EXPECT_NE(m.find("b.rawlog: metadata earth_rate_dph.y missing"), std::string::npos) << m;
	}
	runs[0].setMetadata("earth_rate_dph.x", "fast");
	EXPECT_THROW(runsForAxis(runs, {"a", "b"}, GyroAxis::X), std::invalid_argument);
	EXPECT_EQ(commonAxes(runs).size(), 3u);
}
