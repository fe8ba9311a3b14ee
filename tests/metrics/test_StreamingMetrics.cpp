/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The figures of records read in passes from a RowSpill (logs longer than memory) equal
 * those of the same records in vectors, bit for bit. */
#include <gtest/gtest.h>
#include <mrpt_fog/metrics/AllanDeviation.h>
#include <mrpt_fog/metrics/BiasMetrics.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace mrpt_fog;

namespace
{
bool same(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

/** An irregular record: jittered 10 Hz times, two gaps, NaN stretches, a random walk. */
void irregularRecord(std::size_t n, std::vector<double>& t, std::vector<double>& v)
{
	std::mt19937_64 rng(42);
	std::normal_distribution<double> nd(0, 1);
	std::uniform_real_distribution<double> jitter(-0.002, 0.002);
	double time = 3.0, walk = 0;
	for (std::size_t k = 0; k < n; k++)
	{
		time += 0.1 + jitter(rng) + (k == n / 3 ? 7.0 : 0.0) + (k == n / 2 ? 100.0 : 0.0);
		walk += 0.01 * nd(rng);
		t.push_back(time);
		v.push_back((k % 5000 < 20) ? NAN : walk + nd(rng));
	}
}

RowSpill spillOf(const std::vector<double>& t, const std::vector<double>& v)
{
	RowSpill s(2);
	for (std::size_t k = 0; k < t.size(); k++)
	{
		const double row[2] = {t[k], v[k]};
		s.push(row);
	}
	return s;
}

RecordPass passOf(const RowSpill& s)
{
	return [&s](const RecordVisitor& f) {
		s.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
			for (std::size_t j = 0; j < n; j++) f(r[2 * j], r[2 * j + 1]);
		});
	};
}
}  // namespace

TEST(StreamingMetrics, MedianIntervalEqualsTheSortedMedian)
{
	std::vector<double> t, v;
	irregularRecord(100001, t, v);
	const RowSpill s = spillOf(t, v);
	EXPECT_TRUE(s.onDisk());
	EXPECT_TRUE(same(medianSampleInterval_s(passOf(s)), medianSampleInterval_s(t)));
	t.resize(100000);  // even count of intervals - 1
	v.resize(100000);
	EXPECT_TRUE(same(medianSampleInterval_s(passOf(spillOf(t, v))), medianSampleInterval_s(t)));
	// exactly representable intervals: 0.5 s x 3, 0.25 s x 2 -> sorted 0.25 0.25 0.5 0.5 0.5, index 2
	const std::vector<double> q = {0, 0.5, 0.75, 1.25, 1.5, 2.0};
	EXPECT_EQ(medianSampleInterval_s(passOf(spillOf(q, q))), 0.5);
}

TEST(StreamingMetrics, BiasStatsInPassesEqualTheVectorForm)
{
	std::vector<double> t, v;
	irregularRecord(200000, t, v);
	const BiasStats a = biasStats(t, v, 100.0);
	// the vector form goes through the pass form: check against an independent walk too
	const BiasStats b = biasStats(passOf(spillOf(t, v)), 100.0);
	EXPECT_TRUE(same(a.stability_dph, b.stability_dph));
	EXPECT_TRUE(same(a.range_dph, b.range_dph));
	EXPECT_EQ(a.window_count, b.window_count);
	EXPECT_EQ(a.empty_window_count, b.empty_window_count);
	// window means by hand (closed form of the definition): window w = [t0 + w tau, t0 + (w+1) tau)
	std::vector<double> sum(a.window_count + a.empty_window_count + 2, 0.0);
	std::vector<std::size_t> cnt(sum.size(), 0);
	for (std::size_t k = 0; k < t.size(); k++)
	{
		const auto w = static_cast<std::size_t>(std::floor((t[k] - t[0]) / 100.0));
		if (w < sum.size() && std::isfinite(v[k])) sum[w] += v[k], cnt[w]++;
	}
	std::size_t j = 0;
	for (std::size_t w = 0; w < a.window_count + a.empty_window_count; w++)
		if (cnt[w] > 0)
		{
			ASSERT_LT(j, b.window_mean_dph.size());
			EXPECT_NEAR(b.window_mean_dph[j++], sum[w] / static_cast<double>(cnt[w]), 1e-12);
		}
	EXPECT_EQ(j, b.window_count);
	// the 100 s gap leaves empty windows at tau 30 s
	const BiasStats c = biasStats(t, v, 30.0), d = biasStats(passOf(spillOf(t, v)), 30.0);
	EXPECT_TRUE(same(c.stability_dph, d.stability_dph));
	EXPECT_GT(d.empty_window_count, 0u);
}

// Long enough (2^19 samples) that cluster sizes above the 65 536 ring go through the three-reader
// path.
TEST(StreamingMetrics, ResampleAndOverlappingAllanEqualTheVectorForms)
{
	std::vector<double> t, v;
	irregularRecord(1u << 19, t, v);
	const UniformRecord u = resampleUniform(t, v);
	const RowSpill s = spillOf(t, v);
	RowSpill us(1);
	const UniformRecord w = resampleUniform(s, 0, 1, us);
	EXPECT_TRUE(same(u.t0_s, w.t0_s));
	EXPECT_TRUE(same(u.period_s, w.period_s));
	EXPECT_EQ(u.segments, w.segments);
	ASSERT_EQ(u.value.size(), us.rows());
	std::size_t k = 0, differ = 0;
	us.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
		for (std::size_t j = 0; j < n; j++) differ += !same(r[j], u.value[k++]);
	});
	EXPECT_EQ(differ, 0u);

	// a record with cluster sizes beyond the ring: n = 2^19 + 3, m up to 2^17
	std::vector<double> y(t.size() + 3);
	std::mt19937_64 rng(7);
	std::normal_distribution<double> nd(0, 1);
	double walk = 0;
	for (auto& x : y) x = (walk += 0.001 * nd(rng)) + nd(rng);
	RowSpill ys(1);
	for (double x : y) ys.push(&x);
	const auto m = octaveClusterSizes(y.size(), 4);
	ASSERT_GT(m.back(), 65536u);
	const auto a = allanDeviation(y, 0.01, m, AllanKind::Overlapping);
	const auto b = allanDeviationOverlapping(ys, 0.01, m, AllanOffsets::All);
	ASSERT_EQ(a.size(), b.size());
	for (std::size_t i = 0; i < a.size(); i++)
	{
		EXPECT_EQ(a[i].m, b[i].m);
		EXPECT_TRUE(same(a[i].adev, b[i].adev)) << "m " << a[i].m << ": " << a[i].adev << " vs " << b[i].adev;
	}
	// the linear-time estimator (the default): the same numbers up to the ring, then the strided
	// sum (stride 256: 512 offsets per cluster length at m = 2^17). A Monte Carlo of 300 white
	// and 300 random-walk records of 2^20 samples (docs/reference/metrics.md) put |strided / full - 1| at
	// a median of 1e-4..3.4e-4 and a maximum of 2.8e-3, with the same spread over the records
	// (21-43 %, 4-8 clusters): 1 % is 3.5x the largest seen.
	const auto c = allanDeviationOverlapping(ys, 0.01, m);
	ASSERT_EQ(a.size(), c.size());
	for (std::size_t i = 0; i < a.size(); i++)
	{
		EXPECT_EQ(a[i].m, c[i].m);
		EXPECT_EQ(a[i].clusters, c[i].clusters);
		if (a[i].m <= 65536) EXPECT_TRUE(same(a[i].adev, c[i].adev)) << "m " << a[i].m;
		else EXPECT_NEAR(c[i].adev / a[i].adev, 1.0, 0.01) << "m " << a[i].m << ": " << c[i].adev << " vs " << a[i].adev;
	}
}

// Closed form: on a ramp y_k = a k every second difference of the phase is a m^2 (tau0 = 1),
// so ADEV = a m / sqrt(2) exactly, whichever offsets are summed.
TEST(StreamingMetrics, LinearTimeAllanIsExactOnARamp)
{
	const std::size_t n = (1u << 19) + 5;
	RowSpill ys(1);
	const double a = 1e-6;
	for (std::size_t k = 0; k < n; k++)
	{
		const double v = a * static_cast<double>(k);
		ys.push(&v);
	}
	const auto m = octaveClusterSizes(n, 4);
	ASSERT_EQ(m.back(), 131072u);
	for (const auto& p : allanDeviationOverlapping(ys, 1.0, m))
		EXPECT_NEAR(p.adev, a * static_cast<double>(p.m) / std::sqrt(2.0), 1e-9 * a * static_cast<double>(p.m))
			<< "m " << p.m;
}
