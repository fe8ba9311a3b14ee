/* Tests of mrpt_fog::allanDeviation against the NBS-14 reference values (design/PHYSICS.md) and
 * closed forms; of resampleUniform on irregular records. */
#include <gtest/gtest.h>
#include <mrpt_fog/metrics/AllanDeviation.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace mrpt_fog;

namespace
{
const std::vector<double> kNbs14 = {892, 809, 823, 798, 671, 644, 883, 903, 677};
}

// NBS-14 reference values: ADEV(tau=1) = 91.22945, ADEV(tau=2) = 115.8082 (non-overlapping),
// overlapping ADEV(tau=2) = 85.95287 (published to 7 significant digits).
TEST(AllanDeviation, Nbs14NonOverlapping)
{
	const auto c = allanDeviation(kNbs14, 1.0, {1, 2}, AllanKind::NonOverlapping);
	ASSERT_EQ(c.size(), 2u);
	EXPECT_NEAR(c[0].adev, 91.22945, 5e-5);
	EXPECT_NEAR(c[1].adev, 115.8082, 5e-4);
	EXPECT_DOUBLE_EQ(c[0].tau_s, 1.0);
	EXPECT_DOUBLE_EQ(c[1].tau_s, 2.0);
}

TEST(AllanDeviation, Nbs14Overlapping)
{
	const auto c = allanDeviation(kNbs14, 1.0, {1, 2}, AllanKind::Overlapping);
	ASSERT_EQ(c.size(), 2u);
	EXPECT_NEAR(c[0].adev, 91.22945, 5e-5);  // at m = 1 both estimators are the same
	EXPECT_NEAR(c[1].adev, 85.95287, 5e-5);
}

// A constant offset does not change the deviation (large offset: checks the numerics).
TEST(AllanDeviation, Nbs14WithLargeOffset)
{
	std::vector<double> y = kNbs14;
	for (double& v : y) v += 1e9;
	const auto c = allanDeviation(y, 1.0, {1, 2}, AllanKind::Overlapping);
	EXPECT_NEAR(c[0].adev, 91.22945, 5e-5);
	EXPECT_NEAR(c[1].adev, 85.95287, 5e-5);
}

// A linear ramp y = R t has ADEV = R tau / sqrt(2) exactly (IEEE 952 rate ramp R^2 tau^2 / 2).
TEST(AllanDeviation, RampClosedForm)
{
	const double R = 0.02, tau0 = 0.5;
	std::vector<double> y;
	for (int k = 0; k < 1024; k++) y.push_back(R * k * tau0);
	for (auto kind : {AllanKind::NonOverlapping, AllanKind::Overlapping})
		for (const auto& p : allanDeviation(y, tau0, kind)) EXPECT_NEAR(p.adev, R * p.tau_s / std::sqrt(2.0), 1e-9);
}

// White noise: ADEV(tau) = sigma / sqrt(m). At m = 1 with N = 65536 samples the relative standard
// error is 1/sqrt(2 (N-1)) = 0.28 %; at m = 64 (1024 clusters, overlapping estimator, about
// 1.5x more degrees of freedom than the 1023 of the non-overlapping one) it is below 2.2 %. The
// bounds are 1.5 % and 8 % (fixed seed).
TEST(AllanDeviation, WhiteNoiseSlopeMinusHalf)
{
	std::mt19937_64 rng(42);
	std::normal_distribution<double> g(0.0, 2.0);
	std::vector<double> y(65536);
	for (double& v : y) v = g(rng);
	const auto c = allanDeviation(y, 0.1, {1, 64}, AllanKind::Overlapping);
	ASSERT_EQ(c.size(), 2u);
	EXPECT_NEAR(c[0].adev / 2.0, 1.0, 0.015);
	EXPECT_NEAR(c[1].adev / (2.0 / 8.0), 1.0, 0.08);
	EXPECT_NEAR(c[1].tau_s, 6.4, 1e-12);
	EXPECT_EQ(c[1].clusters, 1024u);
}

TEST(AllanDeviation, OctaveSizesAndSkippedSizes)
{
	EXPECT_EQ(octaveClusterSizes(9), (std::vector<std::size_t>{1, 2, 4}));
	EXPECT_EQ(octaveClusterSizes(100, 10), (std::vector<std::size_t>{1, 2, 4, 8}));
	EXPECT_TRUE(octaveClusterSizes(1).empty());
	// m = 5 does not fit 9 samples twice: skipped.
	EXPECT_EQ(allanDeviation(kNbs14, 1.0, {1, 5}, AllanKind::Overlapping).size(), 1u);
	EXPECT_EQ(allanDeviation(kNbs14, 1.0, {4, 5}, AllanKind::NonOverlapping).size(), 1u);
}

TEST(AllanDeviation, BadInputThrows)
{
	EXPECT_THROW(allanDeviation(kNbs14, 0.0, AllanKind::Overlapping), std::invalid_argument);
	EXPECT_THROW(allanDeviation({1.0}, 1.0, AllanKind::Overlapping), std::invalid_argument);
	EXPECT_THROW(allanDeviation({1.0, NAN, 2.0}, 1.0, AllanKind::Overlapping), std::invalid_argument);
	EXPECT_THROW(allanDeviation(kNbs14, 1.0, {0}, AllanKind::Overlapping), std::invalid_argument);
}

// Irregular timestamps and NaN: a linear function is reproduced exactly by linear interpolation;
// a gap longer than max_gap splits the record and the longest piece is kept.
TEST(AllanDeviation, ResampleUniformIrregularAndGaps)
{
	std::vector<double> t, v;
	std::mt19937_64 rng(3);
	std::uniform_real_distribution<double> jitter(-0.2, 0.2);
	for (int k = 0; k < 200; k++)
	{
		double tk = k + jitter(rng);
		if (k >= 120) tk += 30.0;  // gap of about 30 s after sample 119
		t.push_back(tk);
		v.push_back(k % 11 == 5 ? NAN : 3.0 + 0.5 * tk);
	}
	const UniformRecord r = resampleUniform(t, v, 1.0, 5.0);
	EXPECT_EQ(r.segments, 2u);
	EXPECT_NEAR(r.t0_s, t[0], 1e-12);
	EXPECT_DOUBLE_EQ(r.period_s, 1.0);
	// First piece spans about 119 s -> about 120 samples.
	EXPECT_GE(r.value.size(), 118u);
	EXPECT_LE(r.value.size(), 120u);
	for (std::size_t i = 0; i < r.value.size(); i++) EXPECT_NEAR(r.value[i], 3.0 + 0.5 * (r.t0_s + i), 1e-9);
	EXPECT_THROW(resampleUniform({0, 1}, {1, 2, 3}), std::invalid_argument);
	EXPECT_THROW(resampleUniform({0, 1, 2}, {NAN, 1, NAN}), std::invalid_argument);
	// A period far below the sample spacing would blow the record up 2e6 times: refused.
	EXPECT_THROW(resampleUniform({0, 1, 2}, {1, 2, 3}, 1e-6, 10.0), std::invalid_argument);
}
