/* Tests of mrpt_fog::biasStats (seed's 100 s bias stability, range, raw peak-to-peak) against
 * closed forms and white noise of known sigma. */
#include <gtest/gtest.h>
#include <mrpt_fog/metrics/BiasMetrics.h>

#include <cmath>
#include <random>
#include <stdexcept>

using namespace mrpt_fog;

namespace
{
/** Sample standard deviation (N-1) written out independently of the code under test. */
double stdN1(const std::vector<double>& v)
{
	double m = 0;
	for (double x : v) m += x;
	m /= v.size();
	double s = 0;
	for (double x : v) s += (x - m) * (x - m);
	return std::sqrt(s / (v.size() - 1));
}
}  // namespace

// A step of 1 deg/h halfway through 1000 s at 1 Hz: ten 100 s windows, five at 0 and five at 1.
// Closed form: std (N-1) = sqrt(10 * 0.25 / 9), range = 1, raw peak-to-peak = 1.
TEST(BiasMetrics, StepClosedForm)
{
	std::vector<double> t, r;
	for (int k = 0; k < 1000; k++)
	{
		t.push_back(k);
		r.push_back(k < 500 ? 0.0 : 1.0);
	}
	const BiasStats s = biasStats(t, r, 100.0);
	EXPECT_EQ(s.window_count, 10u);
	EXPECT_EQ(s.empty_window_count, 0u);
	EXPECT_EQ(s.samples_used, 1000u);
	EXPECT_NEAR(s.dropped_tail_s, 0.0, 1e-9);
	EXPECT_NEAR(s.stability_dph, std::sqrt(2.5 / 9.0), 1e-12);
	EXPECT_NEAR(s.range_dph, 1.0, 1e-12);
	EXPECT_NEAR(s.raw_peak_to_peak_dph, 1.0, 1e-12);
	EXPECT_NEAR(s.mean_dph, 0.5, 1e-12);
	ASSERT_EQ(s.window_center_s.size(), 10u);
	EXPECT_NEAR(s.window_center_s[0], 50.0, 1e-12);
	EXPECT_NEAR(s.window_center_s[9], 950.0, 1e-12);
}

// A sine of period 1000 s sampled at 100 Hz over 1000 s: the window averages are the closed-form
// integrals (cos(w a) - cos(w (a + tau))) / (w tau). The sampled mean (left rectangle rule) differs
// from the integral by at most A w h / 2 = 3.2e-5 A, hence the 1e-4 tolerance.
TEST(BiasMetrics, SineWindowAveragesClosedForm)
{
	const double A = 0.3, P = 1000.0, w = 2 * M_PI / P, h = 0.01, tau = 100.0;
	std::vector<double> t, r;
	for (int k = 0; k < 100000; k++)
	{
		t.push_back(k * h);
		r.push_back(A * std::sin(w * k * h));
	}
	const BiasStats s = biasStats(t, r, tau);
	ASSERT_EQ(s.window_count, 10u);
	std::vector<double> expected;
	for (int j = 0; j < 10; j++)
	{
		const double a = j * tau;
		expected.push_back(A * (std::cos(w * a) - std::cos(w * (a + tau))) / (w * tau));
		EXPECT_NEAR(s.window_mean_dph[j], expected.back(), 1e-4 * A);
	}
	double mn = 1e9, mx = -1e9;
	for (double e : expected)
	{
		mn = std::min(mn, e);
		mx = std::max(mx, e);
	}
	EXPECT_NEAR(s.stability_dph, stdN1(expected), 2e-4 * A);
	EXPECT_NEAR(s.range_dph, mx - mn, 2e-4 * A);
	EXPECT_NEAR(s.raw_peak_to_peak_dph, 2 * A, 1e-6);
}

// White noise of sigma 1 deg/h at 1 Hz: each 100 s average has sigma 1/sqrt(100) = 0.1 deg/h.
// With N = 2500 windows the sample std has a relative standard error of 1/sqrt(2 (N-1)) = 1.41 %;
// the 5 % bound is 3.5 standard errors (fixed seed, so the test is deterministic).
TEST(BiasMetrics, WhiteNoiseStabilityIsSigmaOverSqrtN)
{
	std::mt19937_64 rng(20261121);
	std::normal_distribution<double> noise(0.0, 1.0);
	std::vector<double> t, r;
	const int n = 250000;
	for (int k = 0; k < n; k++)
	{
		t.push_back(k);
		r.push_back(9.67 + noise(rng));
	}
	const BiasStats s = biasStats(t, r, 100.0);
	EXPECT_EQ(s.window_count, 2500u);
	EXPECT_NEAR(s.stability_dph / 0.1, 1.0, 0.05);
	// Range of 2500 normal averages: about 2 * 3.4 sigma (expected max of 2500 normals ~3.4).
	EXPECT_GT(s.range_dph, 0.1 * 5.5);
	EXPECT_LT(s.range_dph, 0.1 * 8.5);
	EXPECT_NEAR(s.mean_dph, 9.67, 5 * 1.0 / std::sqrt(n));
}

// Irregular timestamps, NaN samples and a gap covering a whole window: window w holds the value
// w everywhere, window 3 has no sample at all, and the 50 s tail (value 1000) is dropped.
TEST(BiasMetrics, IrregularSamplingGapsNaNAndTail)
{
	std::mt19937_64 rng(7);
	std::uniform_real_distribution<double> jitter(-0.3, 0.3);
	std::vector<double> t, r;
	for (int k = 0; k < 1050; k++)
	{
		const double tk = k + (k == 0 ? 0.0 : jitter(rng));
		const int w = static_cast<int>(std::floor(tk / 100.0));
		if (w == 3) continue;  // gap: no samples in [300, 400)
		t.push_back(tk);
		double v = w >= 10 ? 1000.0 : static_cast<double>(w);
		if (k % 7 == 0 && w < 10) v = NAN;  // dropouts
		r.push_back(v);
	}
	const BiasStats s = biasStats(t, r, 100.0);
	EXPECT_EQ(s.window_count, 9u);
	EXPECT_EQ(s.empty_window_count, 1u);
	EXPECT_NEAR(s.dropped_tail_s, 50.0, 0.7);
	const std::vector<double> expected = {0, 1, 2, 4, 5, 6, 7, 8, 9};
	ASSERT_EQ(s.window_mean_dph.size(), expected.size());
	for (std::size_t i = 0; i < expected.size(); i++) EXPECT_DOUBLE_EQ(s.window_mean_dph[i], expected[i]);
	EXPECT_NEAR(s.stability_dph, stdN1(expected), 1e-12);
	EXPECT_NEAR(s.range_dph, 9.0, 1e-12);
	// The raw peak-to-peak sees the tail (it is over all finite samples).
	EXPECT_NEAR(s.raw_peak_to_peak_dph, 1000.0, 1e-12);
}

// A constant (e.g. vertical Earth rate) only shifts the mean.
TEST(BiasMetrics, ConstantOffsetChangesOnlyTheMean)
{
	std::vector<double> t, r, r2;
	for (int k = 0; k < 2000; k++)
	{
		t.push_back(0.5 * k);
		r.push_back(0.01 * std::sin(k * 0.003) + 0.001 * (k % 13));
		r2.push_back(r.back() + 9.6684);
	}
	const BiasStats a = biasStats(t, r, 50.0), b = biasStats(t, r2, 50.0);
	EXPECT_NEAR(a.stability_dph, b.stability_dph, 1e-12);
	EXPECT_NEAR(a.range_dph, b.range_dph, 1e-12);
	EXPECT_NEAR(a.raw_peak_to_peak_dph, b.raw_peak_to_peak_dph, 1e-12);
	EXPECT_NEAR(b.mean_dph - a.mean_dph, 9.6684, 1e-12);
}

TEST(BiasMetrics, BadInputThrows)
{
	const std::vector<double> t = {0, 1, 2, 3, 4}, r = {1, 2, 3, 4, 5};
	EXPECT_THROW(biasStats(t, r, 0.0), std::invalid_argument);
	EXPECT_THROW(biasStats(t, r, -1.0), std::invalid_argument);
	EXPECT_THROW(biasStats(t, r, NAN), std::invalid_argument);
	EXPECT_THROW(biasStats(t, {1, 2, 3}, 1.0), std::invalid_argument);
	EXPECT_THROW(biasStats({0, 1, 1, 3, 4}, r, 1.0), std::invalid_argument);
	EXPECT_THROW(biasStats({0, 1, NAN, 3, 4}, r, 1.0), std::invalid_argument);
	// tau longer than the run: 5 s of data, tau 3 s leaves one window.
	try
	{
		biasStats(t, r, 3.0);
		FAIL() << "expected an exception";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("at least 2"), std::string::npos) << e.what();
	}
	EXPECT_NO_THROW(biasStats(t, r, 2.5));
	EXPECT_THROW(biasStats({0, 1, 2, 3}, {NAN, NAN, NAN, NAN}, 1.0), std::invalid_argument);
}

// A tau far below the sample interval: most windows are empty; the cost stays O(samples) and
// every sample is its own window (stability = std of the samples).
TEST(BiasMetrics, TinyTauDoesNotHang)
{
	std::vector<double> t, r;
	for (int k = 0; k < 1000; k++)
	{
		t.push_back(k * 10.0);
		r.push_back(k % 2 ? 1.0 : -1.0);
	}
	const BiasStats s = biasStats(t, r, 1e-6);  // 1e10 windows
	EXPECT_EQ(s.window_count, 1000u);
	EXPECT_EQ(s.empty_window_count + s.window_count, static_cast<std::size_t>(std::floor(10000.0 / 1e-6 + 1e-9)));
	EXPECT_NEAR(s.stability_dph, std::sqrt(1000.0 / 999.0), 1e-9);
	EXPECT_NEAR(s.range_dph, 2.0, 1e-12);
}
