/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/metrics/AllanDeviation.h>
#include <mrpt_fog/metrics/BiasMetrics.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
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
		AllanPoint p;
		p.m = m;
		p.tau_s = static_cast<double>(m) * tau0_s;
		p.adev = std::sqrt(static_cast<double>(sum / (2.0L * terms)));
		p.clusters = n / m;
		out.push_back(p);
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
	const double count_d = std::floor(best_len / period_s + 1e-9) + 1;
	const double finite_in_segment = static_cast<double>(best_b - best_a + 1);
	if (count_d > 4 * finite_in_segment + 16)
		throw std::invalid_argument("resampleUniform: a period of " + std::to_string(period_s) + " s would turn " +
									std::to_string(best_b - best_a + 1) + " samples into " +
									std::to_string(static_cast<long long>(count_d)) +
									": the timestamps are too irregular for a uniform resample");
	const auto count = static_cast<std::size_t>(count_d);
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

}  // namespace mrpt_fog
