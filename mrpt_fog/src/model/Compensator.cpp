/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/Compensator.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
std::string describeLayout(const std::vector<ThermistorInfo>& layout)
{
	std::ostringstream o;
	for (std::size_t i = 0; i < layout.size(); i++)
		o << (i ? ", " : "") << layout[i].name << " " << toString(layout[i].side) << " " << layout[i].angle_deg << "deg";
	return layout.empty() ? "(no thermistors)" : o.str();
}
}  // namespace

Compensator::Compiled Compensator::compile(const BiasModel& m, const std::vector<std::string>& names)
{
	Compiled c;
	const auto& fs = m.features;
	const auto chan = [&](const std::string& n) {
		const auto it = std::find(names.begin(), names.end(), n);
		if (it == names.end()) throw std::invalid_argument("calibration model uses thermistor '" + n + "' not in the main model");
		return static_cast<int>(it - names.begin());
	};
	const std::size_t ns = fs.signals().size();
	c.poly.assign(ns, std::array<double, 6>{});
	c.degree.assign(ns, 0);
	for (std::size_t s = 0; s < ns; s++)
	{
		const auto& sig = fs.signals()[s];
		const auto& nm = fs.normalisation()[s];
		c.kind.push_back(static_cast<int>(sig.kind));
		c.a.push_back(chan(sig.a));
		c.b.push_back(sig.isDifference() ? chan(sig.b) : 0);
		c.centre.push_back(nm.centre);
		c.inv_scale.push_back(1.0 / nm.scale);
		c.lo.push_back(nm.min);
		c.hi.push_back(nm.max);
	}
	for (std::size_t i = 0; i < fs.termCount(); i++)
	{
		const int s = fs.termSignal(i);
		if (s < 0)
			c.c0 += m.coef_dph.at(i);
		else
		{
			const int k = fs.terms()[i].power;
			c.poly[s][k] += m.coef_dph.at(i);
			c.degree[s] = std::max(c.degree[s], k);
		}
	}
	return c;
}

std::vector<bool> Compensator::usesMask(const BiasModel& m, const std::vector<std::string>& names)
{
	std::vector<bool> u(names.size(), false);
	for (std::size_t c = 0; c < names.size(); c++) u[c] = m.features.references(names[c]);
	return u;
}

Compensator::Compensator(const Calibration& cal, const std::vector<ThermistorInfo>& layout)
	: window_s_(cal.rate_estimator.window_s),
	  mean_bias_dph_(cal.mean_bias_dph),
	  tracker_(1, cal.rate_estimator.window_s)
{
	cal.rate_estimator.validate();
	if (cal.rate_estimator.kind != "causal")
		throw std::invalid_argument("calibration was fitted with the non-causal rate estimator " +
									cal.rate_estimator.describe() +
									": it cannot run in real time; refit with the causal estimator");
	// Channels: every thermistor used by the main model or a fallback.
	std::vector<std::string> names = cal.model.features.thermistors();
	for (const auto& fb : cal.fallbacks)
		for (const auto& n : fb.features.thermistors())
			if (std::find(names.begin(), names.end(), n) == names.end()) names.push_back(n);
	tracker_ = CausalRateTracker(names.size(), cal.rate_estimator.window_s);
	for (const auto& n : names)
	{
		const ThermistorInfo* want = nullptr;
		for (const auto& t : cal.layout)
			if (t.name == n) want = &t;
		int col = -1;
		for (std::size_t i = 0; i < layout.size(); i++)
			if (layout[i].name == n) col = static_cast<int>(i);
		const bool ok = col >= 0 && (!want || (layout[col].side == want->side && layout[col].angle_deg == want->angle_deg));
		if (!ok)
			throw std::invalid_argument("calibration was made for another sensor layout: it needs thermistor " + n +
										(want ? std::string(" (") + toString(want->side) + " " +
													std::to_string(want->angle_deg) + "deg)"
											  : std::string()) +
										"; calibration layout: " + describeLayout(cal.layout) +
										"; data layout: " + describeLayout(layout));
		channel_col_.push_back(col);
	}
	models_.push_back(compile(cal.model, names));
	uses_.push_back(usesMask(cal.model, names));
	for (const auto& n : names)
	{
		const BiasModel* fb = cal.fallbackFor(n);
		has_fallback_.push_back(fb != nullptr);
		models_.push_back(fb ? compile(*fb, names) : Compiled{});
		uses_.push_back(fb ? usesMask(*fb, names) : std::vector<bool>(names.size(), true));
	}
	missing_.assign(names.size(), false);
	temp_.assign(names.size(), 0.0);
	rate_.assign(names.size(), 0.0);
	x_.assign(names.size(), 0.0);
}

void Compensator::reset()
{
	tracker_.reset();
	counters_ = {};
	last_model_ = 0;
	first_ = true;
}

double Compensator::evaluate(const Compiled& m, int& clamped) const
{
	double sum = m.c0;
	const std::size_t ns = m.kind.size();
	for (std::size_t s = 0; s < ns; s++)
	{
		double v;
		switch (m.kind[s])
		{
			case 0: v = temp_[m.a[s]]; break;
			case 1: v = rate_[m.a[s]]; break;
			case 2: v = temp_[m.a[s]] - temp_[m.b[s]]; break;
			default: v = rate_[m.a[s]] - rate_[m.b[s]]; break;
		}
		if (v < m.lo[s])
		{
			v = m.lo[s];
			clamped++;
		}
		else if (v > m.hi[s])
		{
			v = m.hi[s];
			clamped++;
		}
		const double z = (v - m.centre[s]) * m.inv_scale[s];
		const auto& p = m.poly[s];
		double h = p[m.degree[s]];
		for (int k = m.degree[s] - 1; k >= 1; k--) h = h * z + p[k];
		sum += h * z;
	}
	return sum;
}

Compensator::Output Compensator::step(double time_s, double raw_dph, const double* temp_C)
{
	const std::size_t nc = channel_col_.size();
	for (std::size_t c = 0; c < nc; c++) x_[c] = temp_C[channel_col_[c]];
	tracker_.push(time_s, x_.data());
	bool warm = false;
	for (std::size_t c = 0; c < nc; c++)
	{
		temp_[c] = x_[c];
		rate_[c] = tracker_.rate(c);
		missing_[c] = std::isnan(temp_[c]) || std::isnan(rate_[c]);
		if (missing_[c]) temp_[c] = rate_[c] = 0.0;  // never read by the model in use
	}
	// Main model unless it needs a missing channel; then the fallback without that channel if
	// exactly one is missing and the fallback needs no other missing channel; else none.
	const auto usable = [&](int m) {
		for (std::size_t c = 0; c < nc; c++)
			if (missing_[c] && uses_[m][c]) return false;
		return true;
	};
	int model = -1;
	if (usable(0))
		model = 0;
	else
		for (std::size_t c = 0; c < nc; c++)
			if (missing_[c] && uses_[0][c])
			{
				if (has_fallback_[c] && usable(1 + static_cast<int>(c))) model = 1 + static_cast<int>(c);
				break;
			}
	if (model >= 0)
		for (std::size_t c = 0; c < nc; c++)
			if (uses_[model][c] && tracker_.coveredSpan_s(c) < 0.5 * window_s_) warm = true;
	Output out;
	int clamped = 0;
	if (model >= 0)
		out.bias_dph = evaluate(models_[model], clamped);
	else
		out.bias_dph = mean_bias_dph_;
	out.compensated_dph = raw_dph - out.bias_dph;
	out.model = model;
	if (model > 0) out.flags |= compflags::Fallback;
	if (model < 0) out.flags |= compflags::NoModel;
	if (clamped) out.flags |= compflags::Clamped;
	if (warm) out.flags |= compflags::RateWarmup;
	counters_.samples++;
	counters_.fallback_samples += model > 0;
	counters_.no_model_samples += model < 0;
	counters_.clamped_samples += clamped > 0;
	counters_.clamped_signals += static_cast<std::size_t>(clamped);
	counters_.warmup_samples += warm;
	if (!first_ && model != last_model_) counters_.model_switches++;
	last_model_ = model;
	first_ = false;
	return out;
}

CompensatedSeries compensate(const Calibration& cal, const FogSeries& series)
{
	series.validate();
	const int axis = static_cast<int>(cal.axis);
	if (!series.has_axis[axis])
		throw std::invalid_argument(std::string("the log has no ") + axisLetter(cal.axis) +
									" axis, which the calibration is for");
	Compensator comp(cal, series.thermistors);
	CompensatedSeries out;
	const std::size_t n = series.size();
	out.time_s = series.time_s;
	out.raw_dph = series.rate_dph[axis];
	out.bias_dph.resize(n);
	out.compensated_dph.resize(n);
	out.flags.resize(n);
	std::vector<double> temps(series.thermistorCount());
	for (std::size_t k = 0; k < n; k++)
	{
		for (std::size_t i = 0; i < temps.size(); i++) temps[i] = series.temp_C[i][k];
		const auto o = comp.step(series.time_s[k], out.raw_dph[k], temps.data());
		out.bias_dph[k] = o.bias_dph;
		out.compensated_dph[k] = o.compensated_dph;
		out.flags[k] = o.flags;
	}
	out.counters = comp.counters();
	return out;
}

}  // namespace mrpt_fog
