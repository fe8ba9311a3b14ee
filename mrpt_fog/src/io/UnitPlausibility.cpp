/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/io/NumberText.h>
#include <mrpt_fog/io/UnitPlausibility.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>

namespace mrpt_fog
{
namespace
{
constexpr double kEarthRate_dph = 15.041;
constexpr double kMinArw = 2e-5, kMaxArw = 30;  // deg/sqrt(h)
constexpr double kMinTableRate_dph = 100;
constexpr double kMinSlope = 0.5, kMaxSlope = 2;
constexpr double kMinTriadRest_dph = 0.15;
constexpr double kMaxInterval_s = 30, kMinInterval_s = 20e-6;
constexpr double kMaxTemp_C = 150, kMinTemp_C = -150;

std::string num(double v)
{
	char b[32];
	std::snprintf(b, sizeof b, "%.3g", v);
	return b;
}

double median(std::vector<double> v)
{
	if (v.empty()) return NAN;
	const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
	std::nth_element(v.begin(), mid, v.end());
	return *mid;
}

/** Units of one quantity, each with its size in the native unit. */
template <class Unit>
struct UnitScale
{
	Unit unit;
	double native_per_unit;
};

/** Fills the finding's likely unit: the units u != declared whose conversion factor
 * f(u) = native_per_unit(u) / native_per_unit(declared) makes `fits(f)` true, the smallest
 * change (|log f|) first. */
template <class Unit>
void nameCandidates(UnitFinding& f, Unit declared, const std::vector<UnitScale<Unit>>& units,
					const std::function<bool(double)>& fits)
{
	double d = 1;
	for (const auto& u : units)
		if (u.unit == declared) d = u.native_per_unit;
	std::vector<std::pair<double, std::string>> c;
	for (const auto& u : units)
	{
		if (u.unit == declared) continue;
		const double factor = u.native_per_unit / d;
		if (fits(factor)) c.emplace_back(std::abs(std::log(factor)), toString(u.unit));
	}
	std::sort(c.begin(), c.end());
	for (std::size_t i = 0; i < c.size(); i++)
		(i == 0 ? f.likely_unit : f.other_candidates.emplace_back()) = c[i].second;
}

std::vector<UnitScale<RateUnit>> rateUnits()
{
	std::vector<UnitScale<RateUnit>> v;
	for (auto u : {RateUnit::deg_per_h, RateUnit::deg_per_s, RateUnit::rad_per_s, RateUnit::mdeg_per_s})
		v.push_back({u, degPerHourPer(u)});
	return v;
}
std::vector<UnitScale<TimeUnit>> timeUnits()
{
	std::vector<UnitScale<TimeUnit>> v;
	for (auto u : {TimeUnit::s, TimeUnit::ms, TimeUnit::us, TimeUnit::ns}) v.push_back({u, secondsPer(u)});
	return v;
}
}  // namespace

std::string UnitFinding::message() const
{
	std::string m = column + ": declared " + declared_unit + ", but " + evidence;
	if (likely_unit.empty()) return m + ": no unit of the list fits; check the column and its unit";
	m += ": likely " + likely_unit;
	if (!other_candidates.empty())
	{
		m += " (or ";
		for (std::size_t i = 0; i < other_candidates.size(); i++) m += (i ? ", " : "") + other_candidates[i];
		m += ")";
	}
	return m;
}

DeclaredUnits DeclaredUnits::of(const LogFormat& f)
{
	DeclaredUnits d;
	for (int a = 0; a < 3; a++)
		if (f.rates[a])
		{
			d.rate[a] = f.rates[a]->unit;
			d.rate_column[a] = f.rates[a]->column;
		}
	if (f.table_rate) d.table_rate = f.table_rate->unit;
	d.time = f.time_unit;
	d.time_column = f.time.column;
	if (!f.thermistors.empty())
	{
		d.temperature = f.thermistors.front().unit;
		d.temperature_column = f.thermistors.front().column;
		for (const auto& t : f.thermistors)
			if (t.unit != d.temperature) d.temperature_column = "thermistors";
	}
	return d;
}

UnitPlausibility::UnitPlausibility(DeclaredUnits declared) : declared_(std::move(declared)) {}

void UnitPlausibility::add(const FogSample& x, bool gyro_on)
{
	const bool sampled = rows_ < kSampledRows;
	if (sampled && rows_ > 0 && std::isfinite(x.time_s - last_t_)) dt_s_.push_back(x.time_s - last_t_);
	last_t_ = x.time_s;
	rows_++;
	const bool table = std::isfinite(x.table_rate_dph);
	bool all_axes = true;
	for (int a = 0; a < 3; a++)
	{
		const double r = gyro_on ? x.rate_dph[a] : NAN;
		if (!std::isfinite(r))
		{
			has_last_[a] = false;
			all_axes = false;
			continue;
		}
		seen_axis_[a] = true;
		if (sampled && has_last_[a]) abs_diff_[a].push_back(std::abs(r - last_rate_[a]));
		last_rate_[a] = r;
		has_last_[a] = true;
		if (table && std::abs(x.table_rate_dph) >= kMinTableRate_dph)
		{
			const double t = x.table_rate_dph;
			n_[a]++;
			sx_[a] += t;
			sy_[a] += r;
			sxx_[a] += t * t;
			sxy_[a] += t * r;
			syy_[a] += r * r;
		}
	}
	if (all_axes && gyro_on && (!table || std::abs(x.table_rate_dph) < 1))
	{
		for (int a = 0; a < 3; a++) rest_sum_[a] += x.rate_dph[a];
		rest_n_++;
	}
	if (sampled)
		for (double t : x.temp_C)
			if (std::isfinite(t)) temp_C_.push_back(t);
}

std::vector<UnitFinding> UnitPlausibility::findings() const
{
	std::vector<UnitFinding> out;
	const auto rates = rateUnits();
	const double dt_s = median(dt_s_);

	// Time: the sample interval.
	if (std::isfinite(dt_s) && dt_s > 0 && (dt_s > kMaxInterval_s || dt_s < kMinInterval_s))
	{
		UnitFinding f;
		f.quantity = UnitQuantity::Time;
		f.column = declared_.time_column;
		f.declared_unit = toString(declared_.time);
		f.evidence = "the samples are " + num(dt_s) + " s apart (a gyro log is sampled every " + num(kMinInterval_s) +
					 " .. " + num(kMaxInterval_s) + " s)";
		nameCandidates<TimeUnit>(f, declared_.time, timeUnits(), [&](double k) {
			return dt_s * k >= 1e-4 && dt_s * k <= kMaxInterval_s;
		});
		out.push_back(f);
	}

	// Rate noise as an angle random walk (only with a plausible interval: it scales with it).
	const bool interval_ok = std::isfinite(dt_s) && dt_s >= kMinInterval_s && dt_s <= kMaxInterval_s;
	std::array<bool, 3> flagged{};
	for (int a = 0; a < 3; a++)
	{
		if (!interval_ok || abs_diff_[a].size() < 20) continue;
		// Robust sigma of one sample from |differences|: median |d| = 0.6745 sqrt(2) sigma.
		const double sigma = median(abs_diff_[a]) / (0.6745 * std::sqrt(2.0));
		if (!(sigma > 0)) continue;  // quantised output that rarely changes: cannot tell
		const double arw = sigma * std::sqrt(dt_s) / 60;
		if (arw >= kMinArw && arw <= kMaxArw) continue;
		UnitFinding f;
		f.column = declared_.rate_column[a];
		f.declared_unit = toString(declared_.rate[a]);
		f.evidence = "its sample-to-sample noise is an angle random walk of " + num(arw) + " deg/sqrt(h) (any gyro: " +
					 num(kMinArw) + " .. " + num(kMaxArw) + ")";
		if (arw > kMaxArw)
			f.evidence += "; or the time column's unit is too large (this noise grows with the square root of the " +
						  num(dt_s) + " s sample interval)";
		nameCandidates<RateUnit>(f, declared_.rate[a], rates, [&](double k) { return arw * k >= 1e-4 && arw * k <= 3; });
		out.push_back(f);
		flagged[a] = true;
	}

	// Rate table: the slope of the gyro's rate on the table's.
	for (int a = 0; a < 3; a++)
	{
		if (n_[a] < 20 || flagged[a]) continue;
		const double n = n_[a];
		const double vx = sxx_[a] - sx_[a] * sx_[a] / n, vy = syy_[a] - sy_[a] * sy_[a] / n;
		const double cxy = sxy_[a] - sx_[a] * sy_[a] / n;
		if (!(vx > 0) || !(vy > 0)) continue;
		const double corr = cxy / std::sqrt(vx * vy);
		if (std::abs(corr) < 0.9) continue;  // this axis does not see the table (or too noisy to tell)
		const double slope = std::abs(cxy / vx);
		if (slope >= kMinSlope && slope <= kMaxSlope) continue;
		UnitFinding f;
		f.column = declared_.rate_column[a];
		f.declared_unit = toString(declared_.rate[a]);
		f.evidence = "it reads the table's rate times " + num(slope) + " (a gyro reads it times about 1; table unit " +
					 toString(declared_.table_rate) + ")";
		nameCandidates<RateUnit>(f, declared_.rate[a], rates, [&](double k) {
			return slope * k >= kMinSlope && slope * k <= kMaxSlope;
		});
		out.push_back(f);
		flagged[a] = true;
	}

	// Earth rate on a three-axis gyro at rest.
	if (seen_axis_[0] && seen_axis_[1] && seen_axis_[2] && rest_n_ >= 100 && !flagged[0] && !flagged[1] && !flagged[2])
	{
		double norm2 = 0;
		for (int a = 0; a < 3; a++) norm2 += std::pow(rest_sum_[a] / static_cast<double>(rest_n_), 2);
		const double norm = std::sqrt(norm2);
		if (norm < kMinTriadRest_dph && declared_.rate[0] == declared_.rate[1] && declared_.rate[1] == declared_.rate[2])
		{
			UnitFinding f;
			f.column = declared_.rate_column[0] + ", " + declared_.rate_column[1] + ", " + declared_.rate_column[2];
			f.declared_unit = toString(declared_.rate[0]);
			f.evidence = "the three axes' mean rate is " + num(norm) + " deg/h (Earth's rotation alone is " +
						 num(kEarthRate_dph) + " deg/h)";
			nameCandidates<RateUnit>(f, declared_.rate[0], rates, [&](double k) { return norm * k >= 1 && norm * k <= 100; });
			out.push_back(f);
		}
	}

	// Temperature.
	const double temp_C = median(temp_C_);
	if (std::isfinite(temp_C) && (temp_C > kMaxTemp_C || temp_C < kMinTemp_C))
	{
		UnitFinding f;
		f.quantity = UnitQuantity::Temperature;
		f.column = declared_.temperature_column;
		f.declared_unit = toString(declared_.temperature);
		f.evidence = "the median reading is " + num(temp_C) + " degC (a gyro works between -80 and 150 degC)";
		if (declared_.temperature == TemperatureUnit::C && temp_C - 273.15 >= -80 && temp_C - 273.15 <= 150)
			f.likely_unit = "K";
		if (declared_.temperature == TemperatureUnit::K && temp_C + 273.15 >= -80 && temp_C + 273.15 <= 150)
			f.likely_unit = "C";
		out.push_back(f);
	}
	return out;
}

std::vector<UnitFinding> judgeUnits(const FogSeries& s, const DeclaredUnits& declared)
{
	UnitPlausibility p(declared);
	FogSample x;
	x.temp_C.resize(s.thermistorCount());
	for (std::size_t k = 0; k < s.size(); k++)
	{
		x.time_s = s.time_s[k];
		for (int a = 0; a < 3; a++) x.rate_dph[a] = s.has_axis[a] ? s.rate_dph[a][k] : NAN;
		for (std::size_t i = 0; i < x.temp_C.size(); i++) x.temp_C[i] = s.temp_C[i][k];
		x.table_rate_dph = s.table_rate_dph.empty() ? NAN : s.table_rate_dph[k];
		p.add(x, s.power.empty() || s.power[k] != 0.0);
	}
	return p.findings();
}

}  // namespace mrpt_fog
