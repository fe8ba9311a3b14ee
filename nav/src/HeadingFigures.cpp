/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt_fog_nav/HeadingFigures.h>
#include "NavUnits.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::nav
{
namespace
{
constexpr double kRadToDeg = 180.0 / M_PI;
using units::kSecondsPerHour;

/** Unwrapped truth yaw [deg] at the truth times. */
std::vector<double> unwrappedYaw_deg(const Trajectory& truth)
{
	std::vector<double> y(truth.size());
	double acc = 0;
	for (std::size_t i = 0; i < truth.size(); i++)
	{
		if (i > 0)
		{
			double d = truth[i].yaw_rad - truth[i - 1].yaw_rad;
			d = std::remainder(d, 2 * M_PI);
			acc += d;
		}
		y[i] = (truth.front().yaw_rad + acc) * kRadToDeg;
	}
	return y;
}

/** Linear interpolation of (t, v) at time x (t ascending; clamped to the ends). */
double interpAt(const std::vector<double>& t, const std::vector<double>& v, double x)
{
	if (x <= t.front()) return v.front();
	if (x >= t.back()) return v.back();
	const auto it = std::upper_bound(t.begin(), t.end(), x);
	const std::size_t i = static_cast<std::size_t>(it - t.begin());
	const double a = (x - t[i - 1]) / (t[i] - t[i - 1]);
	return v[i - 1] + a * (v[i] - v[i - 1]);
}
}  // namespace

DriveSegments segmentDrive(const Trajectory& truth, const HeadingFigureOptions& o)
{
	DriveSegments seg;
	const std::size_t n = truth.size();
	if (n < 3) return seg;
	const std::vector<double> yaw = unwrappedYaw_deg(truth);
	std::vector<double> t(n);
	for (std::size_t i = 0; i < n; i++) t[i] = truth[i].t_s;
	// smoothed rate: heading change over [t - w/2, t + w/2] / w
	std::vector<double> rate(n);
	const double h = 0.5 * o.smooth_s;
	for (std::size_t i = 0; i < n; i++)
	{
		const double a = std::max(t.front(), t[i] - h), b = std::min(t.back(), t[i] + h);
		rate[i] = b > a ? (interpAt(t, yaw, b) - interpAt(t, yaw, a)) / (b - a) : 0.0;
	}
	// turns: maximal stretches above turn_rate; straights: below straight_rate
	for (std::size_t i = 0; i < n;)
	{
		const double r = std::abs(rate[i]);
		const bool turn = r > o.turn_rate_dps, straight = r < o.straight_rate_dps;
		std::size_t j = i + 1;
		while (j < n && (std::abs(rate[j]) > o.turn_rate_dps) == turn && (std::abs(rate[j]) < o.straight_rate_dps) == straight)
			j++;
		const double t0 = t[i], t1 = t[j - 1];
		if (turn && t1 > t0)
			seg.turns.push_back({t0, t1});
		else if (straight && t1 - t0 - 2 * o.margin_s >= o.min_straight_s)
			seg.straights.push_back({t0 + o.margin_s, t1 - o.margin_s});
		i = j;
	}
	// A turn's heading change is measured between quiet instants: extend each turn to the
	// neighbouring samples below straight_rate (the transition belongs to the turn).
	for (auto& tr : seg.turns)
	{
		std::size_t a = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), tr.t0_s) - t.begin());
		std::size_t b = static_cast<std::size_t>(std::lower_bound(t.begin(), t.end(), tr.t1_s) - t.begin());
		while (a > 0 && std::abs(rate[a]) >= o.straight_rate_dps) a--;
		while (b + 1 < n && std::abs(rate[b]) >= o.straight_rate_dps) b++;
		tr.t0_s = t[a];
		tr.t1_s = t[b];
	}
	// merge turns that now overlap
	std::vector<DriveSegments::Span> merged;
	for (const auto& tr : seg.turns)
	{
		if (!merged.empty() && tr.t0_s <= merged.back().t1_s)
			merged.back().t1_s = std::max(merged.back().t1_s, tr.t1_s);
		else
			merged.push_back(tr);
	}
	seg.turns = merged;
	return seg;
}

HeadingFigures computeHeadingFigures(const std::vector<double>& t_s, const std::vector<double>& err_deg,
									 const Trajectory& truth, const DriveSegments& seg)
{
	if (t_s.size() != err_deg.size() || t_s.size() < 2)
		throw std::invalid_argument("computeHeadingFigures: need >= 2 error samples with times");
	HeadingFigures f;
	const double nan = std::numeric_limits<double>::quiet_NaN();
	double ss = 0;
	for (double e : err_deg)
	{
		ss += e * e;
		f.heading_error_max_deg = std::max(f.heading_error_max_deg, std::abs(e));
	}
	f.heading_error_rms_deg = std::sqrt(ss / static_cast<double>(err_deg.size()));
	f.heading_error_final_deg = std::abs(err_deg.back());

	// Between-turn drift: pooled within-straight slope.
	double sxy = 0, sxx = 0;
	for (const auto& s : seg.straights)
	{
		double st = 0, se = 0;
		std::size_t m = 0;
		for (std::size_t k = 0; k < t_s.size(); k++)
			if (t_s[k] >= s.t0_s && t_s[k] <= s.t1_s)
			{
				st += t_s[k];
				se += err_deg[k];
				m++;
			}
		if (m < 3) continue;
		const double tm = st / static_cast<double>(m), em = se / static_cast<double>(m);
		for (std::size_t k = 0; k < t_s.size(); k++)
			if (t_s[k] >= s.t0_s && t_s[k] <= s.t1_s)
			{
				sxy += (t_s[k] - tm) * (err_deg[k] - em);
				sxx += (t_s[k] - tm) * (t_s[k] - tm);
			}
		f.straights++;
		f.straight_time_s += s.t1_s - s.t0_s;
	}
	const double drift_dps = sxx > 0 ? sxy / sxx : nan;
	f.heading_drift_between_turns_dph = drift_dps * kSecondsPerHour;

	// Turn scale factor: error change per turn vs heading change, drift over the turn removed.
	const std::vector<double> yaw = unwrappedYaw_deg(truth);
	std::vector<double> tt(truth.size());
	for (std::size_t i = 0; i < truth.size(); i++) tt[i] = truth[i].t_s;
	double sab = 0, saa = 0;
	for (const auto& tr : seg.turns)
	{
		if (tr.t0_s < t_s.front() || tr.t1_s > t_s.back()) continue;
		const double dpsi = interpAt(tt, yaw, tr.t1_s) - interpAt(tt, yaw, tr.t0_s);
		double de = interpAt(t_s, err_deg, tr.t1_s) - interpAt(t_s, err_deg, tr.t0_s);
		if (std::isfinite(drift_dps)) de -= drift_dps * (tr.t1_s - tr.t0_s);
		sab += de * dpsi;
		saa += dpsi * dpsi;
		f.turns++;
		f.turned_deg += std::abs(dpsi);
	}
	f.turn_scale_factor_ppm = saa > 0 ? 1e6 * sab / saa : nan;
	return f;
}

}  // namespace mrpt_fog::nav
