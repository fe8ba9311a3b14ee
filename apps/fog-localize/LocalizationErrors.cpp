/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "LocalizationErrors.h"

#include <mrpt_fog_nav/Rotation.h>

#include <algorithm>
#include <cmath>

namespace mrpt_fog::localize
{
RunErrors computeErrors(const MclRun& run, const nav::Trajectory& truth, const std::vector<Stretch>& stretches,
						double divergence_m, double recover_s)
{
	RunErrors e;
	for (std::size_t k = 0; k < run.t_s.size(); ++k)
	{
		const nav::TrajectoryPoint p = nav::interpolate(truth, run.t_s[k]);
		const double pos = std::hypot(run.x_m[k] - p.x_m, run.y_m[k] - p.y_m);
		e.t_s.push_back(run.t_s[k]);
		e.position_m.push_back(pos);
		e.heading_deg.push_back(nav::wrapToPi(run.yaw_rad[k] - p.yaw_rad) * 180.0 / M_PI);
		e.heading_spread_deg.push_back(k < run.yaw_std_rad.size() ? run.yaw_std_rad[k] * 180.0 / M_PI : NAN);
		const bool wheel_only = k < run.wheel_only.size() && run.wheel_only[k];
		e.wheel_only.push_back(wheel_only);
		const Stretch& s = stretchAt(stretches, run.t_s[k]);
		if (!wheel_only && s.kind == StretchKind::Urban && run.t_s[k] > s.t_begin_s + recover_s)
		{
			e.max_urban_error_m = std::max(e.max_urban_error_m, pos);
			if (pos > divergence_m) e.diverged = true;
		}
	}
	return e;
}

GyroSummary summarize(const std::vector<RunErrors>& seeds, const std::vector<Stretch>& stretches)
{
	GyroSummary g;
	std::vector<double> s2(stretches.size(), 0), h2(stretches.size(), 0), mx(stretches.size(), 0);
	std::vector<std::size_t> n(stretches.size(), 0);
	double all2 = 0;
	std::size_t all_n = 0;
	for (const auto& r : seeds)
	{
		double open2 = 0;
		std::size_t open_n = 0;
		for (std::size_t k = 0; k < r.t_s.size(); ++k)
		{
			if (k < r.wheel_only.size() && r.wheel_only[k]) continue;  // gyro off: in WheelOnlyFigures
			const Stretch& s = stretchAt(stretches, r.t_s[k]);
			const std::size_t i = static_cast<std::size_t>(&s - stretches.data());
			s2[i] += r.position_m[k] * r.position_m[k];
			h2[i] += r.heading_deg[k] * r.heading_deg[k];
			mx[i] = std::max(mx[i], r.position_m[k]);
			++n[i];
			all2 += r.position_m[k] * r.position_m[k];
			++all_n;
			if (s.kind == StretchKind::Open)
			{
				open2 += r.position_m[k] * r.position_m[k];
				++open_n;
			}
		}
		g.open_rms_per_seed_m.push_back(open_n ? std::sqrt(open2 / open_n) : NAN);
		g.diverged_runs += r.diverged ? 1 : 0;
	}
	std::map<StretchKind, double> k2, kh2;
	std::map<StretchKind, std::size_t> kn;
	double worst = -1;
	for (std::size_t i = 0; i < stretches.size(); ++i)
	{
		StretchFigure f;
		f.index = i;
		f.position_rms_m = n[i] ? std::sqrt(s2[i] / n[i]) : NAN;
		f.heading_rms_deg = n[i] ? std::sqrt(h2[i] / n[i]) : NAN;
		f.position_max_m = mx[i];
		g.stretches.push_back(f);
		k2[stretches[i].kind] += s2[i];
		kh2[stretches[i].kind] += h2[i];
		kn[stretches[i].kind] += n[i];
		if (stretches[i].kind == StretchKind::Open && f.position_rms_m > worst)
		{
			worst = f.position_rms_m;
			g.worst_open = i;
		}
	}
	for (const auto& [kind, sum] : k2)
	{
		g.position_rms_m[kind] = kn[kind] ? std::sqrt(sum / kn[kind]) : NAN;
		g.heading_rms_deg[kind] = kn[kind] ? std::sqrt(kh2[kind] / kn[kind]) : NAN;
	}
	g.position_rms_all_m = all_n ? std::sqrt(all2 / all_n) : NAN;
	return g;
}

std::vector<HeadingBudget> headingBudget(const std::vector<RunErrors>& seeds, const std::vector<Stretch>& stretches,
										 const std::vector<double>& odo_err_deg)
{
	std::vector<HeadingBudget> out;
	if (seeds.empty()) return out;
	const std::vector<double>& t = seeds.front().t_s;
	for (std::size_t i = 0; i < stretches.size(); ++i)
	{
		const Stretch& s = stretches[i];
		if (s.kind != StretchKind::Open) continue;
		std::size_t a = 0;
		while (a < t.size() && t[a] < s.t_begin_s) ++a;
		std::size_t b = a;
		while (b + 1 < t.size() && t[b + 1] <= s.t_end_s) ++b;
		if (a >= t.size() || b <= a || odo_err_deg.size() != t.size()) continue;
		HeadingBudget h;
		h.index = i;
		h.duration_s = t[b] - t[a];
		h.length_m = s.s_end_m - s.s_begin_m;
		h.gyro_drift_deg = odo_err_deg[b] - odo_err_deg[a];
		double e2 = 0, em = 0, p2 = 0, w2 = 0, f2 = 0, sp2 = 0;
		for (const auto& r : seeds)
		{
			const double e0 = r.heading_deg[a], e1 = r.heading_deg[b];
			e2 += e0 * e0;
			em += e0;
			p2 += r.position_m[a] * r.position_m[a];
			if (a < r.heading_spread_deg.size()) sp2 += r.heading_spread_deg[a] * r.heading_spread_deg[a];
			const double w = e1 - e0 - h.gyro_drift_deg;
			w2 += w * w;
			f2 += e1 * e1;
		}
		const double n = static_cast<double>(seeds.size());
		h.entry_heading_rms_deg = std::sqrt(e2 / n);
		h.entry_heading_mean_deg = em / n;
		h.entry_heading_spread_rms_deg = std::sqrt(sp2 / n);
		h.entry_position_rms_m = std::sqrt(p2 / n);
		h.walk_rms_deg = std::sqrt(w2 / n);
		h.end_heading_rms_deg = std::sqrt(f2 / n);
		out.push_back(h);
	}
	return out;
}

HeadingRelevance headingRelevance(const GyroSummary& raw, const std::vector<HeadingBudget>& raw_budget,
								  const GyroSummary& ideal, const std::vector<HeadingBudget>& ideal_budget)
{
	HeadingRelevance out;
	const auto r = raw.position_rms_m.find(StretchKind::Open), i = ideal.position_rms_m.find(StretchKind::Open);
	if (r != raw.position_rms_m.end() && i != ideal.position_rms_m.end() && r->second > 0)
		out.ideal_to_raw_position_rms = i->second / r->second;
	out.heading_matters = out.ideal_to_raw_position_rms <= HeadingRelevance::kMaxReachableRatio;
	for (const HeadingBudget& hr : raw_budget)
		for (const HeadingBudget& hi : ideal_budget)
		{
			if (hi.index != hr.index) continue;
			FieldRelevance f;
			f.index = hr.index;
			f.raw_gyro_drift_deg = hr.gyro_drift_deg;
			f.ideal_entry_heading_rms_deg = hi.entry_heading_rms_deg;
			f.gyro_dominates = std::abs(hr.gyro_drift_deg) > hi.entry_heading_rms_deg;
			if (hr.index < raw.stretches.size() && hr.index < ideal.stretches.size() &&
				raw.stretches[hr.index].position_rms_m > 0)
				f.ideal_to_raw_position_rms =
					ideal.stretches[hr.index].position_rms_m / raw.stretches[hr.index].position_rms_m;
			out.fields.push_back(f);
		}
	return out;
}

WheelOnlyFigures wheelOnlyFigures(const std::vector<RunErrors>& seeds)
{
	WheelOnlyFigures f;
	if (!seeds.empty())
		for (bool w : seeds.front().wheel_only) f.steps += w;
	double p2 = 0, h2 = 0, mx = 0;
	std::size_t n = 0;
	for (const auto& r : seeds)
		for (std::size_t k = 0; k < r.t_s.size() && k < r.wheel_only.size(); ++k)
			if (r.wheel_only[k])
			{
				p2 += r.position_m[k] * r.position_m[k];
				h2 += r.heading_deg[k] * r.heading_deg[k];
				mx = std::max(mx, r.position_m[k]);
				++n;
			}
	if (n > 0) f.position_rms_m = std::sqrt(p2 / n), f.heading_rms_deg = std::sqrt(h2 / n), f.position_max_m = mx;
	return f;
}

std::map<StretchKind, double> overlapByKind(const std::vector<Stretch>& stretches, double t0, double t1)
{
	std::map<StretchKind, double> out;
	for (const auto& s : stretches)
	{
		const double a = std::max(t0, s.t_begin_s), b = std::min(t1, s.t_end_s);
		if (b > a) out[s.kind] += b - a;
	}
	return out;
}

}  // namespace mrpt_fog::localize
