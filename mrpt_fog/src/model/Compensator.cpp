/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/Compensator.h>

#include <algorithm>
#include <limits>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
std::string degText(double a)
{
	std::ostringstream o;
	o << a;
	return o.str();
}

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
	// degree of each signal
	std::vector<int> degree(fs.signals().size(), 0);
	for (std::size_t i = 0; i < fs.termCount(); i++)
		if (fs.termSignal(i) >= 0)
			degree[fs.termSignal(i)] = std::max(degree[fs.termSignal(i)], fs.terms()[i].power);
	const std::size_t nc = names.size();
	const double inf = std::numeric_limits<double>::infinity();
	ChannelKernel& K = c.kernel;
	K.t_centre.assign(nc, 0.0);
	K.t_inv.assign(nc, 0.0);
	K.t_lo.assign(nc, -inf);
	K.t_hi.assign(nc, inf);
	K.t_p.assign(5 * nc, 0.0);
	K.r_centre.assign(nc, 0.0);
	K.r_inv.assign(nc, 0.0);
	K.r_lo.assign(nc, -inf);
	K.r_hi.assign(nc, inf);
	K.r_p.assign(3 * nc, 0.0);
	for (std::size_t s = 0; s < fs.signals().size(); s++)
	{
		const auto& sig = fs.signals()[s];
		if (sig.isDifference()) continue;
		const auto& nm = fs.normalisation()[s];
		const int ch = chan(sig.a);
		const bool t = sig.kind == SignalKind::Temp;
		(t ? K.t_centre : K.r_centre)[ch] = nm.centre;
		(t ? K.t_inv : K.r_inv)[ch] = 1.0 / nm.scale;
		(t ? K.t_lo : K.r_lo)[ch] = nm.min;
		(t ? K.t_hi : K.r_hi)[ch] = nm.max;
		c.uses |= 1u << ch;
	}
	std::vector<int> group_of(fs.signals().size()), index_in(fs.signals().size());
	for (int kind = 2; kind < 4; kind++)
	{
		SignalGroup g;
		g.kind = kind;
		for (std::size_t s = 0; s < fs.signals().size(); s++)
		{
			const auto& sig = fs.signals()[s];
			if (static_cast<int>(sig.kind) != kind) continue;
			const auto& nm = fs.normalisation()[s];
			group_of[s] = static_cast<int>(c.groups.size());
			index_in[s] = static_cast<int>(g.a.size());
			g.a.push_back(chan(sig.a));
			g.b.push_back(sig.isDifference() ? chan(sig.b) : 0);
			g.centre.push_back(nm.centre);
			g.inv_scale.push_back(1.0 / nm.scale);
			g.lo.push_back(nm.min);
			g.hi.push_back(nm.max);
			g.degree = std::max(g.degree, degree[s]);
			c.uses |= 1u << g.a.back();
			if (sig.isDifference()) c.uses |= 1u << g.b.back();
		}
		if (g.a.empty()) continue;
		g.p.assign(static_cast<std::size_t>(g.degree + 1) * g.a.size(), 0.0);
		c.groups.push_back(std::move(g));
	}
	for (std::size_t i = 0; i < fs.termCount(); i++)
	{
		const int s = fs.termSignal(i);
		if (s < 0)
		{
			c.c0 += m.coef_dph.at(i);
			continue;
		}
		const auto& sig = fs.signals()[s];
		if (!sig.isDifference())
		{
			const int ch = chan(sig.a);
			const int k = fs.terms()[i].power;
			(sig.kind == SignalKind::Temp ? K.t_p : K.r_p)[static_cast<std::size_t>(k - 1) * nc + ch] += m.coef_dph.at(i);
			continue;
		}
		SignalGroup& g = c.groups[group_of[s]];
		g.p[static_cast<std::size_t>(fs.terms()[i].power) * g.a.size() + static_cast<std::size_t>(index_in[s])] +=
			m.coef_dph.at(i);
	}
	return c;
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
	if (names.size() > 32) throw std::invalid_argument("compensator: at most 32 thermistors are supported");
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
										(want ? std::string(" (") + toString(want->side) + " " + degText(want->angle_deg) + "deg)"
											  : std::string()) +
										"; calibration layout: " + describeLayout(cal.layout) +
										"; data layout: " + describeLayout(layout));
		channel_col_.push_back(col);
	}
	models_.push_back(compile(cal.model, names));
	for (const auto& n : names)
	{
		const BiasModel* fb = cal.fallbackFor(n);
		has_fallback_.push_back(fb != nullptr);
		models_.push_back(fb ? compile(*fb, names) : Compiled{});
	}
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

namespace
{
/** Clamp, normalise and Horner-evaluate the n signals of one group; D = the group's degree
 * (compile-time, so the Horner loop unrolls). Returns the group's contribution [deg/h]. */
template <int D, bool Diff>
inline double groupSum(const int* a, const int* b, const double* src, const double* lo, const double* hi,
					   const double* centre, const double* inv_scale, const double* p, std::size_t n, int& clamped)
{
	double sum = 0;
	int cl = 0;
	std::size_t i = 0;
	// Four signals in lockstep: their Horner chains are independent, so interleaving them hides
	// the multiply-add latency (and lets the compiler use SIMD).
	for (; i + 4 <= n; i += 4)
	{
		double z[4], h[4];
		for (int j = 0; j < 4; j++)
		{
			double v = Diff ? src[a[i + j]] - src[b[i + j]] : src[a[i + j]];
			cl += (v < lo[i + j]) + (v > hi[i + j]);
			v = v < lo[i + j] ? lo[i + j] : v;
			v = v > hi[i + j] ? hi[i + j] : v;
			z[j] = (v - centre[i + j]) * inv_scale[i + j];
			h[j] = p[D * n + i + j];
		}
		for (int k = D - 1; k >= 1; k--)
			for (int j = 0; j < 4; j++) h[j] = h[j] * z[j] + p[k * n + i + j];
		sum += (h[0] * z[0] + h[1] * z[1]) + (h[2] * z[2] + h[3] * z[3]);
	}
	for (; i < n; i++)
	{
		double v = Diff ? src[a[i]] - src[b[i]] : src[a[i]];
		cl += (v < lo[i]) + (v > hi[i]);
		v = v < lo[i] ? lo[i] : v;
		v = v > hi[i] ? hi[i] : v;
		const double z = (v - centre[i]) * inv_scale[i];
		double h = p[D * n + i];
		for (int k = D - 1; k >= 1; k--) h = h * z + p[k * n + i];
		sum += h * z;
	}
	clamped += cl;
	return sum;
}

template <bool Diff>
double groupSumAnyDegree(int degree, const int* a, const int* b, const double* src, const double* lo, const double* hi,
						 const double* centre, const double* inv_scale, const double* p, std::size_t n, int& clamped)
{
	switch (degree)
	{
		case 1: return groupSum<1, Diff>(a, b, src, lo, hi, centre, inv_scale, p, n, clamped);
		case 2: return groupSum<2, Diff>(a, b, src, lo, hi, centre, inv_scale, p, n, clamped);
		case 3: return groupSum<3, Diff>(a, b, src, lo, hi, centre, inv_scale, p, n, clamped);
		case 4: return groupSum<4, Diff>(a, b, src, lo, hi, centre, inv_scale, p, n, clamped);
		default: return groupSum<5, Diff>(a, b, src, lo, hi, centre, inv_scale, p, n, clamped);
	}
}
}  // namespace

namespace
{
/** The per-channel T / dT/dt polynomials; NC > 0: compile-time channel count (fully unrolled). */
template <std::size_t NC>
inline double kernelSumN(const double* tc, const double* ti, const double* tl, const double* th, const double* tp,
						 const double* rc, const double* ri, const double* rl, const double* rh, const double* rp,
						 const double* T, const double* R, std::size_t nc_rt, int& clamped)
{
	const std::size_t nc = NC ? NC : nc_rt;
	int cl = 0;
	double acc = 0;
	for (std::size_t c = 0; c < nc; c++)
	{
		double v = T[c];
		cl += (v < tl[c]) + (v > th[c]);
		v = v < tl[c] ? tl[c] : v;
		v = v > th[c] ? th[c] : v;
		const double z = (v - tc[c]) * ti[c];
		double w = R[c];
		cl += (w < rl[c]) + (w > rh[c]);
		w = w < rl[c] ? rl[c] : w;
		w = w > rh[c] ? rh[c] : w;
		const double q = (w - rc[c]) * ri[c];
		// Estrin's scheme (shorter dependency chains than Horner: the loop is latency-bound).
		const double z2 = z * z, q2 = q * q;
		const double hT = z * ((tp[c] + tp[nc + c] * z) + z2 * ((tp[2 * nc + c] + tp[3 * nc + c] * z) + z2 * tp[4 * nc + c]));
		const double hR = q * ((rp[c] + rp[nc + c] * q) + q2 * rp[2 * nc + c]);
		acc += hT + hR;
	}
	clamped += cl;
	return acc;
}
}  // namespace

double Compensator::kernelSum(const ChannelKernel& K, const double* T, const double* R, int& clamped)
{
	const std::size_t nc = K.t_centre.size();
#define FOG_KERNEL(N)                                                                                              \
	kernelSumN<N>(K.t_centre.data(), K.t_inv.data(), K.t_lo.data(), K.t_hi.data(), K.t_p.data(), K.r_centre.data(), \
				  K.r_inv.data(), K.r_lo.data(), K.r_hi.data(), K.r_p.data(), T, R, nc, clamped)
	switch (nc)
	{
		case 1: return FOG_KERNEL(1);
		case 2: return FOG_KERNEL(2);
		case 3: return FOG_KERNEL(3);
		case 4: return FOG_KERNEL(4);
		default: return FOG_KERNEL(0);
	}
#undef FOG_KERNEL
}

double Compensator::evaluate(const Compiled& m, int& clamped) const
{
	double sum = m.c0;
	sum += kernelSum(m.kernel, temp_.data(), rate_.data(), clamped);
	for (const SignalGroup& g : m.groups)
	{
		const double* src = (g.kind == 0 || g.kind == 2) ? temp_.data() : rate_.data();
		if (g.kind >= 2)
			sum += groupSumAnyDegree<true>(g.degree, g.a.data(), g.b.data(), src, g.lo.data(), g.hi.data(),
										   g.centre.data(), g.inv_scale.data(), g.p.data(), g.a.size(), clamped);
		else
			sum += groupSumAnyDegree<false>(g.degree, g.a.data(), g.b.data(), src, g.lo.data(), g.hi.data(),
											g.centre.data(), g.inv_scale.data(), g.p.data(), g.a.size(), clamped);
	}
	return sum;
}

Compensator::Output Compensator::step(double time_s, double raw_dph, const double* temp_C)
{
	const std::size_t nc = channel_col_.size();
	for (std::size_t c = 0; c < nc; c++) x_[c] = temp_C[channel_col_[c]];
	tracker_.push(time_s, x_.data());
	const std::uint32_t short_span = tracker_.ratesAndCoverage(rate_.data(), 0.5 * window_s_);
	std::uint32_t missing = 0;
	for (std::size_t c = 0; c < nc; c++)
	{
		temp_[c] = x_[c];
		if (std::isnan(temp_[c]) || std::isnan(rate_[c]))
		{
			missing |= 1u << c;
			temp_[c] = rate_[c] = 0.0;  // never read by the model in use
		}
	}
	// Main model unless it reads a missing channel; then the fallback without that channel if
	// it reads no other missing channel; else none.
	int model = -1;
	if ((missing & models_[0].uses) == 0)
		model = 0;
	else
	{
		const std::uint32_t need = missing & models_[0].uses;
		const int c = __builtin_ctz(need);
		if (has_fallback_[c] && (missing & models_[1 + c].uses) == 0) model = 1 + c;
	}
	Output out;
	int clamped = 0;
	bool warm = false;
	if (model >= 0)
	{
		out.bias_dph = evaluate(models_[model], clamped);
		warm = (short_span & models_[model].uses) != 0;
	}
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
