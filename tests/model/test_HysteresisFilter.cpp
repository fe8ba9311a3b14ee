/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// The hysteresis operators (HysteresisFilter.h) against their closed forms on triangle waves and
// ramps, with reading noise and a quantisation staircase below the operator's width.
#include <gtest/gtest.h>
#include <mrpt_fog/model/HysteresisFilter.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

using namespace mrpt_fog;

namespace
{
/** Triangle wave between lo and hi starting at lo going up, period 2 (hi - lo) / slope. */
double triangle(double lo, double hi, double slope, double t)
{
	const double half = (hi - lo) / slope, ph = std::fmod(t, 2 * half);
	return ph <= half ? lo + slope * ph : hi - slope * (ph - half);
}
}  // namespace

TEST(HysteresisFilter, PlayOnATriangleWaveIsItsClosedForm)
{
	// x: triangle 10..20 C (amplitude 5 C > w); play of half-width w from the warm start at 10 C:
	// first rise h = min(1, (x - 10) / w); then falling h = max(-1, 1 - (20 - x) / w) and rising
	// h = min(1, -1 + (x - 10) / w). A second channel reads the other thermistor (x = -x: h = -h).
	const double w = 2.0, lo = 10, hi = 20, slope = 0.01;  // 0.6 C/min
	HysteresisFilterBank bank({{0, HysteresisOperator::Play, w}, {1, HysteresisOperator::Play, w}});
	const double period = 2 * (hi - lo) / slope;
	for (double t = 0; t <= 3.5 * period; t += 5.0)  // samples on the turning points
	{
		const double x[2] = {triangle(lo, hi, slope, t), -triangle(lo, hi, slope, t)};
		bank.push(x);
		const bool rising = std::fmod(t, period) <= period / 2;
		double want;
		if (t <= period / 2)
			want = std::min(1.0, (x[0] - lo) / w);
		else
			want = rising ? std::min(1.0, -1.0 + (x[0] - lo) / w) : std::max(-1.0, 1.0 - (hi - x[0]) / w);
		ASSERT_NEAR(bank.value(0), want, 1e-12) << t;
		ASSERT_NEAR(bank.value(1), -want, 1e-12) << t;
		ASSERT_LE(std::fabs(bank.value(0)), 1.0);
	}
}

TEST(HysteresisFilter, NoiseBelowThePlayWidthNeverFlipsIt)
{
	// heated from 10 to 20 C (h = 1), then a soak whose readings carry noise of +-0.45 w and a
	// 0.01 C quantum: h stays in [1 - 0.9 - quantum / w, 1] (never reaches the cooling branch)
	const double w = 1.0;
	HysteresisFilterBank bank({{0, HysteresisOperator::Play, w}});
	for (double x = 10; x <= 20; x += 0.05) bank.push(&x);
	EXPECT_DOUBLE_EQ(bank.value(0), 1.0);
	std::mt19937 rng(5);
	std::uniform_real_distribution<double> noise(-0.45 * w, 0.45 * w);
	double lowest = 1;
	for (int k = 0; k < 20000; k++)
	{
		const double x = std::round((20.0 - 0.45 * w + noise(rng)) * 100.0) / 100.0;
		bank.push(&x);
		lowest = std::min(lowest, bank.value(0));
	}
	EXPECT_GE(lowest, 1.0 - 0.9 - 0.01 / w - 1e-12);
	EXPECT_GT(lowest, 0.0);
}

TEST(HysteresisFilter, BranchFollowsItsClosedFormBehindTheDeadBand)
{
	// ramp up from the warm start x0: the dead band's position moves once x - x0 > d, so
	// h = 1 - exp(-(x - x0 - d) / span); after the top xt it reverses once x < xt - 2 d:
	// h = -1 + (h_top + 1) exp(-(xt - 2 d - x) / span)
	const double span = 5.0, d = kHysteresisDeadBand_C, x0 = 0.0, xt = 8.0;
	HysteresisFilterBank bank({{0, HysteresisOperator::Branch, span}});
	for (double x = x0; x <= xt + 1e-9; x += 0.01)
	{
		bank.push(&x);
		const double want = x - x0 <= d ? 0.0 : 1.0 - std::exp(-(x - x0 - d) / span);
		ASSERT_NEAR(bank.value(0), want, 1e-9) << x;
	}
	const double h_top = bank.value(0);
	for (double x = xt; x >= -5.0; x -= 0.01)
	{
		bank.push(&x);
		const double want = x >= xt - 2 * d ? h_top : -1.0 + (h_top + 1.0) * std::exp(-(xt - 2 * d - x) / span);
		ASSERT_NEAR(bank.value(0), want, 1e-9) << x;
	}
}

TEST(HysteresisFilter, BranchDoesNotChatterOnAQuantisedNoisySoak)
{
	// a reading noise of +-0.04 C on a 0.01 C quantum (below the dead band of 0.05 C): the raw
	// reading's change flips sign on most samples; the branch keeps the value it had
	HysteresisFilterBank bank({{0, HysteresisOperator::Branch, 2.0}});
	for (double x = 0; x <= 6.0 + 1e-9; x += 0.01) bank.push(&x);
	const double h = bank.value(0);
	std::mt19937 rng(9);
	std::uniform_real_distribution<double> noise(-0.04, 0.04);
	int flips = 0, last_sign = 0;
	double prev = 6.0;
	for (int k = 0; k < 20000; k++)
	{
		const double x = std::round((6.0 - kHysteresisDeadBand_C + noise(rng)) * 100.0) / 100.0;
		if (x != prev)
		{
			const int sign = x > prev ? 1 : -1;
			flips += last_sign != 0 && sign != last_sign;
			last_sign = sign;
		}
		prev = x;
		bank.push(&x);
		ASSERT_EQ(bank.value(0), h) << k;
	}
	EXPECT_GT(flips, 1000);  // the reading does reverse, often
}

TEST(HysteresisFilter, WarmStartDropoutAndReset)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	HysteresisFilterBank bank({{0, HysteresisOperator::Play, 1.0}, {0, HysteresisOperator::Branch, 1.0}});
	bank.push(&nan);  // no reading yet: no output, no state
	EXPECT_TRUE(std::isnan(bank.value(0)) && std::isnan(bank.value(1)));
	double x = 30.0;
	bank.push(&x);  // warm start: h = 0 at the first valid reading
	EXPECT_EQ(bank.value(0), 0.0);
	EXPECT_EQ(bank.value(1), 0.0);
	x = 30.5;
	bank.push(&x);
	EXPECT_DOUBLE_EQ(bank.value(0), 0.5);
	const double b = bank.value(1);
	bank.push(&nan);  // dropout: NaN out, state held
	EXPECT_TRUE(std::isnan(bank.value(0)) && std::isnan(bank.value(1)));
	x = 30.5;
	bank.push(&x);
	EXPECT_DOUBLE_EQ(bank.value(0), 0.5);
	EXPECT_EQ(bank.value(1), b);
	x = 33.0;  // across a gap: one step of the operator (the play depends on the path's extremes only)
	bank.push(&x);
	EXPECT_DOUBLE_EQ(bank.value(0), 1.0);
	bank.reset();
	x = 12.0;
	bank.push(&x);
	EXPECT_EQ(bank.value(0), 0.0);
	EXPECT_THROW(HysteresisFilterBank({{0, HysteresisOperator::Play, 0.0}}), std::invalid_argument);
	EXPECT_THROW(HysteresisFilterBank({{0, HysteresisOperator::Branch, -1.0}}), std::invalid_argument);
	EXPECT_THROW(HysteresisFilterBank({{0, HysteresisOperator::Play, std::nan("")}}), std::invalid_argument);
}
