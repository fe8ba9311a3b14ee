/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/AnalysisTimescale.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/metrics/AllanDeviation.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrpt_fog::discrepancy
{
namespace
{
using mrpt_fog::units::kNaN;

bool sameValue(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }
double at(const std::vector<double>& v, std::size_t k) { return v.empty() ? kNaN : v[k]; }
}  // namespace

double medianRowPeriod_s(const FogSeries& run)
{
	if (run.size() < 2) return 0.0;
	std::vector<double> d;
	d.reserve(run.size() - 1);
	for (std::size_t k = 1; k < run.size(); ++k) d.push_back(run.time_s[k] - run.time_s[k - 1]);
	std::nth_element(d.begin(), d.begin() + static_cast<std::ptrdiff_t>(d.size() / 2), d.end());
	return d[d.size() / 2];
}

double whiteNoiseCorner_s(const std::vector<double>& residual, double period_s)
{
	std::vector<double> y;
	y.reserve(residual.size());
	for (double v : residual)
		if (std::isfinite(v)) y.push_back(v);
	if (y.size() < 64 || !(period_s > 0)) return kNaN;
	const auto curve = allanDeviation(y, period_s, octaveClusterSizes(y.size(), 8), AllanKind::NonOverlapping);
	if (curve.empty() || !(curve.front().adev > 0)) return kNaN;
	const double avar0 = curve.front().adev * curve.front().adev, tau0 = curve.front().tau_s;
	for (const auto& p : curve)
		if (p.adev * p.adev >= 2.0 * avar0 * tau0 / p.tau_s) return p.tau_s;
	return kNaN;
}

FogSeries blockMeansOfRows(const FogSeries& run, double block_s)
{
	const double period = medianRowPeriod_s(run);
	const std::size_t K = period > 0 ? static_cast<std::size_t>(std::floor(block_s / period + 1e-9)) : 1;
	if (K <= 1) return run;
	FogSeries out = run;
	out.resize(0);
	const std::size_t n = run.size(), nth = run.thermistorCount();
	std::size_t begin = 0;
	while (begin < n)
	{
		std::size_t end = begin + 1;
		while (end < n && end - begin < K && sameValue(at(run.power, end), at(run.power, begin)) &&
			   sameValue(at(run.table_rate_dph, end), at(run.table_rate_dph, begin)) &&
			   sameValue(at(run.field_uT, end), at(run.field_uT, begin)) &&
			   run.time_s[end] - run.time_s[end - 1] <= 3.0 * period)
			++end;
		const double m = static_cast<double>(end - begin);
		double t = 0;
		for (std::size_t k = begin; k < end; ++k) t += run.time_s[k];
		out.time_s.push_back(t / m);
		for (int a = 0; a < 3; ++a)
			if (!run.rate_dph[a].empty())
			{
				double s = 0;
				for (std::size_t k = begin; k < end; ++k) s += run.rate_dph[a][k];
				out.rate_dph[a].push_back(s / m);  // NaN only on power-off blocks, as in the rows
			}
		for (std::size_t i = 0; i < nth; ++i)
		{
			double s = 0, c = 0;
			for (std::size_t k = begin; k < end; ++k)
				if (std::isfinite(run.temp_C[i][k]))
				{
					s += run.temp_C[i][k];
					c += 1;
				}
			out.temp_C[i].push_back(c > 0 ? s / c : kNaN);
		}
		if (!run.table_rate_dph.empty()) out.table_rate_dph.push_back(run.table_rate_dph[begin]);
		if (!run.field_uT.empty()) out.field_uT.push_back(run.field_uT[begin]);
		if (!run.power.empty()) out.power.push_back(run.power[begin]);
		begin = end;
	}
	return out;
}

}  // namespace mrpt_fog::discrepancy
