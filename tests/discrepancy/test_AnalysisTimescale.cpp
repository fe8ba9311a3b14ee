/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The analysis timescale (AnalysisTimescale.h): the white corner against the closed form of the
 * Allan variance of white noise plus a rate random walk, and block means that never mix power
 * states nor bridge a gap. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/AnalysisTimescale.h>

#include <cmath>
#include <random>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

TEST(AnalysisTimescale, WhiteCornerOfWhitePlusRandomWalk)
{
	// AVAR = s^2 / tau + q^2 tau / 3 reaches twice the white line at tau = sqrt(3) s / q:
	// 173 s for s = 1, q = 0.01 per 1 s step, i.e. the 256 s octave (128 s: 1.55 x; 256 s: 3.2 x)
	std::mt19937_64 rng(7);
	std::normal_distribution<double> g(0.0, 1.0);
	std::vector<double> white(40000), walk(40000);
	double w = 0;
	for (std::size_t k = 0; k < white.size(); ++k)
	{
		w += 0.01 * g(rng);
		white[k] = g(rng);
		walk[k] = white[k] + w;
	}
	const double corner = whiteNoiseCorner_s(walk, 1.0);
	EXPECT_GE(corner, 128.0);
	EXPECT_LE(corner, 512.0);
	const double none = whiteNoiseCorner_s(white, 1.0);  // white to the longest tau (or nearly)
	EXPECT_TRUE(std::isnan(none) || none >= 1024.0) << none;
	EXPECT_TRUE(std::isnan(whiteNoiseCorner_s({1.0, 2.0}, 1.0)));  // too short to say
}

TEST(AnalysisTimescale, BlockMeansNeverMixPowerStatesNorBridgeGaps)
{
	FogSeries run;
	run.thermistors = {{"T", CoilSide::Other, 0.0}};
	run.temp_C.assign(1, {});
	run.power.clear();
	for (int k = 0; k < 100; ++k)
	{
		const double t = k < 70 ? k : k + 30;  // a 31 s gap before row 70
		run.time_s.push_back(t);
		const bool on = !(k >= 40 && k < 50);
		run.rate_dph[2].push_back(on ? double(k) : NAN);
		run.temp_C[0].push_back(k % 3 == 0 ? NAN : double(k));
		run.power.push_back(on ? 1.0 : 0.0);
	}
	const auto b = blockMeansOfRows(run, 10.0);
	// blocks: 0-9, 10-19, 20-29, 30-39 | off 40-49 | 50-59, 60-69 | gap | 70-79, 80-89, 90-99
	ASSERT_EQ(b.size(), 10u);
	EXPECT_NEAR(b.time_s[0], 4.5, 1e-12);
	EXPECT_NEAR(b.rate_dph[2][0], 4.5, 1e-12);
	EXPECT_EQ(b.power[4], 0.0);
	EXPECT_TRUE(std::isnan(b.rate_dph[2][4]));
	EXPECT_NEAR(b.time_s[7], 104.5, 1e-12);  // rows 70..79 after the gap
	// the thermistor over its finite readings only: rows 1, 2, 4, 5, 7, 8 of the first block
	EXPECT_NEAR(b.temp_C[0][0], (1 + 2 + 4 + 5 + 7 + 8) / 6.0, 1e-12);
	EXPECT_EQ(blockMeansOfRows(run, 1.5).size(), run.size());  // K = 1: unchanged
}
