/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/RateEstimator.h>

#include <cmath>
#include <limits>
#include <random>

using namespace mrpt_fog;

namespace
{
std::vector<double> irregularTimes(std::size_t n, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(0.5, 1.5);
	std::vector<double> t{0.0};
	while (t.size() < n) t.push_back(t.back() + u(rng));
	return t;
}
}  // namespace

// A straight line is fitted exactly by a local line, whatever the sampling.
TEST(RateEstimator, CausalLineExactOnIrregularTimes)
{
	const auto t = irregularTimes(500, 1);
	std::vector<double> x;
	for (double ti : t) x.push_back(20.0 + 0.0167 * ti);
	const auto r = CausalRateEstimator(60.0).estimate(t, x);
	EXPECT_TRUE(std::isnan(r[0]));  // one sample: no slope
	for (std::size_t k = 1; k < t.size(); k++) EXPECT_NEAR(r[k], 0.0167, 1e-10) << k;
}

// Closed form: the LS slope of x = a t^2 over a symmetric sample set is 2 a t_c, t_c the
// centroid of the window's times -> with 1 s samples and a 60 s window the delay is 29.5 s.
TEST(RateEstimator, CausalQuadraticGivesDerivativeAtWindowCentre)
{
	const double a = 1e-4;
	std::vector<double> t, x;
	for (int k = 0; k < 400; k++)
	{
		t.push_back(k);
		x.push_back(a * k * k);
	}
	const auto r = CausalRateEstimator(60.0).estimate(t, x);
	for (int k = 100; k < 400; k++) EXPECT_NEAR(r[k], 2 * a * (k - 29.5), 1e-10) << k;
}

// Order 2 (delay-compensated): the whole-window and last-half slopes of x = a t^2 + b t
// are 2 a c + b at their centroids c (1 s samples: t - 29.5 and t - 14.5); the line through them
// at t is the derivative at t itself, exactly (closed form, no delay), from one full window on.
TEST(RateEstimator, CausalOrderTwoHasNoDelayOnAQuadratic)
{
	const double a = 1e-4, b = -0.01;
	std::vector<double> t, x;
	for (int k = 0; k < 400; k++)
	{
		t.push_back(k);
		x.push_back(a * k * k + b * k + 7.0);
	}
	const auto r1 = CausalRateEstimator(60.0, 1).estimate(t, x);
	const auto r2 = CausalRateEstimator(60.0, 2).estimate(t, x);
	for (int k = 100; k < 400; k++)
	{
		EXPECT_NEAR(r1[k], 2 * a * (k - 29.5) + b, 1e-10) << k;
		EXPECT_NEAR(r2[k], 2 * a * k + b, 1e-10) << k;
	}
	// a straight line stays exact, whatever the sampling
	const auto ti = irregularTimes(500, 3);
	std::vector<double> line;
	for (double v : ti) line.push_back(20.0 - 0.02 * v);
	const auto rl = CausalRateEstimator(60.0, 2).estimate(ti, line);
	for (std::size_t k = 2; k < ti.size(); k++) EXPECT_NEAR(rl[k], -0.02, 1e-9) << k;
	EXPECT_EQ(makeRateEstimator({RateEstimatorKind::Causal, 60, 2})->settings().describe(), "causal(window_s=60, order=2)");
	EXPECT_THROW(makeRateEstimator({RateEstimatorKind::Causal, 60, 3}), std::invalid_argument);
}

// Savitzky-Golay of order 2 is exact on a quadratic, at the sample itself (no delay), even on
// irregular timestamps and near the ends (truncated windows).
TEST(RateEstimator, SavitzkyGolayExactOnQuadraticIrregular)
{
	const auto t = irregularTimes(300, 2);
	std::vector<double> x;
	for (double ti : t) x.push_back(5 - 0.02 * ti + 3e-4 * ti * ti);
	const auto r = SavitzkyGolayRateEstimator(30.0, 2).estimate(t, x);
	for (std::size_t k = 0; k < t.size(); k++) EXPECT_NEAR(r[k], -0.02 + 6e-4 * t[k], 1e-9) << k;
}

// Quantisation to 0.01 C: the LS slope error is bounded by q/2 * sum|u - ubar| / sum (u - ubar)^2
// = 0.005 * 3/n for n uniform samples (n = 60 here: 2.5e-4 C/s).
TEST(RateEstimator, QuantisedRampWithinQuantisationBound)
{
	std::vector<double> t, x;
	for (int k = 0; k < 2000; k++)
	{
		t.push_back(k);
		x.push_back(std::round((25.0 - k / 60.0) * 100) / 100);
	}
	const auto r = CausalRateEstimator(60.0).estimate(t, x);
	for (int k = 60; k < 2000; k++) EXPECT_NEAR(r[k], -1.0 / 60, 0.005 * 3.0 / 60) << k;
}

// The order-2 (delay-compensated) estimate is 2 x the half-window slope - the whole-window
// slope, so its quantisation error is bounded by 2 x 1.5 q / (W / 2) + 1.5 q / W = 7.5 q / W
// (closed form, RateEstimator.h). With the window windowForQuantum_s gives for q, the bound is
// that of 0.02 degC in 60 s (kQuantumWindowStart_C) for 1/16 degC; 1 degC hits the 1200 s cap and
// keeps its own bound. Ramps of 0.3 and 1 degC/min, 1 s samples, reading noise 0.003 degC before quantising.
TEST(RateEstimator, OrderTwoQuantisationBoundWithQuantumWindow)
{
	const double ref_bound = 7.5 * kQuantumWindowStart_C / 60.0;
	for (const double q : {0.01, 1.0 / 256, 1.0 / 16, 1.0})
		for (const double rate_C_per_min : {0.3, 1.0})
		{
			std::mt19937 rng(7);
			std::normal_distribution<double> noise(0.0, 0.003);
			std::vector<double> t, x;
			for (int k = 0; k < 6000; k++)
			{
				t.push_back(k);
				x.push_back(q * std::round((-10.0 + rate_C_per_min * k / 60.0 + noise(rng)) / q));
			}
			EXPECT_NEAR(readingQuantum_C(x), q, 1e-12) << q;
			const double w = windowForQuantum_s(60.0, q);
			EXPECT_DOUBLE_EQ(w, q <= 0.02 ? 60.0 : std::min(std::round(60.0 * q / 0.02), 1200.0)) << q;
			const auto r = CausalRateEstimator(w, 2).estimate(t, x);
			// the noise adds at most a few sigma of its own (0.003 degC, far below q for q >= 1/16)
			const double bound = 7.5 * (q + 12 * 0.003) / w;  // error per reading <= q / 2 + 6 sigma
			double worst = 0;
			for (std::size_t k = static_cast<std::size_t>(w); k < t.size(); k++)
				worst = std::max(worst, std::abs(r[k] - rate_C_per_min / 60.0));
			EXPECT_LE(worst, bound) << "q " << q << " rate " << rate_C_per_min;
			if (q > 0.02 && q < 1.0) EXPECT_LE(7.5 * q / w, ref_bound * (1 + 1e-2)) << q;  // 1 %: w rounded to whole s
		}
}

// readingQuantum_C: 0 for a constant column, NaN readings skipped, an unquantised noisy column
// gives a change far below any quantum.
TEST(RateEstimator, ReadingQuantumOfColumns)
{
	EXPECT_EQ(readingQuantum_C({}), 0.0);
	EXPECT_EQ(readingQuantum_C({20.0, 20.0, 20.0}), 0.0);
	const double nan = std::numeric_limits<double>::quiet_NaN();
	EXPECT_DOUBLE_EQ(readingQuantum_C({20.0, nan, 20.5, 20.5, nan, 21.5}), 0.5);
	std::mt19937 rng(3);
	std::normal_distribution<double> noise(0.0, 0.003);
	std::vector<double> x;
	for (int k = 0; k < 1000; k++) x.push_back(20.0 + noise(rng));
	EXPECT_LT(readingQuantum_C(x), 1e-4);
	EXPECT_DOUBLE_EQ(windowForQuantum_s(60.0, readingQuantum_C(x)), 60.0);
}

TEST(RateEstimator, DropoutsAndGaps)
{
	std::vector<double> t, x;
	for (int k = 0; k < 100; k++)
	{
		t.push_back(k);
		x.push_back(0.01 * k);
	}
	// gap of 200 s (longer than the 60 s window) then more samples
	for (int k = 0; k < 50; k++)
	{
		t.push_back(300 + k);
		x.push_back(0.01 * (300 + k));
	}
	x[50] = std::numeric_limits<double>::quiet_NaN();
	const auto r = CausalRateEstimator(60.0).estimate(t, x);
	EXPECT_TRUE(std::isnan(r[50]));  // dropout sample: no estimate there
	EXPECT_NEAR(r[51], 0.01, 1e-12);  // the window around the dropout still works
	EXPECT_TRUE(std::isnan(r[100]));  // first sample after the gap: alone in its window
	EXPECT_NEAR(r[101], 0.01, 1e-12);
	const auto s = SavitzkyGolayRateEstimator(20.0, 2).estimate(t, x);
	EXPECT_TRUE(std::isnan(s[50]));
	EXPECT_NEAR(s[100], 0.01, 1e-9);  // one-sided window after the gap
}

// The multi-channel streaming tracker gives exactly the batch numbers per column, and a long
// run (10^6 samples, many rebuilds of the running sums) keeps full accuracy.
TEST(RateEstimator, TrackerMatchesBatchAndDoesNotDrift)
{
	const std::size_t n = 1000000;
	std::vector<double> t(n), x0(n), x1(n);
	for (std::size_t k = 0; k < n; k++)
	{
		t[k] = 0.1 * static_cast<double>(k) + 1e6;
		x0[k] = -40 + 1e-4 * static_cast<double>(k);
		x1[k] = (k % 1000 == 7) ? std::numeric_limits<double>::quiet_NaN() : 3.0 - 2e-5 * static_cast<double>(k);
	}
	const auto r0 = CausalRateEstimator(30.0).estimate(t, x0);
	const auto r1 = CausalRateEstimator(30.0).estimate(t, x1);
	CausalRateTracker tr(2, 30.0);
	for (std::size_t k = 0; k < n; k++)
	{
		const double xs[2] = {x0[k], x1[k]};
		tr.push(t[k], xs);
		if (k == 0) continue;  // one sample: NaN in both
		ASSERT_EQ(tr.rate(0), r0[k]) << k;
		if (!std::isnan(x1[k])) ASSERT_EQ(tr.rate(1), r1[k]) << k;
	}
	EXPECT_NEAR(r0[n - 1], 1e-3, 1e-10);
	EXPECT_NEAR(r1[n - 1], -2e-4, 1e-10);
}

TEST(RateEstimator, BadInputThrows)
{
	EXPECT_THROW(CausalRateEstimator(60).estimate({0, 1, 1}, {1, 2, 3}), std::invalid_argument);
	EXPECT_THROW(CausalRateEstimator(60).estimate({0, 1}, {1}), std::invalid_argument);
	EXPECT_THROW(CausalRateEstimator(0.0), std::invalid_argument);
	EXPECT_THROW(SavitzkyGolayRateEstimator(10, 5), std::invalid_argument);
	EXPECT_THROW(rateEstimatorKindFromString("kalman"), std::invalid_argument);
	EXPECT_EQ(rateEstimatorKindFromString("savgol"), RateEstimatorKind::SavitzkyGolay);
	EXPECT_STREQ(toString(RateEstimatorKind::Causal), "causal");
	EXPECT_THROW(makeRateEstimator({RateEstimatorKind::Causal, 60, 0}), std::invalid_argument);
	CausalRateTracker tr(1, 10);
	const double x = 1;
	tr.push(5, &x);
	EXPECT_THROW(tr.push(5, &x), std::invalid_argument);
	EXPECT_EQ(makeRateEstimator({RateEstimatorKind::SavitzkyGolay, 30, 2})->settings().describe(), "savgol(window_s=30, order=2)");
	EXPECT_FALSE(makeRateEstimator({RateEstimatorKind::SavitzkyGolay, 30, 2})->isCausal());
	EXPECT_TRUE(makeRateEstimator({RateEstimatorKind::Causal, 30, 1})->isCausal());
}
