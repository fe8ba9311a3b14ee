/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/common/NumberFormat.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{

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
	return biasStats(
		[&](const RecordVisitor& f) {
			for (std::size_t k = 0; k < time_s.size(); k++) f(time_s[k], rate_dph[k]);
		},
		tau_s);
}

double medianSampleInterval_s(const RecordPass& pass)
{
	// Exact order statistic dt[(n - 1) / 2] (what nth_element gives on the n - 1 intervals) by a
	// radix selection over the bits of the (positive) intervals: four passes of 16 bits, 65 536
	// counters, whatever the record's length.
	std::size_t count = 0;
	pass([&](double, double) { count++; });
	if (count < 2) throw std::invalid_argument("need at least 2 samples to find the sample interval");
	std::size_t rank = (count - 1) / 2;
	std::uint64_t prefix = 0;
	std::vector<std::size_t> hist(1u << 16);
	for (int digit = 3; digit >= 0; digit--)
	{
		std::fill(hist.begin(), hist.end(), 0);
		const int shift = 16 * digit;
		const std::uint64_t high_mask = digit == 3 ? 0 : ~std::uint64_t{0} << (shift + 16);
		bool first = true;
		double prev = 0;
		pass([&](double t, double) {
			if (!first)
			{
				const double dt = t - prev;
				std::uint64_t bits;
				std::memcpy(&bits, &dt, sizeof bits);
				bits ^= (bits >> 63) ? ~std::uint64_t{0} : (std::uint64_t{1} << 63);  // order as unsigned
				if ((bits & high_mask) == prefix) hist[(bits >> shift) & 0xffff]++;
			}
			first = false;
			prev = t;
		});
		std::size_t b = 0;
		while (rank >= hist[b]) rank -= hist[b++];
		prefix |= static_cast<std::uint64_t>(b) << shift;
	}
	const std::uint64_t bits = (prefix >> 63) ? prefix ^ (std::uint64_t{1} << 63) : ~prefix;
	double v;
	std::memcpy(&v, &bits, sizeof v);
	return v;
}

BiasStats biasStats(const RecordPass& pass, double tau_s)
{
	if (!std::isfinite(tau_s) || tau_s <= 0)
		throw std::invalid_argument("tau_s must be a positive number of seconds, got " + formatValue("%g", tau_s));
	// Pass 1: the times (finite, strictly increasing), count, first and last, raw extremes.
	std::size_t n = 0;
	double t0 = 0, t_last = 0, raw_min = INFINITY, raw_max = -INFINITY;
	pass([&](double t, double r) {
		if (!std::isfinite(t)) throw std::invalid_argument("time_s[" + std::to_string(n) + "] is not finite");
		if (n > 0 && !(t > t_last))
			throw std::invalid_argument("time_s is not strictly increasing at sample " + std::to_string(n) + " (" +
										formatValue("%g", t_last) + " s then " + formatValue("%g", t) + " s)");
		if (n == 0) t0 = t;
		t_last = t;
		n++;
		if (std::isfinite(r))
		{
			raw_min = std::min(raw_min, r);
			raw_max = std::max(raw_max, r);
		}
	});
	if (n < 2) throw std::invalid_argument("need at least 2 samples, got " + std::to_string(n));

	BiasStats s;
	s.tau_s = tau_s;
	const double dt = medianSampleInterval_s(pass);
	const double covered_s = t_last - t0 + dt;
	// Complete windows; the small tolerance keeps an exact multiple (e.g. 1000 samples at 1 Hz,
	// tau 100 s) from losing its last window to rounding.
	const auto n_windows = static_cast<std::size_t>(std::floor(covered_s / tau_s + 1e-9));
	s.dropped_tail_s = std::max(0.0, covered_s - static_cast<double>(n_windows) * tau_s);
	s.raw_peak_to_peak_dph = raw_max >= raw_min ? raw_max - raw_min : NAN;

	// Pass 2: the window averages, sample by sample; runs of empty windows (gaps, or a tau shorter
	// than the sample interval) are skipped in one step, so the cost is O(samples) whatever tau is.
	std::size_t w = 0, wn = 0;
	bool open = false;  // window w has started collecting samples
	double sum = 0;
	const auto close = [&]() {
		if (wn == 0) s.empty_window_count++;
		else
		{
			s.window_center_s.push_back(t0 + (static_cast<double>(w) + 0.5) * tau_s);
			s.window_mean_dph.push_back(sum / static_cast<double>(wn));
			s.samples_used += wn;
		}
		w++;
		open = false;
	};
	pass([&](double t, double r) {
		while (w < n_windows)
		{
			const double w_end = t0 + static_cast<double>(w + 1) * tau_s;
			if (!open)
			{
				if (t >= w_end)
				{
					auto next = static_cast<std::size_t>(std::floor((t - t0) / tau_s));
					if (next <= w) next = w + 1;
					while (next > w + 1 && t0 + static_cast<double>(next) * tau_s > t) next--;
					while (t0 + static_cast<double>(next + 1) * tau_s <= t) next++;
					next = std::min(next, n_windows);
					s.empty_window_count += next - w;
					w = next;
					continue;
				}
				open = true;
				sum = 0;
				wn = 0;
			}
			if (t < w_end)
			{
				if (std::isfinite(r))
				{
					sum += r;
					wn++;
				}
				return;
			}
			close();
		}
	});
	if (open) close();
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
