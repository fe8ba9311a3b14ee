/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/HeatSourceCandidate.h>

#include <cmath>
#include <random>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
// 8 h at 20 s, power off between 3 h and 4 h and between 6 h and 6.5 h.
struct Synthetic
{
	std::vector<double> t, power;
	std::vector<std::vector<double>> r;
	std::vector<ThermistorInfo> info{{"Ti1", CoilSide::Inner, 0}, {"To1", CoilSide::Outer, 0},
									 {"Ti2", CoilSide::Inner, 180}, {"To2", CoilSide::Outer, 180}};
};

/** Residual = amplitude_i x first-order response (tau_true) + AR(1) + white noise (truth built
 * here, independently of powerResponse). */
Synthetic makeResidual(const std::vector<double>& amp_C, double tau_true_s, unsigned seed, double ar_sd = 0.003,
					   double white_sd = 0.004)
{
	Synthetic s;
	std::mt19937 rng(seed);
	std::normal_distribution<double> nd(0.0, 1.0);
	const double dt = 20;
	const int n = static_cast<int>(8 * 3600 / dt) + 1;
	s.r.assign(4, {});
	std::vector<double> ar(4, 0.0), heat(4, 0.0);
	double h = 1.0;  // settled, powered
	for (int k = 0; k < n; ++k)
	{
		const double t = k * dt;
		const bool on = !((t > 3 * 3600 && t <= 4 * 3600) || (t > 6 * 3600 && t <= 6.5 * 3600));
		if (k > 0) h += (1 - std::exp(-dt / tau_true_s)) * ((on ? 1.0 : 0.0) - h);
		s.t.push_back(t);
		s.power.push_back(on ? 1.0 : 0.0);
		for (int i = 0; i < 4; ++i)
		{
			ar[i] = 0.98 * ar[i] + ar_sd * std::sqrt(1 - 0.98 * 0.98) * nd(rng);
			s.r[i].push_back(amp_C[i] * h + ar[i] + white_sd * nd(rng) + 0.05 * i);
		}
	}
	return s;
}
}  // namespace

TEST(HeatSourceCandidate, PowerResponseIsFirstOrderLagOfPower)
{
	const std::vector<double> t{0, 100, 200, 300};
	const std::vector<double> p{1, 0, 0, 1};
	const auto h = powerResponse(t, p, 100.0);
	EXPECT_DOUBLE_EQ(h[0], 1.0);
	EXPECT_NEAR(h[1], std::exp(-1.0), 1e-12);
	EXPECT_NEAR(h[2], std::exp(-2.0), 1e-12);
	EXPECT_NEAR(h[3], std::exp(-3.0) + (1 - std::exp(-1.0)), 1e-12);
}

TEST(HeatSourceCandidate, NamesHiddenHeatSourceAndLocatesIt)
{
	// warmer everywhere, most at To2 (outer, 180 deg)
	const auto s = makeResidual({0.05, 0.08, 0.10, 0.20}, 1200.0, 7);
	const auto r = testHeatSource(s.t, s.power, s.r, s.info);
	ASSERT_TRUE(r.tested);
	EXPECT_TRUE(r.named) << r.sentence;
	EXPECT_TRUE(r.same_sign);
	EXPECT_EQ(r.nearest, "To2");
	EXPECT_NEAR(r.amplitude_C, 0.1075, 0.03);  // mean of the four amplitudes
	EXPECT_LT(r.ci_low_C, 0.1075);
	EXPECT_GT(r.ci_high_C, 0.1075);
	EXPECT_GE(r.tau_s, 600.0);
	EXPECT_LE(r.tau_s, 2400.0);
	EXPECT_GT(r.confidence, 0.99);
	EXPECT_LT(r.p_adjusted, 1e-6);
}

TEST(HeatSourceCandidate, NullGivesNoNamingOnMostSeeds)
{
	int named = 0;
	for (unsigned seed = 1; seed <= 20; ++seed)
	{
		const auto s = makeResidual({0, 0, 0, 0}, 1200.0, seed);
		named += testHeatSource(s.t, s.power, s.r, s.info).named;
	}
	EXPECT_LE(named, 1) << named << "/20 false namings";
}

TEST(HeatSourceCandidate, MixedSignsAreNotAHeatSource)
{
	const auto s = makeResidual({0.3, -0.1, 0.3, -0.1}, 1200.0, 3);
	const auto r = testHeatSource(s.t, s.power, s.r, s.info);
	EXPECT_TRUE(r.significant);
	EXPECT_FALSE(r.same_sign);
	EXPECT_FALSE(r.named);
}

TEST(HeatSourceCandidate, UntestableWithoutPowerChange)
{
	auto s = makeResidual({0.1, 0.1, 0.1, 0.1}, 1200.0, 3);
	std::fill(s.power.begin(), s.power.end(), 1.0);
	const auto r = testHeatSource(s.t, s.power, s.r, s.info);
	EXPECT_FALSE(r.tested);
	EXPECT_FALSE(r.named);
	EXPECT_NE(r.untestable_reason.find("power"), std::string::npos);
	EXPECT_THROW(testHeatSource(s.t, s.power, {s.r[0]}, s.info), std::invalid_argument);
}

TEST(HeatSourceCandidate, ConfirmationUsesFixedTau)
{
	const auto s = makeResidual({0.1, 0.1, 0.1, 0.1}, 600.0, 11);
	const auto c = confirmHeatSource(s.t, s.power, s.r, 600.0, 0.01);
	EXPECT_TRUE(c.tested);
	EXPECT_TRUE(c.confirmed);
	EXPECT_NEAR(c.amplitude_C, 0.1, 0.03);
	const auto n = makeResidual({0, 0, 0, 0}, 600.0, 12);
	EXPECT_FALSE(confirmHeatSource(n.t, n.power, n.r, 600.0, 0.01).confirmed);
}
