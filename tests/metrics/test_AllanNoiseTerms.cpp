/* Tests of mrpt_fog::allanNoiseTerms: IEEE 952 terms recovered from synthetic noise of known
 * parameters and from a closed-form Allan curve. */
#include <gtest/gtest.h>
#include <mrpt_fog/metrics/AllanNoiseTerms.h>

#include "FlickerNoise.h"

#include <cmath>
#include <random>

using namespace mrpt_fog;

// White rate noise of sigma_w deg/h at fs Hz has ARW N = sigma_w / (60 sqrt(fs)) deg/sqrt(h)
// (PHYSICS.md). N = 131072 samples: the fit is dominated by the small-tau points whose relative
// standard error is about 1/sqrt(2 clusters) = 0.2-0.3 %; the 1.5 % bound is > 5 of them.
TEST(AllanNoiseTerms, WhiteNoiseGivesKnownArw)
{
	const double fs = 10.0, arw_true = 0.002;  // deg/sqrt(h)
	const double sigma_w = arw_true * 60.0 * std::sqrt(fs);
	std::mt19937_64 rng(952);
	std::normal_distribution<double> g(0.0, sigma_w);
	std::vector<double> y(131072);
	for (double& v : y) v = 9.67 + g(rng);
	const auto curve = allanDeviation(y, 1.0 / fs, AllanKind::Overlapping);
	const AllanNoiseTerms t = allanNoiseTerms(curve);
	ASSERT_TRUE(t.arw.identified());
	EXPECT_NEAR(t.arw_dpsh / arw_true, 1.0, 0.015);
	EXPECT_LE(t.arw.tau_min_s, 0.1 + 1e-12);  // the region starts at the first point
	EXPECT_FALSE(t.rrw.identified());
	EXPECT_FALSE(t.quantization.identified());
	EXPECT_FALSE(t.flat.identified());
	EXPECT_TRUE(std::isnan(t.bias_instability_dph));
}

// Rate random walk: y_k = y_{k-1} + e_k, e ~ N(0, q). Discrete closed form:
// AVAR(m) = q (2 m^2 + 1) / (6 m) -> q m / 3 = K^2 tau / 3 with K = sqrt(q / tau0) [deg/h/sqrt(s)],
// i.e. K = 60 sqrt(q / tau0) deg/h/sqrt(h). The fitted region starts at m = 2, where the discrete
// form is 6 % above the asymptote in deviation (1.6 % at m = 4, 0.4 % at m = 8); weighted by the
// clusters this biases K by about +3.3 %. Over 20 other seeds the recovered K / K_true was
// 1.033 +- 0.0043 (1 sd). The 6 % bound is the bias plus more than 5 sd.
TEST(AllanNoiseTerms, RandomWalkGivesKnownK)
{
	const double tau0 = 1.0, q_sigma = 0.001;  // deg/h per sample step
	const double k_true = 60.0 * q_sigma / std::sqrt(tau0);  // deg/h/sqrt(h)
	std::mt19937_64 rng(1997);
	std::normal_distribution<double> g(0.0, q_sigma);
	std::vector<double> y(131072);
	double r = 0;
	for (double& v : y)
	{
		r += g(rng);
		v = r;
	}
	const auto curve = allanDeviation(y, tau0, AllanKind::Overlapping);
	const AllanNoiseTerms t = allanNoiseTerms(curve);
	ASSERT_TRUE(t.rrw.identified());
	EXPECT_NEAR(t.rrw_dphsh / k_true, 1.0, 0.06);
	EXPECT_FALSE(t.arw.identified());
	EXPECT_FALSE(t.quantization.identified());
	EXPECT_TRUE(std::isnan(t.bias_instability_dph));
}

// White noise plus rate random walk, no flicker: the curve has a minimum between its -1/2 and
// +1/2 slopes (where the local slope passes through 0) but no flat region, so B is not
// reported. Before the joint fit this read B = 0.016 deg/h on 2 of 4 such records. Five seeds,
// all must give NaN; ARW must still be read (within 1.5 %, as above).
TEST(AllanNoiseTerms, WhitePlusRandomWalkHasNoBiasInstability)
{
	const double fs = 10.0, arw_true = 0.002, q_sigma = 2e-4;  // deg/sqrt(h), deg/h per step
	const double sigma_w = arw_true * 60.0 * std::sqrt(fs);
	for (unsigned seed = 1; seed <= 5; seed++)
	{
		std::mt19937_64 rng(seed);
		std::normal_distribution<double> gw(0.0, sigma_w), gq(0.0, q_sigma);
		std::vector<double> y(131072);
		double r = 0;
		for (double& v : y)
		{
			r += gq(rng);
			v = gw(rng) + r;
		}
		const AllanNoiseTerms t = allanNoiseTerms(allanDeviation(y, 1.0 / fs, AllanKind::Overlapping));
		EXPECT_TRUE(std::isnan(t.bias_instability_dph)) << "seed " << seed << ": B = " << t.bias_instability_dph;
		EXPECT_NEAR(t.arw_dpsh / arw_true, 1.0, 0.015) << "seed " << seed;
	}
}

// Flicker rate noise of known B (FlickerNoise.h: B is the innovation sigma by the PSD
// definition, IEEE 952 S(f) = B^2 / (2 pi f); block means of 8 fine samples). IEEE 952 value: flat AVAR = (2 ln2 / pi) B^2.
// Target: within 5 %. Over 20 other seeds (numpy prototype of the same generator and
// estimator) B / B_true = 0.998 +- 0.006 (1 sd); the 5 % bound is > 8 sd.
TEST(AllanNoiseTerms, FlickerGivesKnownB)
{
	const double fs = 10.0, b_true = 0.01;  // deg/h
	std::mt19937_64 rng(1952);
	const std::vector<double> y = fog_test::flickerRate(65536, b_true, 8, rng);
	const AllanNoiseTerms t = allanNoiseTerms(allanDeviation(y, 1.0 / fs, AllanKind::Overlapping));
	ASSERT_TRUE(t.flat.identified());
	EXPECT_NEAR(t.bias_instability_dph / b_true, 1.0, 0.05);
	EXPECT_FALSE(t.arw.identified());
	EXPECT_FALSE(t.quantization.identified());
}

// White noise (N = 0.002 deg/sqrt(h)) plus flicker (B = 0.05 deg/h, crossing the ARW line at
// tau = (N / 0.664 B)^2 = 13 s): both read. One record's B scatters by about 3 % (1 sd over 20
// seeds in the prototype), so the target (within 5 %) is checked on the mean of 8 seeds (sd of
// the mean ~1 %), and every seed must identify the flat region. (Block means of 4 fine samples:
// the generator's +2.5 % excess at tau = 0.1 s lies where ARW dominates.)
TEST(AllanNoiseTerms, WhitePlusFlickerGivesKnownBAndN)
{
	const double fs = 10.0, arw_true = 0.002, b_true = 0.05;
	const double sigma_w = arw_true * 60.0 * std::sqrt(fs);
	double sum_b = 0;
	const int seeds = 8;
	for (int seed = 0; seed < seeds; seed++)
	{
		std::mt19937_64 rng(100 + seed);
		std::vector<double> y = fog_test::flickerRate(65536, b_true, 4, rng);
		std::normal_distribution<double> g(0.0, sigma_w);
		for (double& v : y) v += g(rng);
		const AllanNoiseTerms t = allanNoiseTerms(allanDeviation(y, 1.0 / fs, AllanKind::Overlapping));
		ASSERT_TRUE(t.flat.identified()) << "seed " << seed;
		EXPECT_NEAR(t.arw_dpsh / arw_true, 1.0, 0.03) << "seed " << seed;
		sum_b += t.bias_instability_dph;
	}
	EXPECT_NEAR(sum_b / seeds / b_true, 1.0, 0.05);
}

// A closed-form curve with all four terms in separate decades of tau:
// AVAR = 3 Q^2/tau^2 + N^2/tau + (0.664 B)^2 + K^2 tau/3 (tau in s, rates in deg/h).
// Each region still contains a little of its neighbours; the terms are placed so that inside the
// fitted regions the neighbours add less than about 20 % to the variance (10 % to the deviation),
// which is the bound used for the line-read terms. (Measured: Q +8.6 %, N +3.4 %, K +6.6 %: every
// neighbour adds variance, so the read values are biased high.) B comes from the joint fit of all
// four terms, exact on this exact curve (was +3.9 % from a line through the flat points).
TEST(AllanNoiseTerms, ClosedFormCurveAllFourTerms)
{
	const double Q_as = 0.001;  // arcsec (deg/h * s); crosses the ARW line at 3 Q^2/N^2 = 8e-4 s
	const double N_s = 0.06;  // deg/h * sqrt(s)  (0.001 deg/sqrt(h))
	const double B = 0.005;  // deg/h; crosses ARW at 326 s and RRW at 3.3e7 s
	const double K_s = 1e-6;  // deg/h / sqrt(s)
	std::vector<AllanPoint> c;
	for (double tau = 1e-4; tau < 1e9; tau *= 2)
	{
		AllanPoint p;
		p.tau_s = tau;
		const double avar = 3 * Q_as * Q_as / (tau * tau) + N_s * N_s / tau +
							std::pow(kBiasInstabilityFactor * B, 2) + K_s * K_s * tau / 3;
		p.adev = std::sqrt(avar);
		p.clusters = 1000000;
		c.push_back(p);
	}
	const AllanNoiseTerms t = allanNoiseTerms(c);
	EXPECT_NEAR(t.quantization_arcsec / Q_as, 1.0, 0.10);
	EXPECT_NEAR(t.arw_dpsh / (N_s / 60.0), 1.0, 0.10);
	EXPECT_NEAR(t.bias_instability_dph / B, 1.0, 1e-6);
	EXPECT_NEAR(t.rrw_dphsh / (K_s * 60.0), 1.0, 0.10);
	// B is the flat level / 0.664, not the curve minimum.
	double mn = 1e300;
	for (const auto& p : c) mn = std::min(mn, p.adev);
	EXPECT_GT(t.bias_instability_dph, 1.3 * mn);
}

TEST(AllanNoiseTerms, EmptyCurveGivesNaN)
{
	const AllanNoiseTerms t = allanNoiseTerms({});
	EXPECT_TRUE(std::isnan(t.arw_dpsh));
	EXPECT_TRUE(std::isnan(t.bias_instability_dph));
	EXPECT_TRUE(std::isnan(t.rrw_dphsh));
	EXPECT_TRUE(std::isnan(t.quantization_arcsec));
}

// A -1 slope at LONG tau (e.g. slow variations removed by a fit) after an ARW part is not
// quantisation: Q is only read at the shortest taus. Curve: N^2/tau for tau < 100 s, then
// falling as 1/tau (continuous at 100 s).
TEST(AllanNoiseTerms, LongTauMinusOneSlopeIsNotQuantization)
{
	const double N_s = 0.06;  // deg/h * sqrt(s)
	std::vector<AllanPoint> c;
	for (double tau = 1; tau < 1e5; tau *= 2)
	{
		AllanPoint p;
		p.tau_s = tau;
		p.adev = tau < 100 ? N_s / std::sqrt(tau) : N_s / std::sqrt(100.0) * (100.0 / tau);
		p.clusters = 1000000;
		c.push_back(p);
	}
	const AllanNoiseTerms t = allanNoiseTerms(c);
	EXPECT_FALSE(t.quantization.identified());
	ASSERT_TRUE(t.arw.identified());
	EXPECT_NEAR(t.arw_dpsh / (N_s / 60.0), 1.0, 1e-9);  // exact: the -1/2 part is pure
	EXPECT_LE(t.arw.tau_max_s, 64.0);
}
