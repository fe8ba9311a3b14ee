/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/RunSignals.h>

#include <cmath>
#include <limits>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
/** 2 inner + 2 outer thermistors; temperatures from a function of time. */
template <class F>
FogSeries makeRun(std::size_t n, double dt, F temp)
{
	FogSeries s;
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}, {"Ti2", CoilSide::Inner, 180}, {"To1", CoilSide::Outer, 0},
					 {"To2", CoilSide::Outer, 180}};
	s.temp_C.assign(4, {});
	for (std::size_t k = 0; k < n; ++k)
	{
		const double t = k * dt;
		s.time_s.push_back(t);
		s.rate_dph[2].push_back(0.1);
		for (int i = 0; i < 4; ++i) s.temp_C[i].push_back(temp(t, i));
	}
	return s;
}
}  // namespace

TEST(RunSignals, LinearRampGivesExactRateAndGradient)
{
	// inner = 1 C/min ramp, outer = inner + 2 C: rate exactly 1 C/min, gradient exactly -2 C
	const auto run = makeRun(200, 10.0, [](double t, int i) { return 20.0 + t / 60.0 + (i >= 2 ? 2.0 : 0.0); });
	const auto s = computeRunSignals(run);
	ASSERT_EQ(s.size(), 200u);
	EXPECT_TRUE(s.has_inner_outer);
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		EXPECT_NEAR(s.dtemp_dt_Cpm[k], 1.0, 1e-9);
		EXPECT_NEAR(s.gradient_C[k], -2.0, 1e-12);
		EXPECT_NEAR(s.dgradient_dt_Cpm[k], 0.0, 1e-9);
	}
	EXPECT_EQ(s.usableCount(), 200u);
	EXPECT_DOUBLE_EQ(s.dt_s, 10.0);
}

TEST(RunSignals, ShortDropoutBridgedLongDropoutUnusable)
{
	auto run = makeRun(300, 10.0, [](double t, int) { return 25.0 + 0.5 * t / 60.0; });
	const double nan = std::numeric_limits<double>::quiet_NaN();
	for (int k = 50; k < 55; ++k) run.temp_C[0][k] = nan;  // 50 s: bridged
	for (int k = 100; k < 160; ++k) run.temp_C[1][k] = nan;  // 600 s > 300 s: unusable
	const auto s = computeRunSignals(run);
	EXPECT_TRUE(s.usable[52]);
	EXPECT_NEAR(s.thermistor_C[0][52], 25.0 + 0.5 * 520.0 / 60.0, 1e-9);
	EXPECT_FALSE(s.usable[130]);
	EXPECT_EQ(s.block[130], -1);
	EXPECT_NE(s.block[90], s.block[170]);  // the dropout splits the blocks
}

TEST(RunSignals, TimeGapStartsNewBlockAndPowerOffIsUnusable)
{
	auto run = makeRun(200, 10.0, [](double, int) { return 20.0; });
	for (std::size_t k = 100; k < 200; ++k) run.time_s[k] += 3600.0;  // a 1 h gap
	run.power.assign(200, 1.0);
	for (std::size_t k = 150; k < 160; ++k) run.power[k] = 0.0;
	const auto s = computeRunSignals(run);
	EXPECT_NE(s.block[99], s.block[100]);
	EXPECT_FALSE(s.usable[155]);
	ASSERT_EQ(s.power_on_s.size(), 2u);  // run start and after the power-off
	EXPECT_DOUBLE_EQ(s.power_on_s[1], run.time_s[160]);
}

TEST(RunSignals, RejectsTooShortOrNoThermistors)
{
	auto shortRun = makeRun(10, 1.0, [](double, int) { return 20.0; });
	EXPECT_THROW(computeRunSignals(shortRun), std::invalid_argument);
	auto noTherm = makeRun(50, 1.0, [](double, int) { return 20.0; });
	noTherm.thermistors.clear();
	noTherm.temp_C.clear();
	EXPECT_THROW(computeRunSignals(noTherm), std::invalid_argument);
}

TEST(RunSignals, BiasIsRateMinusTableRate)
{
	auto run = makeRun(50, 1.0, [](double, int) { return 20.0; });
	run.table_rate_dph.assign(50, 0.0);
	for (std::size_t k = 20; k < 30; ++k)
	{
		run.table_rate_dph[k] = 3600.0;
		run.rate_dph[2][k] = 3600.1;
	}
	const auto s = computeRunSignals(run);
	EXPECT_TRUE(s.has_table);
	EXPECT_NEAR(s.bias_dph[25], 0.1, 1e-9);
	EXPECT_NEAR(s.bias_dph[5], 0.1, 1e-12);
}

TEST(RunSignals, ThermistorsOnNeitherSideGiveOuterMinusOtherAndStayOutOfTheCoilTemperature)
{
	// inner 30 C, outer 28 C, a housing thermistor (CoilSide::Other) at 20 C + 1 C/min
	FogSeries run;
	run.thermistors = {{"Ca", CoilSide::Inner, 30}, {"Cb", CoilSide::Outer, 210}, {"Hs", CoilSide::Other, 0}};
	run.temp_C.assign(3, {});
	for (std::size_t k = 0; k < 100; ++k)
	{
		const double t = 10.0 * static_cast<double>(k);
		run.time_s.push_back(t);
		run.rate_dph[2].push_back(0.1);
		run.temp_C[0].push_back(30.0);
		run.temp_C[1].push_back(28.0);
		run.temp_C[2].push_back(20.0 + t / 60.0);
	}
	const auto s = computeRunSignals(run);
	EXPECT_TRUE(s.has_other);
	ASSERT_EQ(s.outer_other_C.size(), s.size());
	ASSERT_EQ(s.temp_coil_C.size(), s.size());
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		const double t = s.time_s[k];
		EXPECT_NEAR(s.outer_other_C[k], 28.0 - (20.0 + t / 60.0), 1e-9);
		EXPECT_NEAR(s.temp_coil_C[k], 29.0, 1e-12);  // the housing is not the coil
		EXPECT_NEAR(s.dtemp_coil_dt_Cpm[k], 0.0, 1e-9);
		EXPECT_NEAR(s.dtemp_dt_Cpm[k], 1.0 / 3.0, 1e-9);  // the mean of all three still moves
	}
	// without a thermistor on neither side: no second gradient column, coil = mean
	const auto plain = computeRunSignals(makeRun(50, 10.0, [](double t, int i) { return 20.0 + t / 60.0 + i; }));
	EXPECT_FALSE(plain.has_other);
	EXPECT_TRUE(plain.outer_other_C.empty());
	EXPECT_EQ(plain.temp_coil_C, plain.temp_mean_C);
}
