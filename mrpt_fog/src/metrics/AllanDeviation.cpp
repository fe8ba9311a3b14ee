/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/metrics/AllanDeviation.h>
#include <mrpt_fog/metrics/BiasMetrics.h>

#include <cmath>
#include <map>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
namespace
{
/** Samples of a uniform resample at period_s over a gap-free segment of length segment_s
 * holding finite_samples samples; refuses a period that would multiply the samples (irregular
 * timestamps). */
std::size_t uniformSampleCount(double segment_s, double period_s, std::size_t finite_samples)
{
	const double count_d = std::floor(segment_s / period_s + 1e-9) + 1;
	if (count_d > 4 * static_cast<double>(finite_samples) + 16)
		throw std::invalid_argument("resampleUniform: a period of " + std::to_string(period_s) + " s would turn " +
									std::to_string(finite_samples) + " samples into " +
									std::to_string(static_cast<long long>(count_d)) +
									": the timestamps are too irregular for a uniform resample");
	return static_cast<std::size_t>(count_d);
}
/** The Allan deviation at cluster size m from the sum of squared second differences of the
 * cluster averages (`terms` of them) of an n-sample record at tau0_s. */
AllanPoint allanPointOf(std::size_t m, double tau0_s, long double sum, std::size_t terms, std::size_t n)
{
	AllanPoint p;
	p.m = m;
	p.tau_s = static_cast<double>(m) * tau0_s;
	p.adev = std::sqrt(static_cast<double>(sum / (2.0L * terms)));
	p.clusters = n / m;
	return p;
}
}  // namespace

std::vector<std::size_t> octaveClusterSizes(std::size_t n, std::size_t min_clusters)
{
	if (min_clusters < 2) min_clusters = 2;
	std::vector<std::size_t> m;
	for (std::size_t k = 1; k * min_clusters <= n; k *= 2) m.push_back(k);
	return m;
}

std::vector<AllanPoint> allanDeviation(const std::vector<double>& y, double tau0_s,
									   const std::vector<std::size_t>& cluster_sizes, AllanKind kind)
{
	if (!std::isfinite(tau0_s) || tau0_s <= 0)
		throw std::invalid_argument("Allan deviation: sample period must be > 0 s, got " + std::to_string(tau0_s));
	const std::size_t n = y.size();
	if (n < 2) throw std::invalid_argument("Allan deviation: need at least 2 samples, got " + std::to_string(n));
	// Remove the mean first: the estimators are blind to it, and it keeps the phase sums small.
	double mean = 0;
	for (std::size_t k = 0; k < n; k++)
	{
		if (!std::isfinite(y[k]))
			throw std::invalid_argument("Allan deviation: sample " + std::to_string(k) +
										" is not finite (resample the record first)");
		mean += y[k];
	}
	mean /= static_cast<double>(n);
	// Phase x_i = sum_{k<i} (y_k - mean), in units of rate * samples (tau0 cancels out below).
	std::vector<long double> x(n + 1, 0.0L);
	for (std::size_t k = 0; k < n; k++) x[k + 1] = x[k] + static_cast<long double>(y[k] - mean);

	std::vector<AllanPoint> out;
	for (std::size_t m : cluster_sizes)
	{
		if (m == 0) throw std::invalid_argument("Allan deviation: cluster size 0");
		long double sum = 0;
		std::size_t terms = 0;
		if (kind == AllanKind::NonOverlapping)
		{
			const std::size_t M = n / m;
			if (M < 2) continue;
			// Cluster average j is (x[(j+1)m] - x[jm]) / m.
			for (std::size_t j = 0; j + 1 < M; j++)
			{
				const long double d = (x[(j + 2) * m] - 2 * x[(j + 1) * m] + x[j * m]) / m;
				sum += d * d;
			}
			terms = M - 1;
		}
		else
		{
			if (2 * m > n) continue;
			for (std::size_t i = 0; i + 2 * m <= n; i++)
			{
				const long double d = (x[i + 2 * m] - 2 * x[i + m] + x[i]) / m;
				sum += d * d;
			}
			terms = n - 2 * m + 1;
		}
		out.push_back(allanPointOf(m, tau0_s, sum, terms, n));
	}
	return out;
}

std::vector<AllanPoint> allanDeviation(const std::vector<double>& y, double tau0_s, AllanKind kind)
{
	return allanDeviation(y, tau0_s, octaveClusterSizes(y.size()), kind);
}

UniformRecord resampleUniform(const std::vector<double>& time_s, const std::vector<double>& value, double period_s,
							  double max_gap_s)
{
	if (time_s.size() != value.size())
		throw std::invalid_argument("resampleUniform: " + std::to_string(time_s.size()) + " times but " +
									std::to_string(value.size()) + " values");
	std::vector<double> t, v;
	for (std::size_t k = 0; k < time_s.size(); k++)
	{
		if (!std::isfinite(time_s[k]) || (k > 0 && !(time_s[k] > time_s[k - 1])))
			throw std::invalid_argument("resampleUniform: time is not finite and strictly increasing at sample " +
										std::to_string(k));
		if (std::isfinite(value[k]))
		{
			t.push_back(time_s[k]);
			v.push_back(value[k]);
		}
	}
	if (t.size() < 2) throw std::invalid_argument("resampleUniform: fewer than 2 finite samples");
	if (!(period_s > 0)) period_s = medianSampleInterval_s(time_s);
	if (!(max_gap_s > 0)) max_gap_s = 5 * period_s;

	// Longest gap-free segment [best_a, best_b] of finite samples.
	UniformRecord r;
	r.segments = 1;
	std::size_t a = 0, best_a = 0, best_b = 0;
	double best_len = -1;
	for (std::size_t k = 1; k <= t.size(); k++)
	{
		if (k == t.size() || t[k] - t[k - 1] > max_gap_s)
		{
			if (t[k - 1] - t[a] > best_len)
			{
				best_len = t[k - 1] - t[a];
				best_a = a;
				best_b = k - 1;
			}
			if (k < t.size())
			{
				r.segments++;
				a = k;
			}
		}
	}
	r.t0_s = t[best_a];
	r.period_s = period_s;
	const std::size_t count = uniformSampleCount(best_len, period_s, best_b - best_a + 1);
	r.value.resize(count);
	std::size_t j = best_a;
	for (std::size_t i = 0; i < count; i++)
	{
		const double ti = r.t0_s + static_cast<double>(i) * period_s;
		while (j + 1 < best_b && t[j + 1] <= ti) j++;
		const std::size_t j1 = std::min(j + 1, best_b);
		if (j1 == j || ti <= t[j]) r.value[i] = v[j];
		else
		{
			const double f = (ti - t[j]) / (t[j1] - t[j]);
			r.value[i] = v[j] + f * (v[j1] - v[j]);
		}
	}
	return r;
}

UniformRecord resampleUniform(const RowSpill& rows, std::size_t tc, std::size_t vc, RowSpill& out, double period_s,
							  double max_gap_s)
{
	if (tc >= rows.width() || vc >= rows.width() || out.width() != 1)
		throw std::invalid_argument("resampleUniform: bad columns");
	const RecordPass times = [&](const RecordVisitor& f) {
		rows.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
			for (std::size_t j = 0; j < n; j++) f(r[j * rows.width() + tc], 0.0);
		});
	};
	// Pass 1: times finite and strictly increasing; finite values counted.
	std::size_t k = 0, finite = 0;
	double prev = 0;
	rows.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
		for (std::size_t j = 0; j < n; j++, k++)
		{
			const double t = r[j * rows.width() + tc], v = r[j * rows.width() + vc];
			if (!std::isfinite(t) || (k > 0 && !(t > prev)))
				throw std::invalid_argument("resampleUniform: time is not finite and strictly increasing at sample " +
											std::to_string(k));
			prev = t;
			finite += std::isfinite(v);
		}
	});
	if (finite < 2) throw std::invalid_argument("resampleUniform: fewer than 2 finite samples");
	if (!(period_s > 0)) period_s = medianSampleInterval_s(times);
	if (!(max_gap_s > 0)) max_gap_s = 5 * period_s;

	// Pass 2: longest gap-free segment [best_a, best_b] of finite samples (indices among them).
	UniformRecord rec;
	rec.segments = 1;
	std::size_t q = 0, a = 0, best_a = 0, best_b = 0;
	double best_len = -1, t_a = 0, t_prev = 0, t_best_a = 0;
	const auto close = [&](std::size_t last) {
		if (t_prev - t_a > best_len)
		{
			best_len = t_prev - t_a;
			best_a = a;
			best_b = last;
			t_best_a = t_a;
		}
	};
	rows.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
		for (std::size_t j = 0; j < n; j++)
		{
			const double t = r[j * rows.width() + tc], v = r[j * rows.width() + vc];
			if (!std::isfinite(v)) continue;
			if (q == 0) t_a = t;
			else if (t - t_prev > max_gap_s)
			{
				close(q - 1);
				rec.segments++;
				a = q;
				t_a = t;
			}
			t_prev = t;
			q++;
		}
	});
	close(q - 1);
	rec.t0_s = t_best_a;
	rec.period_s = period_s;
	const std::size_t count = uniformSampleCount(best_len, period_s, best_b - best_a + 1);

	// Pass 3: linear interpolation, a window of two finite samples (j, j + 1) sliding forward.
	RowSpill::Reader reader(rows);
	std::size_t fq = 0;  // finite samples read so far
	const auto nextFinite = [&](double& t, double& v) {
		for (const double* r = reader.next(); r; r = reader.next())
			if (std::isfinite(r[vc]))
			{
				t = r[tc];
				v = r[vc];
				fq++;
				return;
			}
		throw std::logic_error("resampleUniform: the record changed between passes");
	};
	double tj = 0, vj = 0, tn = 0, vn = 0;
	while (fq <= best_a) nextFinite(tj, vj);
	std::size_t j = best_a;
	if (best_b > best_a) nextFinite(tn, vn);
	for (std::size_t i = 0; i < count; i++)
	{
		const double ti = rec.t0_s + static_cast<double>(i) * period_s;
		while (j + 1 < best_b && tn <= ti)
		{
			tj = tn;
			vj = vn;
			nextFinite(tn, vn);
			j++;
		}
		const std::size_t j1 = std::min(j + 1, best_b);
		double value;
		if (j1 == j || ti <= tj) value = vj;
		else
		{
			const double f = (ti - tj) / (tn - tj);
			value = vj + f * (vn - vj);
		}
		out.push(&value);
	}
	return rec;
}

std::vector<AllanPoint> allanDeviationOverlapping(const RowSpill& y, double tau0_s,
												  const std::vector<std::size_t>& cluster_sizes, AllanOffsets offsets)
{
	if (!std::isfinite(tau0_s) || tau0_s <= 0)
		throw std::invalid_argument("Allan deviation: sample period must be > 0 s, got " + std::to_string(tau0_s));
	if (y.width() != 1) throw std::invalid_argument("Allan deviation: the record must have one column");
	const std::size_t n = y.rows();
	if (n < 2) throw std::invalid_argument("Allan deviation: need at least 2 samples, got " + std::to_string(n));
	double mean = 0;
	{
		std::size_t k = 0;
		y.forEachBlock([&](const double* v, std::size_t m, std::size_t) {
			for (std::size_t j = 0; j < m; j++, k++)
			{
				if (!std::isfinite(v[j]))
					throw std::invalid_argument("Allan deviation: sample " + std::to_string(k) +
												" is not finite (resample the record first)");
				mean += v[j];
			}
		});
	}
	mean /= static_cast<double>(n);
	// Phase x_i = sum_{k<i} (y_k - mean) as in allanDeviation(), computed in the same order by
	// every reader: the same long doubles.
	constexpr std::size_t kRingMax = 1u << 16;
	std::vector<std::size_t> ring_m;
	std::size_t ring_top = 0;
	for (std::size_t m : cluster_sizes)
	{
		if (m == 0) throw std::invalid_argument("Allan deviation: cluster size 0");
		if (m <= kRingMax && 2 * m <= n)
		{
			ring_m.push_back(m);
			ring_top = std::max(ring_top, m);
		}
	}
	// Linear: phases at multiples of the stride, kept during the pass, for the larger sizes
	std::size_t stride = 256;
	while (stride < n / (std::size_t{1} << 18)) stride *= 2;
	bool strided = false;
	if (offsets == AllanOffsets::Linear)
		for (std::size_t m : cluster_sizes)
			strided = strided || (m > kRingMax && 2 * m <= n && m % stride == 0);
	std::vector<long double> phase_at_stride;
	if (strided) phase_at_stride.reserve(n / stride + 1);
	std::map<std::size_t, long double> sums;
	if (!ring_m.empty() || strided)
	{
		// One pass: x[p] with p = 0..n, a ring of the last 2 m_max + 1 phases.
		const std::size_t L = 2 * ring_top + 1;
		std::vector<long double> ring(L, 0.0L);
		std::vector<long double> acc(ring_m.size(), 0.0L);
		long double x = 0.0L;
		std::size_t p = 0;
		const auto at = [&](std::size_t idx) -> long double { return ring[idx % L]; };
		const auto visit = [&]() {
			ring[p % L] = x;
			if (strided && p % stride == 0) phase_at_stride.push_back(x);
			for (std::size_t u = 0; u < ring_m.size(); u++)
			{
				const std::size_t m = ring_m[u];
				if (p < 2 * m) continue;
				const long double d = (x - 2 * at(p - m) + at(p - 2 * m)) / m;
				acc[u] += d * d;
			}
		};
		visit();  // p = 0, x = 0
		y.forEachBlock([&](const double* v, std::size_t m, std::size_t) {
			for (std::size_t j = 0; j < m; j++)
			{
				x = x + static_cast<long double>(v[j] - mean);
				p++;
				visit();
			}
		});
		for (std::size_t u = 0; u < ring_m.size(); u++) sums[ring_m[u]] = acc[u];
	}
	std::vector<AllanPoint> out;
	for (std::size_t m : cluster_sizes)
	{
		if (2 * m > n) continue;
		long double sum = 0;
		std::size_t terms = n - 2 * m + 1;
		if (m <= kRingMax) sum = sums.at(m);
		else if (strided && m % stride == 0)
		{
			// offsets i = j s: x_i, x_{i+m}, x_{i+2m} are phases j, j + q, j + 2q of the stride
			const std::size_t q = m / stride;
			terms = 0;
			for (std::size_t j = 0; j + 2 * q < phase_at_stride.size(); j++, terms++)
			{
				const long double d = (phase_at_stride[j + 2 * q] - 2 * phase_at_stride[j + q] + phase_at_stride[j]) / m;
				sum += d * d;
			}
		}
		else
		{
			// Three readers at phases i, i + m, i + 2m.
			RowSpill::Reader r0(y), r1(y), r2(y);
			long double x0 = 0.0L, x1 = 0.0L, x2 = 0.0L;
			const auto step = [&](RowSpill::Reader& r, long double& x) { x = x + static_cast<long double>(*r.next() - mean); };
			for (std::size_t k = 0; k < m; k++) step(r1, x1);
			for (std::size_t k = 0; k < 2 * m; k++) step(r2, x2);
			for (std::size_t i = 0; i + 2 * m <= n; i++)
			{
				const long double d = (x2 - 2 * x1 + x0) / m;
				sum += d * d;
				if (i + 2 * m == n) break;
				step(r0, x0);
				step(r1, x1);
				step(r2, x2);
			}
		}
		out.push_back(allanPointOf(m, tau0_s, sum, terms, n));
	}
	return out;
}

}  // namespace mrpt_fog
