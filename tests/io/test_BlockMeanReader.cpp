/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* Block means with bounded rows (io/BlockMeanReader.h): a slow log passes through bit for bit,
 * a fast one gives the closed-form means of linear signals, blocks never mix power states,
 * table rates or bridge gaps, dropouts average over the finite readings, and the rows stay
 * within max_rows by merging in pairs. */
#include <mrpt_fog/io/BlockMeanReader.h>
#include <mrpt_fog/obs/FogSeriesLayout.h>

#include <algorithm>
#include <cmath>

#include "IoTestUtil.h"

using namespace mrpt_fog;

namespace
{
/** A layout with two thermistors, the z axis, and the optional columns asked for. */
FogSeries layout(bool table, bool power)
{
	FogSeries s;
	s.thermistors = {{"Ti1", CoilSide::Inner, 0.0}, {"To1", CoilSide::Outer, 0.0}};
	s.temp_C.resize(2);
	s.rate_dph[2] = {};
	return layoutHeaderOf(s, table, false, power);
}

FogSample sample(double t, double rate, double t1, double t2, double table = NAN, double power = NAN)
{
	FogSample x;
	x.time_s = t;
	x.rate_dph = {{NAN, NAN, rate}};
	x.temp_C = {t1, t2};
	x.table_rate_dph = table;
	x.power = power;
	return x;
}

// n samples at 10 Hz from t = 0 with a constant rate and both thermistors reading t (C = s)
void addTenHzRamp(BlockMeanAccumulator& acc, std::size_t n, double rate_dph)
{
	for (std::size_t k = 0; k < n; k++)
	{
		const double t = 0.1 * static_cast<double>(k);
		acc.add(sample(t, rate_dph, t, t));
	}
}
}  // namespace

TEST(BlockMeanReader, SlowLogPassesThroughBitForBit)
{
	// 0.25 Hz with 225 power-off rows and a turn-on: slower than 1 / min_block_s
	const std::string f = iotest::dataFile("power_cycle.csv");
	BlockMeanInfo info;
	const FogSeries reduced = readFogLogBlockMeans(f, "", BlockMeanOptions{}, info);
	const FogSeries whole = readFogLog(f);
	EXPECT_FALSE(info.reduced());
	EXPECT_EQ(info.samples_per_block, 1u);
	EXPECT_DOUBLE_EQ(info.native_period_s, 4.0);
	iotest::expectSameSeries(reduced, whole);
}

TEST(BlockMeanReader, LinearSignalsGiveTheClosedFormMeans)
{
	// 10 Hz, 1 s blocks: block j holds samples 10j .. 10j + 9, mean time 0.1 (10j + 4.5)
	BlockMeanAccumulator acc(layout(false, false), BlockMeanOptions{});
	const std::size_t n = 1005;  // the last block holds 5 samples
	for (std::size_t k = 0; k < n; k++)
	{
		const double t = 0.1 * static_cast<double>(k);
		acc.add(sample(t, 3.0 - 0.02 * t, 20.0 + 0.01 * t, -5.0 + 0.3 * t));
	}
	BlockMeanInfo info;
	const FogSeries s = acc.finish(info);
	EXPECT_EQ(info.samples, n);
	EXPECT_EQ(info.samples_per_block, 10u);
	EXPECT_NEAR(info.block_s, 1.0, 1e-12);
	ASSERT_EQ(s.size(), 101u);
	for (std::size_t j = 0; j < s.size(); j++)
	{
		const double count = j < 100 ? 10.0 : 5.0;
		const double tm = 0.1 * (10.0 * static_cast<double>(j) + (count - 1.0) / 2.0);
		EXPECT_NEAR(s.time_s[j], tm, 1e-9) << j;
		EXPECT_NEAR(s.rate_dph[2][j], 3.0 - 0.02 * tm, 1e-9) << j;
		EXPECT_NEAR(s.temp_C[0][j], 20.0 + 0.01 * tm, 1e-9) << j;
		EXPECT_NEAR(s.temp_C[1][j], -5.0 + 0.3 * tm, 1e-9) << j;
	}
	EXPECT_NO_THROW(s.validate());
}

TEST(BlockMeanReader, BlocksEndAtPowerAndTableChangesAndGaps)
{
	BlockMeanAccumulator acc(layout(true, true), BlockMeanOptions{});
	// 10 Hz; power off at sample 13 (rate NaN), on again at 27; table 0 -> 100 deg/s at 45;
	// a 2 s gap after sample 60
	std::size_t k = 0;
	double t = 0;
	for (; k < 80; k++)
	{
		const bool on = k < 13 || k >= 27;
		const double table = k < 45 ? 0.0 : 360000.0;
		acc.add(sample(t, on ? 1.0 + table : NAN, 20.0, 20.0, table, on ? 1.0 : 0.0));
		t += k == 60 ? 2.0 : 0.1;
	}
	BlockMeanInfo info;
	const FogSeries s = acc.finish(info);
	// blocks: [0,10) [10,13) | off [13,23) [23,27) | on [27,37) [37,45) | table [45,55) [55,61) | gap [61,71) [71,80)
	ASSERT_EQ(s.size(), 10u);
	const std::vector<double> power{1, 1, 0, 0, 1, 1, 1, 1, 1, 1};
	const std::vector<double> table{0, 0, 0, 0, 0, 0, 360000, 360000, 360000, 360000};
	EXPECT_EQ(s.power, power);
	EXPECT_EQ(s.table_rate_dph, table);
	for (std::size_t j = 0; j < s.size(); j++)
		if (power[j] == 1.0) EXPECT_DOUBLE_EQ(s.rate_dph[2][j], 1.0 + table[j]) << j;
		else EXPECT_TRUE(std::isnan(s.rate_dph[2][j])) << j;
	EXPECT_NEAR(s.time_s[1], 0.1 * 11.0, 1e-12);  // samples 10, 11, 12
	EXPECT_NEAR(s.time_s[8], 6.0 + 2.0 + 0.1 * 4.5, 1e-9);  // samples 61..70 at 8.0 .. 8.9 s
	EXPECT_NO_THROW(s.validate());
}

TEST(BlockMeanReader, DropoutsAverageOverTheFiniteReadings)
{
	BlockMeanAccumulator acc(layout(false, false), BlockMeanOptions{});
	for (std::size_t k = 0; k < 100; k++)
	{
		const double t = 0.1 * static_cast<double>(k);
		// thermistor 0: samples 10..14 lost (half of block 1); thermistor 1: block 3 lost
		const double t1 = k >= 10 && k < 15 ? NAN : static_cast<double>(k);
		const double t2 = k >= 30 && k < 40 ? NAN : 1.0;
		acc.add(sample(t, 0.0, t1, t2));
	}
	BlockMeanInfo info;
	const FogSeries s = acc.finish(info);
	ASSERT_EQ(s.size(), 10u);
	EXPECT_DOUBLE_EQ(s.temp_C[0][1], 17.0);  // mean of 15..19
	EXPECT_DOUBLE_EQ(s.temp_C[0][2], 24.5);
	EXPECT_TRUE(std::isnan(s.temp_C[1][3]));
	EXPECT_DOUBLE_EQ(s.temp_C[1][4], 1.0);
}

TEST(BlockMeanReader, RowsStayWithinTheLimitByMergingInPairs)
{
	BlockMeanOptions opt;
	opt.max_rows = 1000;
	BlockMeanAccumulator acc(layout(false, false), opt);
	const std::size_t n = 100000;  // 10 Hz, 10 000 s: 10 000 blocks of 1 s before merging
	for (std::size_t k = 0; k < n; k++)
	{
		const double t = 0.1 * static_cast<double>(k);
		acc.add(sample(t, 0.5 * t, t, 2.0 * t));
	}
	BlockMeanInfo info;
	const FogSeries s = acc.finish(info);
	EXPECT_LE(s.size(), 1000u);
	EXPECT_GT(s.size(), 500u);
	EXPECT_EQ(info.doublings, 4);  // 1 s -> 16 s blocks: 10 000 / 16 = 625 rows
	EXPECT_EQ(info.samples_per_block, 160u);
	EXPECT_EQ(s.size(), 625u);
	for (std::size_t j = 0; j < s.size(); j++)
	{
		// block j: samples 160 j .. 160 j + 159, mean time 0.1 (160 j + 79.5)
		const double tm = 0.1 * (160.0 * static_cast<double>(j) + 79.5);
		EXPECT_NEAR(s.time_s[j], tm, 1e-7) << j;
		EXPECT_NEAR(s.rate_dph[2][j], 0.5 * tm, 1e-7) << j;
		EXPECT_NEAR(s.temp_C[1][j], 2.0 * tm, 1e-7) << j;
	}
}

TEST(BlockMeanReader, ZeroBlockLengthKeepsEverySample)
{
	BlockMeanOptions opt;
	opt.min_block_s = 0;
	opt.max_rows = 10;
	BlockMeanAccumulator acc(layout(false, false), opt);
	for (std::size_t k = 0; k < 500; k++) acc.add(sample(0.01 * static_cast<double>(k), 1.0, 20.0, 21.0));
	BlockMeanInfo info;
	EXPECT_EQ(acc.finish(info).size(), 500u);
	EXPECT_FALSE(info.reduced());
}

TEST(BlockMeanReader, PoweredSampleWithoutRateIsRefused)
{
	BlockMeanAccumulator acc(layout(false, false), BlockMeanOptions{});
	for (std::size_t k = 0; k < 100; k++) acc.add(sample(0.1 * static_cast<double>(k), 1.0, 20.0, 21.0));
	const std::string msg = fogtest::messageOf<std::invalid_argument>(
		[&]() { acc.add(sample(10.0, NAN, 20.0, 21.0)); });
	EXPECT_NE(msg.find("sample 100"), std::string::npos) << msg;
	EXPECT_NE(msg.find("not finite"), std::string::npos) << msg;
}

TEST(BlockMeanReader, RawlogEqualsMeansOfTheWholeRead)
{
	// the bundled 10 Hz chamber run (no power change, gap or table): 1 s blocks are consecutive
	// groups of 10 samples of what readFogLog returns
	const std::string f = std::string(FOG_SOURCE_DIR) + "/datasets/chamber_A.rawlog";
	BlockMeanInfo info;
	const FogSeries s = readFogLogBlockMeans(f, "", BlockMeanOptions{}, info);
	const FogSeries w = readFogLog(f);
	EXPECT_EQ(info.samples, w.size());
	EXPECT_EQ(info.samples_per_block, 10u);
	ASSERT_EQ(s.size(), (w.size() + 9) / 10);
	EXPECT_EQ(s.sensor_label, w.sensor_label);
	EXPECT_EQ(s.epoch_s, w.epoch_s);
	EXPECT_TRUE(s.sameLayout(w));
	for (std::size_t j = 0; j < s.size(); j++)
	{
		const std::size_t k0 = 10 * j, k1 = std::min(k0 + 10, w.size());
		double t = 0, r = 0;
		std::vector<double> th(w.temp_C.size(), 0.0);
		for (std::size_t k = k0; k < k1; k++)
		{
			t += w.time_s[k];
			r += w.rate_dph[2][k];
			for (std::size_t i = 0; i < th.size(); i++) th[i] += w.temp_C[i][k];
		}
		const double c = static_cast<double>(k1 - k0);
		ASSERT_NEAR(s.time_s[j], t / c, 1e-9) << j;
		ASSERT_NEAR(s.rate_dph[2][j], r / c, 1e-9) << j;
		for (std::size_t i = 0; i < th.size(); i++) ASSERT_NEAR(s.temp_C[i][j], th[i] / c, 1e-9) << j;
	}
}

TEST(BlockMeanReader, RawQuantumOfTheThermistors)
{
	// 10 Hz, a 0.01 C/s ramp read through a 0.1 C quantiser: raw steps are 0.1 C, the 1 s means
	// step by 0.01 C
	BlockMeanAccumulator acc(layout(false, false), BlockMeanOptions{});
	for (std::size_t k = 0; k < 20000; k++)
	{
		const double t = 0.1 * static_cast<double>(k);
		const double q = 0.1 * std::round((20.0 + 0.01 * t) / 0.1);
		acc.add(sample(t, 0.0, q, q));
	}
	BlockMeanInfo info;
	const FogSeries s = acc.finish(info);
	EXPECT_NEAR(info.thermistor_step_p05_C, 0.1, 1e-9);
	std::vector<double> row_steps;
	for (std::size_t j = 1; j < s.size(); j++)
		if (s.temp_C[0][j] != s.temp_C[0][j - 1]) row_steps.push_back(std::fabs(s.temp_C[0][j] - s.temp_C[0][j - 1]));
	ASSERT_GT(row_steps.size(), 100u);
	std::sort(row_steps.begin(), row_steps.end());
	EXPECT_LT(row_steps[row_steps.size() / 20], 0.05);  // why the analysis needs the raw figure
}

TEST(BlockMeanReader, BlocksStopGrowingAtTheirLongest)
{
	// 10 Hz for 40 000 s with at most 1000 rows: blocks would reach 64 s, they stop at 16 s and
	// the rows grow to 2500 instead
	BlockMeanOptions opt;
	opt.max_rows = 1000;
	BlockMeanAccumulator acc(layout(false, false), opt);
	addTenHzRamp(acc, 400000, 1.0);
	BlockMeanInfo info;
	const FogSeries s = acc.finish(info);
	EXPECT_EQ(info.doublings, 4);
	EXPECT_NEAR(info.block_s, 16.0, 1e-9);
	EXPECT_EQ(s.size(), 2500u);
	for (std::size_t j = 0; j < s.size(); j++) ASSERT_NEAR(s.time_s[j], 0.1 * (160.0 * static_cast<double>(j) + 79.5), 1e-6) << j;
}

TEST(BlockMeanReader, RowsAtTheirFirstSampleStayOnTheLogsGrid)
{
	BlockMeanOptions opt;
	opt.row_time = BlockMeanOptions::RowTime::FirstSample;
	BlockMeanAccumulator acc(layout(false, false), opt);
	addTenHzRamp(acc, 1000, 0.0);
	BlockMeanInfo info;
	const FogSeries s = acc.finish(info);
	ASSERT_EQ(s.size(), 100u);
	for (std::size_t j = 0; j < s.size(); j++)
	{
		EXPECT_DOUBLE_EQ(s.time_s[j], 0.1 * static_cast<double>(10 * j)) << j;  // sample 10 j
		EXPECT_NEAR(s.temp_C[0][j], s.time_s[j] + 0.45, 1e-9) << j;  // the mean lags by half a block
	}
}
