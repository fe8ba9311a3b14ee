/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/discrepancy/RunSegmenter.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>

namespace mrpt_fog::discrepancy
{
const char* toString(SegmentType t)
{
	switch (t)
	{
		case SegmentType::RampUp: return "ramp_up";
		case SegmentType::RampDown: return "ramp_down";
		case SegmentType::Soak: return "soak";
		case SegmentType::Step: return "step";
		case SegmentType::PowerOn: return "power_on";
		case SegmentType::RateTable: return "rate_table";
		case SegmentType::Field: return "field";
		case SegmentType::PowerOff: return "power_off";
	}
	return "?";
}

namespace
{
constexpr EnumName<TemperatureDirection> kDirections[] = {{TemperatureDirection::Steady, "steady"},
															 {TemperatureDirection::Heating, "heating"},
															 {TemperatureDirection::Cooling, "cooling"}};
}  // namespace

const char* toString(TemperatureDirection d) { return nameIn(kDirections, d, "steady"); }

namespace
{
int bandIndex(double T)
{
	if (!std::isfinite(T)) return -1;
	if (T < -20) return 0;
	if (T < 0) return 1;
	if (T < 20) return 2;
	if (T < 40) return 3;
	return 4;
}

std::string bandOf(double T)
{
	if (T < -20) return "below -20 C";
	if (T < 0) return "between -20 and 0 C";
	if (T < 20) return "between 0 and 20 C";
	if (T < 40) return "between 20 and 40 C";
	return "above 40 C";
}

std::string kindPhrase(SegmentType t, TemperatureDirection dir, bool plural)
{
	const std::string s = plural ? "s" : "";
	switch (t)
	{
		case SegmentType::RampUp: return "heating ramp" + s;
		case SegmentType::RampDown: return "cooling ramp" + s;
		case SegmentType::Step:
			return (dir == TemperatureDirection::Cooling   ? "cooling step"
					: dir == TemperatureDirection::Heating ? "heating step"
														   : "temperature step") +
				   s;
		case SegmentType::Soak: return "soak" + s;
		case SegmentType::PowerOn: return "power-on transient" + s;
		case SegmentType::RateTable: return "rate-table segment" + s;
		case SegmentType::Field: return "field segment" + s;
		case SegmentType::PowerOff: return "power-off stretch" + std::string(plural ? "es" : "");
	}
	return "segment" + s;
}

/** Thermal label of a moving stretch [b, e): a ramp holds its rate (|rate| >= 0.8 x peak without a break
 * for at least plateau_s and 30 % of the stretch), a step's rate decays right after its peak. */
SegmentType classifyMoving(const RunSignals& s, std::size_t b, std::size_t e, double plateau_s)
{
	double peak = 0;
	for (std::size_t k = b; k < e; ++k) peak = std::max(peak, std::fabs(s.dtemp_dt_Cpm[k]));
	double run = 0, longest = 0;  // longest contiguous time near the peak rate
	for (std::size_t k = b; k < e; ++k)
	{
		run = std::fabs(s.dtemp_dt_Cpm[k]) >= 0.8 * peak ? run + s.dt_s : 0.0;
		longest = std::max(longest, run);
	}
	const double duration = double(e - b) * s.dt_s;
	if (longest < std::max(plateau_s, 0.3 * duration)) return SegmentType::Step;
	return s.dtemp_dt_Cpm[(b + e) / 2] > 0 ? SegmentType::RampUp : SegmentType::RampDown;
}
}  // namespace

std::string Segment::describe() const
{
	return kindPhrase(type, direction, false) + " " + band;
}

std::vector<Segment> segmentRun(const RunSignals& s, const SegmentationOptions& opt)
{
	const std::size_t n = s.size();
	// 1. thermal label per sample: 0 soak, +1 heating, -1 cooling
	std::vector<int> dir(n, 0);
	for (std::size_t k = 0; k < n; ++k)
	{
		const double r = s.dtemp_dt_Cpm[k];
		if (std::fabs(r) >= opt.moving_rate_Cpm) dir[k] = r > 0 ? 1 : -1;
	}
	std::vector<SegmentType> lab(n, SegmentType::Soak);
	for (std::size_t k = 0; k < n;)
	{
		std::size_t e = k;
		while (e < n && dir[e] == dir[k]) ++e;
		if (dir[k] != 0) std::fill(lab.begin() + long(k), lab.begin() + long(e), classifyMoving(s, k, e, opt.ramp_plateau_s));
		k = e;
	}
	// 2. overlays by priority
	std::size_t on = 0;
	for (std::size_t k = 0; k < n; ++k)
	{
		if (s.has_table && std::fabs(s.table_rate_dph[k]) > opt.table_threshold_dph) lab[k] = SegmentType::RateTable;
		else if (s.has_field && std::fabs(s.field_uT[k]) > opt.field_threshold_uT) lab[k] = SegmentType::Field;
		if (s.has_power)
		{
			while (on + 1 < s.power_on_s.size() && s.power_on_s[on + 1] <= s.time_s[k]) ++on;
			// only after a turn-on seen in the run (a run that starts powered has no known turn-on)
			if (!s.power_on_s.empty() && s.power_on_s[on] > s.time_s.front() && s.time_s[k] >= s.power_on_s[on] &&
				s.time_s[k] - s.power_on_s[on] < opt.power_on_transient_s)
				lab[k] = SegmentType::PowerOn;
			if (s.power[k] < 0.5) lab[k] = SegmentType::PowerOff;
		}
	}
	// 3. run-length segments, short ones merged into the previous one; a step keeps the sign of
	// its stretch (a cooling step is never merged into a heating one)
	std::vector<int> band(n);
	for (std::size_t k = 0; k < n; ++k)
		band[k] = bandIndex(s.temp_mean_C[k]) * 4 + (lab[k] == SegmentType::Step ? dir[k] + 1 : 3);
	std::vector<Segment> segs;
	for (std::size_t k = 0; k < n;)
	{
		std::size_t e = k;
		while (e < n && lab[e] == lab[k] && band[e] == band[k]) ++e;
		const double dur = s.time_s[e - 1] - s.time_s[k] + s.dt_s;
		if (!segs.empty() && dur < opt.min_segment_s)
			segs.back().end = e;
		else
		{
			Segment g;
			g.type = lab[k];
			g.begin = k;
			g.end = e;
			segs.push_back(g);
		}
		k = e;
	}
	// merge neighbours that ended up with the same type
	std::vector<Segment> merged;
	for (const auto& g : segs)
	{
		if (!merged.empty() && merged.back().type == g.type && band[merged.back().begin] == band[g.begin])
			merged.back().end = g.end;
		else
			merged.push_back(g);
	}
	for (auto& g : merged)
	{
		g.t_start_s = s.time_s[g.begin];
		g.t_end_s = s.time_s[g.end - 1] + s.dt_s;
		double sT = 0, sR = 0;
		std::size_t m = 0;
		for (std::size_t k = g.begin; k < g.end; ++k)
			if (std::isfinite(s.temp_mean_C[k]))
			{
				sT += s.temp_mean_C[k];
				sR += s.dtemp_dt_Cpm[k];
				++m;
			}
		g.mean_temp_C = m ? sT / m : NAN;
		g.mean_rate_Cpm = m ? sR / m : 0.0;
		g.band = m ? bandOf(g.mean_temp_C) : "unknown band";
		using Dir = TemperatureDirection;
		g.direction = std::fabs(g.mean_rate_Cpm) < opt.moving_rate_Cpm ? Dir::Steady
					  : g.mean_rate_Cpm > 0							   ? Dir::Heating
																	   : Dir::Cooling;
		if (g.type == SegmentType::RampUp) g.direction = Dir::Heating;
		if (g.type == SegmentType::RampDown) g.direction = Dir::Cooling;
		if (g.type == SegmentType::Step && dir[g.begin] != 0) g.direction = dir[g.begin] > 0 ? Dir::Heating : Dir::Cooling;
	}
	return merged;
}

SegmentRanking rankSegments(const std::vector<Segment>& segments, const Eigen::VectorXd& r,
							const std::vector<unsigned char>& rows)
{
	SegmentRanking out;
	double total = 0;
	std::size_t totalN = 0;
	for (std::size_t k = 0; k < rows.size(); ++k)
		if (rows[k])
		{
			total += r(static_cast<Eigen::Index>(k)) * r(static_cast<Eigen::Index>(k));
			++totalN;
		}
	out.run_rms_dph = totalN ? std::sqrt(total / totalN) : 0.0;
	struct Acc
	{
		double e = 0;
		std::size_t n = 0, segs = 0;
	};
	std::map<std::string, Acc> acc;
	std::vector<std::string> order;
	for (auto g : segments)
	{
		double e = 0;
		std::size_t m = 0;
		for (std::size_t k = g.begin; k < g.end && k < rows.size(); ++k)
			if (rows[k])
			{
				e += r(static_cast<Eigen::Index>(k)) * r(static_cast<Eigen::Index>(k));
				++m;
			}
		g.usable = m;
		g.rms_dph = m ? std::sqrt(e / m) : 0.0;
		g.energy_share = total > 0 ? e / total : 0.0;
		g.time_share = totalN ? double(m) / totalN : 0.0;
		out.ranked.push_back(g);
		if (m == 0) continue;
		const std::string key = kindPhrase(g.type, g.direction, true) + " " + g.band;
		if (!acc.count(key)) order.push_back(key);
		acc[key].e += e;
		acc[key].n += m;
		acc[key].segs += 1;
	}
	std::stable_sort(out.ranked.begin(), out.ranked.end(),
					 [](const Segment& a, const Segment& b) { return a.energy_share > b.energy_share; });
	for (const auto& key : order)
	{
		const auto& a = acc[key];
		SegmentGroup gr;
		gr.description = key;
		gr.rms_dph = std::sqrt(a.e / a.n);
		gr.energy_share = total > 0 ? a.e / total : 0.0;
		gr.time_share = totalN ? double(a.n) / totalN : 0.0;
		gr.segments = a.segs;
		out.groups.push_back(gr);
	}
	std::stable_sort(out.groups.begin(), out.groups.end(),
					 [](const SegmentGroup& a, const SegmentGroup& b) { return a.rms_dph > b.rms_dph; });
	for (const auto& g : out.groups)
	{
		if (g.time_share < 0.02) continue;
		char buf[400];
		std::snprintf(buf, sizeof buf,
					  "The residual is largest during %s (RMS %.3g deg/h, %.1f x the run's %.3g deg/h; %.0f %% of the "
					  "residual energy in %.0f %% of the time).",
					  g.description.c_str(), g.rms_dph, out.run_rms_dph > 0 ? g.rms_dph / out.run_rms_dph : 0.0,
					  out.run_rms_dph, 100 * g.energy_share, 100 * g.time_share);
		out.sentence = buf;
		break;
	}
	if (out.sentence.empty()) out.sentence = "No segment stands out.";
	return out;
}

}  // namespace mrpt_fog::discrepancy
