/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/common/NumberFormat.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
namespace
{
void checkTimes(const std::vector<double>& time_s)
{
	for (std::size_t k = 0; k < time_s.size(); k++)
	{
		if (!std::isfinite(time_s[k]))
			throw std::invalid_argument("time_s[" + std::to_string(k) + "] is not finite");
		if (k > 0 && !(time_s[k] > time_s[k - 1]))
			throw std::invalid_argument(
				"time_s is not strictly increasing at sample " + std::to_string(k) + " (" +
				formatValue("%g", time_s[k - 1]) + " s then " + formatValue("%g", time_s[k]) + " s)");
	}
}
}  // namespace

double medianSampleInterval_s(const std::vector<double>& time_s)
{
	if (time_s.size() < 2) throw std::invalid_argument("need at least 2 samples to find the sample interval");
	std::vector<double> dt(time_s.size() - 1);
	for (std::size_t k = 1; k < time_s.size(); k++) dt[k - 1] = time_s[k] - time_s[k - 1];
	const auto mid = dt.begin() + static_cast<std::ptrdiff_t>(dt.size() / 2);
	std::nth_element(dt.begin(), mid, dt.end());
	return *mid;
}

BiasStats biasStats(const std::vector<double>& time_s, const std::vector<double>& rate_dph, double tau_s)
{
	if (time_s.size() != rate_dph.size())
		throw std::invalid_argument("time_s has " + std::to_string(time_s.size()) + " samples but rate_dph has " +
									std::to_string(rate_dph.size()));
	if (!std::isfinite(tau_s) || tau_s <= 0)
		throw std::invalid_argument("tau_s must be a positive number of seconds, got " + formatValue("%g", tau_s));
	checkTimes(time_s);
	if (time_s.size() < 2) throw std::invalid_argument("need at least 2 samples, got " + std::to_string(time_s.size()));

	BiasStats s;
	s.tau_s = tau_s;
	const double t0 = time_s.front();
	const double dt = medianSampleInterval_s(time_s);
	const double covered_s = time_s.back() - t0 + dt;
	// Complete windows; the small tolerance keeps an exact multiple (e.g. 1000 samples at 1 Hz,
	// tau 100 s) from losing its last window to rounding.
	const auto n_windows = static_cast<std::size_t>(std::floor(covered_s / tau_s + 1e-9));
	s.dropped_tail_s = std::max(0.0, covered_s - static_cast<double>(n_windows) * tau_s);

	double raw_min = INFINITY, raw_max = -INFINITY;
	for (double r : rate_dph)
		if (std::isfinite(r))
		{
			raw_min = std::min(raw_min, r);
			raw_max = std::max(raw_max, r);
		}
	s.raw_peak_to_peak_dph = raw_max >= raw_min ? raw_max - raw_min : NAN;

	// Walk the samples once; runs of empty windows (gaps, or a tau shorter than the sample
	// interval) are skipped in one step, so the cost is O(samples) whatever tau is.
	std::size_t k = 0, w = 0;
	while (w < n_windows && k < time_s.size())
	{
		const double w_end = t0 + static_cast<double>(w + 1) * tau_s;
		if (time_s[k] >= w_end)
		{
			auto next = static_cast<std::size_t>(std::floor((time_s[k] - t0) / tau_s));
			if (next <= w) next = w + 1;
			while (next > w + 1 && t0 + static_cast<double>(next) * tau_s > time_s[k]) next--;
			while (t0 + static_cast<double>(next + 1) * tau_s <= time_s[k]) next++;
			next = std::min(next, n_windows);
			s.empty_window_count += next - w;
			w = next;
			continue;
		}
		double sum = 0;
		std::size_t n = 0;
		for (; k < time_s.size() && time_s[k] < w_end; k++)
			if (std::isfinite(rate_dph[k]))
			{
				sum += rate_dph[k];
				n++;
			}
		if (n == 0) s.empty_window_count++;
		else
		{
			s.window_center_s.push_back(t0 + (static_cast<double>(w) + 0.5) * tau_s);
			s.window_mean_dph.push_back(sum / static_cast<double>(n));
			s.samples_used += n;
		}
		w++;
	}
	s.empty_window_count += n_windows - w;
	s.window_count = s.window_mean_dph.size();
	if (s.window_count < 2)
		throw std::invalid_argument("tau " + formatValue("%g", tau_s) + " s leaves " + std::to_string(s.window_count) +
									" window(s) with data in a run of " + formatValue("%g", covered_s) +
									" s; bias stability needs at least 2 (use a shorter tau)");

	// Two-pass mean and variance (numerically safe for a large constant offset such as Earth rate).
	double mean = 0;
	for (double m : s.window_mean_dph) mean += m;
	mean /= static_cast<double>(s.window_count);
	double ss = 0;
	for (double m : s.window_mean_dph) ss += (m - mean) * (m - mean);
	s.mean_dph = mean;
	s.stability_dph = std::sqrt(ss / static_cast<double>(s.window_count - 1));
	const auto [mn, mx] = std::minmax_element(s.window_mean_dph.begin(), s.window_mean_dph.end());
	s.range_dph = *mx - *mn;
	return s;
}

}  // namespace mrpt_fog
