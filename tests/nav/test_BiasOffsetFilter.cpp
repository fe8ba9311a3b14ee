/* BiasOffsetFilter against the closed forms of a constant offset in known white noise. */
#include <gtest/gtest.h>
#include <mrpt_fog_nav/BiasOffsetFilter.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

using namespace mrpt_fog::nav;

namespace
{
GyroNoiseModel whiteOnly(double arw_deg_rt_h)
{
	GyroNoiseModel n;
	n.arw_deg_rt_h = arw_deg_rt_h;
	n.bias_instability_dph = 0;
	n.rrw_deg_h_rt_h = 0;
	return n;
}
}  // namespace

// Constant offset, white noise of known variance R per sample, Gaussian prior (m0, P0): the
// posterior after z_1..z_n is P = 1 / (1/P0 + n/R), m = P (m0/P0 + sum z / R), whatever the z.
TEST(BiasOffsetFilter, ConstantOffsetPosteriorIsTheClosedForm)
{
	const double N = 0.002, dt = 0.1, m0 = 0.05, s0 = 0.4;
	const double R = std::pow(60.0 * N / std::sqrt(dt), 2);  // per-sample variance [(deg/h)^2]
	BiasOffsetFilter kf(0.0, m0, s0, whiteOnly(N));
	std::mt19937_64 rng(11);
	std::normal_distribution<double> w(0.0, std::sqrt(R));
	double sum = 0;
	const int n = 1200;
	for (int k = 1; k <= n; k++)
	{
		const double z = 0.3 + w(rng);
		sum += z;
		ASSERT_TRUE(kf.update(k * dt, z, dt));
	}
	const double P = 1.0 / (1.0 / (s0 * s0) + n / R);
	const double m = P * (m0 / (s0 * s0) + sum / R);
	EXPECT_NEAR(kf.offset_sigma_dph(), std::sqrt(P), 1e-12);
	EXPECT_NEAR(kf.offset_dph(), m, 1e-10);
	// and the estimate is where the truth is, within 4 posterior sigmas
	EXPECT_NEAR(kf.offset_dph(), 0.3, 4 * std::sqrt(P));
}

// The measurement noise follows the sample interval: 10 samples of 0.1 s carry the information
// of one of 1 s (white rate noise sigma = 60 N / sqrt(dt)).
TEST(BiasOffsetFilter, InformationFollowsTheIntervalNotTheSampleCount)
{
	BiasOffsetFilter a(0.0, 0.0, 1.0, whiteOnly(0.001)), b(0.0, 0.0, 1.0, whiteOnly(0.001));
	for (int k = 1; k <= 10; k++) a.update(0.1 * k, 0.2, 0.1);
	b.update(1.0, 0.2, 1.0);
	EXPECT_NEAR(a.offset_sigma_dph(), b.offset_sigma_dph(), 1e-12);
	EXPECT_NEAR(a.offset_dph(), b.offset_dph(), 1e-12);
}

// With a bias instability B, a short standstill cannot tell the offset from B: the offset's
// posterior variance stays >= about B^2 even with noise-free samples, while their sum c + g is
// pinned; the g part of the correction decays with the correlation time afterwards.
TEST(BiasOffsetFilter, BiasInstabilityIsNotTakenForTheOffset)
{
	GyroNoiseModel n;
	n.arw_deg_rt_h = 1e-6;  // practically noise free
	n.bias_instability_dph = 0.01;
	n.bias_corr_time_s = 300;
	n.rrw_deg_h_rt_h = 0;
	BiasOffsetFilter kf(0.0, 0.0, 1.0, n);
	for (int k = 1; k <= 600; k++) kf.update(0.1 * k, 0.3, 0.1);  // 60 s reading 0.3 deg/h
	EXPECT_NEAR(kf.correctionAt_dph(60.0), 0.3, 1e-3);  // c + g = what was read (B = 0.01)
	EXPECT_GT(kf.offset_sigma_dph(), 0.5 * n.bias_instability_dph);
	// g decays: long after, the correction is c alone
	EXPECT_NEAR(kf.correctionAt_dph(60.0 + 1e5), kf.offset_dph(), 1e-12);
	// no measurement: the instability's variance is stationary, B^2
	BiasOffsetFilter idle(0.0, 0.0, 1.0, n);
	idle.predictTo(1e4);
	EXPECT_NEAR(idle.covariance()(1, 1), n.bias_instability_dph * n.bias_instability_dph, 1e-15);
}

// Rate random walk K: the offset's variance grows by K^2 t (t in hours) between standstills.
TEST(BiasOffsetFilter, RateRandomWalkGrowsTheOffsetVariance)
{
	GyroNoiseModel n = whiteOnly(0.001);
	n.rrw_deg_h_rt_h = 0.01;
	BiasOffsetFilter kf(0.0, 0.0, 0.1, n);
	kf.predictTo(7200.0);
	EXPECT_NEAR(kf.covariance()(0, 0), 0.01 + 0.01 * 0.01 * 2.0, 1e-15);
}

TEST(BiasOffsetFilter, BadInputIsRefusedOrIgnored)
{
	EXPECT_THROW(BiasOffsetFilter(0.0, 0.0, -1.0, {}), std::invalid_argument);
	EXPECT_THROW(BiasOffsetFilter(0.0, NAN, 1.0, {}), std::invalid_argument);
	GyroNoiseModel bad;
	bad.bias_corr_time_s = 0;
	EXPECT_THROW(BiasOffsetFilter(0.0, 0.0, 1.0, bad), std::invalid_argument);
	BiasOffsetFilter kf(0.0, 0.0, 1.0, {});
	EXPECT_FALSE(kf.update(1.0, NAN, 0.1));
	EXPECT_FALSE(kf.update(1.0, 0.1, 0.0));
	EXPECT_EQ(kf.offset_dph(), 0.0);
}
