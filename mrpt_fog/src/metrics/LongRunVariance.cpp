/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/metrics/LongRunVariance.h>
#include <mrpt_fog/obs/Units.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;

double pooledBlocks(const std::vector<std::vector<double>>& series)
{
	std::size_t m = 0;
	for (const auto& s : series) m += s.size();
	if (m < 8) return kNaN;
	const auto b = static_cast<std::size_t>(std::max(1.0, std::round(std::sqrt(static_cast<double>(m) / series.size()))));
	std::vector<double> means;
	double grand = 0;
	for (const auto& s : series)
		for (std::size_t i = 0; i + b <= s.size(); i += b)
		{
			double x = 0;
			for (std::size_t j = i; j < i + b; ++j) x += s[j];
			means.push_back(x / b);
			grand += x / b;
		}
	if (means.size() < 2) return kNaN;
	grand /= means.size();
	double v = 0;
	for (double x : means) v += (x - grand) * (x - grand);
	return static_cast<double>(b) * v / (means.size() - 1);
}

double meanOfSeries(const std::vector<std::vector<double>>& series)
{
	double s2sum = 0;
	int s2n = 0;
	for (const auto& s : series)
	{
		const std::size_t m = s.size();
		const auto b = static_cast<std::size_t>(std::max<long>(1, std::lround(std::sqrt(static_cast<double>(m)))));
		const std::size_t nb = m / b;
		if (nb < 2) continue;
		std::vector<double> means(nb, 0.0);
		for (std::size_t blk = 0; blk < nb; ++blk)
		{
			for (std::size_t u = 0; u < b; ++u) means[blk] += s[blk * b + u];
			means[blk] /= static_cast<double>(b);
		}
		double mu = 0;
		for (double v : means) mu += v;
		mu /= static_cast<double>(nb);
		double var = 0;
		for (double v : means) var += (v - mu) * (v - mu);
		var /= static_cast<double>(nb - 1);
		s2sum += std::max(var * static_cast<double>(b), 0.0);
		s2n++;
	}
	return s2n > 0 ? s2sum / s2n : kNaN;
}
}  // namespace

double batchMeansLongRunVariance(const std::vector<std::vector<double>>& series, BatchPooling pooling)
{
	return pooling == BatchPooling::PooledBlocks ? pooledBlocks(series) : meanOfSeries(series);
}

double longRunVarianceFactor(const Eigen::VectorXd& e, int max_lag)
{
	const Eigen::Index n = e.size();
	if (n < 3) return 1.0;
	const double mean = e.mean();
	const Eigen::VectorXd c = e.array() - mean;
	const double c0 = c.squaredNorm();
	if (c0 <= 0) return 1.0;
	double f = 1.0;
	for (int l = 1; l <= max_lag && l < n; ++l)
	{
		const double rho = c.head(n - l).dot(c.tail(n - l)) / c0;
		f += 2.0 * (1.0 - double(l) / (max_lag + 1)) * rho;
	}
	return std::max(1.0, f);
}

}  // namespace mrpt_fog
