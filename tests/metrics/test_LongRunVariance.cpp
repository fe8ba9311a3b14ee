/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// The long-run variance estimators against values computed by hand from their definitions.
#include <mrpt_fog/metrics/LongRunVariance.h>  // internal

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace mrpt_fog;

// 1..9: b = round(sqrt(9)) = 3, block means 2, 5, 8 around 5: var = (9 + 0 + 9) / 2 = 9, x b = 27.
TEST(LongRunVariance, BatchMeansOfOneSeriesByHand)
{
	const std::vector<double> x = {1, 2, 3, 4, 5, 6, 7, 8, 9};
	EXPECT_DOUBLE_EQ(batchMeansLongRunVariance({x}, BatchPooling::PooledBlocks), 27.0);
	EXPECT_DOUBLE_EQ(batchMeansLongRunVariance({x}, BatchPooling::MeanOfSeries), 27.0);
}

// Two series 1..9 and 11..19 (offset 10):
//  pooled: b = round(sqrt(18 / 2)) = 3; means 2 5 8 12 15 18 around 10: squares 64 25 4 4 25 64
//    = 186, / 5 = 37.2, x 3 = 111.6 (the offset between the series counts);
//  per series: 27 each, mean 27 (it does not).
TEST(LongRunVariance, PoolingOfSeveralSeriesByHand)
{
	std::vector<double> a, b;
	for (int i = 1; i <= 9; i++)
	{
		a.push_back(i);
		b.push_back(i + 10);
	}
	EXPECT_NEAR(batchMeansLongRunVariance({a, b}, BatchPooling::PooledBlocks), 111.6, 1e-12);
	EXPECT_DOUBLE_EQ(batchMeansLongRunVariance({a, b}, BatchPooling::MeanOfSeries), 27.0);
}

TEST(LongRunVariance, TooFewBlocksGiveNaN)
{
	EXPECT_TRUE(std::isnan(batchMeansLongRunVariance({{1, 2, 3}}, BatchPooling::PooledBlocks)));  // < 8 entries
	EXPECT_TRUE(std::isnan(batchMeansLongRunVariance({{1, 2, 3}}, BatchPooling::MeanOfSeries)));  // b 2: 1 block
	EXPECT_TRUE(std::isnan(batchMeansLongRunVariance({}, BatchPooling::MeanOfSeries)));
}

// Bartlett factor with L = 1 lag, 1 + 2 (1/2) rho_1, rho_1 = sum c_k c_{k+1} / sum c_k^2:
//  1, -1, 1, -1 (mean 0): rho_1 = -3/4 -> 0.25, clamped to 1;
//  1, 1, -1, -1: rho_1 = (1 - 1 + 1) / 4 = 1/4 -> 1.25; a constant: 1.
TEST(LongRunVariance, BartlettFactorByHand)
{
	Eigen::VectorXd alt(4), pairs(4);
	alt << 1, -1, 1, -1;
	pairs << 1, 1, -1, -1;
	EXPECT_DOUBLE_EQ(longRunVarianceFactor(alt, 1), 1.0);
	EXPECT_DOUBLE_EQ(longRunVarianceFactor(pairs, 1), 1.25);
	EXPECT_DOUBLE_EQ(longRunVarianceFactor(Eigen::VectorXd::Constant(5, 2.0), 3), 1.0);
}
