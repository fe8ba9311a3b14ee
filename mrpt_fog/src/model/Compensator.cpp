/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/model/CompensatorStep.h>

#include <Eigen/Core>
#include <algorithm>
#include <limits>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
std::string degText(double a) { return formatValue("%g", a); }

std::string describeLayout(const std::vector<ThermistorInfo>& layout)
{
	std::ostringstream o;
	for (std::size_t i = 0; i < layout.size(); i++)
		o << (i ? ", " : "") << layout[i].name << " " << toString(layout[i].side) << " " << formatValue("%g", layout[i].angle_deg) << "deg";
	return layout.empty() ? "(no thermistors)" : o.str();
}
}  // namespace

Compensator::Compiled Compensator::compile(const BiasModel& m, const std::vector<std::string>& names,
										   const std::vector<LagChannel>& lag_channels,
										   const std::vector<HysteresisChannel>& hyst_channels)
{
	Compiled c;
	const auto& fs = m.features;
	const auto chan = [&](const std::string& n) {
		const auto it = std::find(names.begin(), names.end(), n);
		if (it == names.end()) throw std::invalid_argument("calibration model uses thermistor '" + n + "' not in the main model");
		return static_cast<int>(it - names.begin());
	};
	const auto lagOf = [&](const ThermalSignal& sig) {
		const auto it = std::find(lag_channels.begin(), lag_channels.end(), LagChannel{chan(sig.a), sig.tau_s});
		return static_cast<int>(it - lag_channels.begin());  // every model's lags are in the bank
	};
	const auto hystOf = [&](const ThermalSignal& sig) {
		const auto it = std::find(hyst_channels.begin(), hyst_channels.end(),
								  HysteresisChannel{chan(sig.a), sig.hyst_op, sig.width_C});
		return static_cast<int>(it - hyst_channels.begin());  // every model's operators are in the bank
	};
	// a signal read from a filter bank: its channel there (lag or hysteresis), else its thermistor's
	const auto source = [&](const ThermalSignal& sig) {
		return sig.isLag() ? lagOf(sig) : sig.isHysteresis() ? hystOf(sig) : chan(sig.a);
	};
	// degree of each signal
	std::vector<int> degree(fs.signals().size(), 0);
	for (std::size_t i = 0; i < fs.termCount(); i++)
		if (fs.termSignal(i) >= 0)
			degree[fs.termSignal(i)] = std::max(degree[fs.termSignal(i)], fs.terms()[i].power);
	const std::size_t nc = names.size();
	const double inf = std::numeric_limits<double>::infinity();
	std::vector<detail::KernelBlock>& K = c.kernel;
	K.resize((nc + 3) / 4);
	for (detail::KernelBlock& b : K)
		for (int j = 0; j < 4; j++)
		{
			b.t_centre[j] = b.r_centre[j] = 0.0;
			b.t_lo[j] = b.r_lo[j] = -inf;
			b.t_hi[j] = b.r_hi[j] = inf;
			for (auto& p : b.t_q) p[j] = 0.0;
			for (auto& p : b.r_q) p[j] = 0.0;
		}
	for (std::size_t s = 0; s < fs.signals().size(); s++)
	{
		const auto& sig = fs.signals()[s];
		if (sig.isDifference() || sig.isLag() || sig.isHysteresis()) continue;
		const auto& nm = fs.normalisation()[s];
		const int ch = chan(sig.a);
		detail::KernelBlock& b = K[ch / 4];
		const int j = ch % 4;
		const bool t = sig.kind == SignalKind::Temp;
		(t ? b.t_centre : b.r_centre)[j] = nm.centre;
		(t ? b.t_lo : b.r_lo)[j] = nm.min;
		(t ? b.t_hi : b.r_hi)[j] = nm.max;
		c.uses |= 1u << ch;
		if (!t) c.uses_rate |= 1u << ch;
	}
	for (std::size_t s = 0; s < fs.signals().size(); s++)
	{
		const auto& sig = fs.signals()[s];
		const auto& nm = fs.normalisation()[s];
		EdgeSignal e;
		e.kind = static_cast<int>(sig.kind);
		e.a = source(sig);
		e.b = sig.isDifference() ? chan(sig.b) : 0;
		e.lo = nm.min;
		e.hi = nm.max;
		e.slope_lo = m.edgeSlope(s, false);
		e.slope_hi = m.edgeSlope(s, true);
		e.centre = nm.centre;
		e.scale = nm.scale;
		for (std::size_t i = 0; i < fs.termCount(); i++)
			if (fs.termSignal(i) == static_cast<int>(s)) e.coef[fs.terms()[i].power] += m.coef_dph.at(i);
		c.edges.push_back(e);
	}
	std::vector<int> group_of(fs.signals().size()), index_in(fs.signals().size());
	for (const SignalKind kind : {SignalKind::Diff, SignalKind::DiffRate, SignalKind::LagRate, SignalKind::Hysteresis})  // T and dT/dt: the kernel
	{
		SignalGroup g;
		g.kind = kind;
		for (std::size_t s = 0; s < fs.signals().size(); s++)
		{
			const auto& sig = fs.signals()[s];
			if (sig.kind != kind) continue;
			const auto& nm = fs.normalisation()[s];
			group_of[s] = static_cast<int>(c.groups.size());
			index_in[s] = static_cast<int>(g.a.size());
			g.a.push_back(source(sig));  // a lag or hysteresis: its channel in the bank
			g.b.push_back(sig.isDifference() ? chan(sig.b) : 0);
			g.centre.push_back(nm.centre);
			g.inv_scale.push_back(1.0 / nm.scale);
			g.lo.push_back(nm.min);
			g.hi.push_back(nm.max);
			g.degree = std::max(g.degree, degree[s]);
			c.uses |= 1u << chan(sig.a);  // a lag or hysteresis needs its thermistor's reading
			if (sig.isDifference()) c.uses |= 1u << g.b.back();
			if (kind == SignalKind::DiffRate) c.uses_rate |= (1u << g.a.back()) | (1u << g.b.back());
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
		if (!sig.isDifference() && !sig.isLag() && !sig.isHysteresis())
		{
			// coef * ((v - centre) / scale)^k = (coef / scale^k) * (v - centre)^k
			const int ch = chan(sig.a);
			const int k = fs.terms()[i].power;
			const double inv_scale = 1.0 / fs.normalisation()[s].scale;
			double q = m.coef_dph.at(i);
			for (int e = 0; e < k; e++) q *= inv_scale;
			detail::KernelBlock& b = K[ch / 4];
			(sig.kind == SignalKind::Temp ? b.t_q : b.r_q)[k - 1][ch % 4] += q;
			continue;
		}
		SignalGroup& g = c.groups[group_of[s]];
		g.p[static_cast<std::size_t>(fs.terms()[i].power) * g.a.size() + static_cast<std::size_t>(index_in[s])] +=
			m.coef_dph.at(i);
	}
	return c;
}

// Defined here, where Compiled is complete (Compensator.h only declares it).
Compensator::~Compensator() = default;
Compensator::Compensator(const Compensator&) = default;
Compensator::Compensator(Compensator&&) noexcept = default;
Compensator& Compensator::operator=(const Compensator&) = default;
Compensator& Compensator::operator=(Compensator&&) noexcept = default;

Compensator::Compensator(const Calibration& cal, const std::vector<ThermistorInfo>& layout, KernelBuild build)
	: window_s_(cal.rate_estimator.window_s),
	  half_window_s_(0.5 * cal.rate_estimator.window_s),
	  mean_bias_dph_(cal.mean_bias_dph),
	  extrapolation_(cal.extrapolation),
	  tracker_(1, cal.rate_estimator.window_s),
	  half_tracker_(1, 0.5 * cal.rate_estimator.window_s)
{
	if (build == KernelBuild::Avx2 && !detail::cpuHasAvx2())
		throw std::invalid_argument("compensator: the AVX2 build was requested but this CPU lacks AVX2");
	const bool avx2 = build == KernelBuild::Avx2 || (build == KernelBuild::Auto && detail::cpuHasAvx2());
	cal.rate_estimator.validate();
	if (cal.rate_estimator.kind != RateEstimatorKind::Causal)
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
	delay_comp_ = cal.rate_estimator.poly_order == 2;
	half_tracker_ = CausalRateTracker(names.size(), 0.5 * cal.rate_estimator.window_s);
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
	same_order_ = true;
	for (std::size_t c = 0; c < channel_col_.size(); c++) same_order_ &= channel_col_[c] == static_cast<int>(c);
	// The lags every model reads, over tracked channels (LagFilter.h).
	std::vector<LagChannel> lag_channels;
	const auto addLags = [&](const BiasModel& m) {
		for (const auto& sig : m.features.signals())
		{
			if (!sig.isLag()) continue;
			const auto it = std::find(names.begin(), names.end(), sig.a);
			const LagChannel lc{static_cast<int>(it - names.begin()), sig.tau_s};
			if (it != names.end() && std::find(lag_channels.begin(), lag_channels.end(), lc) == lag_channels.end())
				lag_channels.push_back(lc);
		}
	};
	// The hysteresis operators every model reads, over tracked channels (HysteresisFilter.h).
	std::vector<HysteresisChannel> hyst_channels;
	const auto addHysteresis = [&](const BiasModel& m) {
		for (const auto& sig : m.features.signals())
		{
			if (!sig.isHysteresis()) continue;
			const auto it = std::find(names.begin(), names.end(), sig.a);
			const HysteresisChannel hc{static_cast<int>(it - names.begin()), sig.hyst_op, sig.width_C};
			if (it != names.end() && std::find(hyst_channels.begin(), hyst_channels.end(), hc) == hyst_channels.end())
				hyst_channels.push_back(hc);
		}
	};
	const auto everyModel = [&](const auto& add) {
		add(cal.model);
		for (const auto& fb : cal.fallbacks) add(fb);
		if (cal.startup) add(*cal.startup);
	};
	everyModel(addLags);
	everyModel(addHysteresis);
	has_filters_ = !lag_channels.empty() || !hyst_channels.empty();
	lags_ = LagFilterBank(lag_channels);
	lag_rate_.assign(lag_channels.size(), 0.0);
	hyst_ = HysteresisFilterBank(hyst_channels);
	hyst_value_.assign(hyst_channels.size(), 0.0);
	models_.push_back(compile(cal.model, names, lag_channels, hyst_channels));
	for (const auto& n : names)
	{
		const BiasModel* fb = cal.fallbackFor(n);
		has_fallback_.push_back(fb != nullptr);
		models_.push_back(fb ? compile(*fb, names, lag_channels, hyst_channels) : Compiled{});
	}
	if (cal.startup)
	{
		for (std::size_t s = 0; s < cal.startup->features.signals().size(); s++)
		{
			const SignalKind k = cal.startup->features.signals()[s].kind;
			if (k == SignalKind::Rate || k == SignalKind::DiffRate)
				throw std::invalid_argument("calibration's start-up model reads a rate (" +
											cal.startup->features.signals()[s].name() + "): it must be rate-free");
		}
		startup_ = static_cast<int>(models_.size());
		models_.push_back(compile(*cal.startup, names, lag_channels, hyst_channels));
	}
	if (cal.scale_factor)
	{
		sf_ = cal.scale_factor;
		const auto column = [&](const std::string& name) {
			for (std::size_t i = 0; i < layout.size(); i++)
				if (layout[i].name == name) return static_cast<int>(i);
			throw std::invalid_argument("calibration's scale-factor model reads thermistor " + name +
										", which the data layout lacks; data layout: " + describeLayout(layout));
		};
		if (sf_->thermistors.empty()) sf_col_ = column(sf_->thermistor);
		for (const auto& name : sf_->thermistors) sf_cols_.push_back(column(name));
		if (!sf_->weights.empty() && sf_->weights.size() != sf_->thermistors.size())
			throw std::invalid_argument("calibration's scale-factor model has " + std::to_string(sf_->weights.size()) +
										" weights for " + std::to_string(sf_->thermistors.size()) + " thermistors");
		sf_initial_ppm_ = sf_ppm_ = sf_->evaluate_ppm(sf_->centre_C);
	}
	warmup_ = cal.warmup;
	magnetic_ = cal.magnetic;
	extras_ = sf_.has_value() || warmup_.has_value() || magnetic_.has_value();
	use_avx2_ = avx2 && !names.empty() && names.size() <= 4;  // stepAvx2 covers 1..4 channels
	const std::size_t padded = 4 * ((names.size() + 3) / 4);
	temp_.assign(padded, 0.0);  // padding lanes stay 0: finite, never clamped, zero coefficients
	rate_.assign(padded, 0.0);
}

void Compensator::reset()
{
	tracker_.reset();
	half_tracker_.reset();
	lags_.reset();
	hyst_.reset();
	counters_ = {};
	last_model_ = kNoSampleYet;
	sf_ppm_ = sf_initial_ppm_;
	power_on_s_ = std::numeric_limits<double>::quiet_NaN();
	field_uT_ = std::numeric_limits<double>::quiet_NaN();
}

void Compensator::notePowerOn(double time_s) { power_on_s_ = time_s; }

void Compensator::noteField(double field_uT)
{
	field_uT_ = std::isfinite(field_uT) ? field_uT : std::numeric_limits<double>::quiet_NaN();
}

void Compensator::notePowerOnFromMetadata(const FogSeries& log)
{
	const std::string meta = log.metadataValue("power_on_time_s");
	if (meta.empty()) return;
	char* end = nullptr;
	const double t_on = std::strtod(meta.c_str(), &end);
	if (!std::isfinite(t_on) || *end != '\0')
		throw std::invalid_argument("metadata power_on_time_s: '" + meta + "' is not a time [s]");
	notePowerOn(t_on);
}

[[gnu::noinline]] void Compensator::delayCompensateRates(double time_s, const double* temp_C)
{
	half_tracker_.push(time_s, temp_C);
	for (std::size_t c = 0; c < channel_col_.size(); c++)
		rate_[c] = CausalRateTracker::extrapolatedRate(tracker_, half_tracker_, c, time_s);
}

[[gnu::noinline]] void Compensator::updateFilters(double time_s, const double* temp_C)
{
	if (lags_.size())
	{
		lags_.push(time_s, temp_C);
		for (std::size_t i = 0; i < lag_rate_.size(); i++) lag_rate_[i] = lags_.rate_C_per_s(i);
	}
	if (hyst_.size())
	{
		hyst_.push(temp_C);
		for (std::size_t i = 0; i < hyst_value_.size(); i++) hyst_value_[i] = hyst_.value(i);
	}
}

[[gnu::noinline]] void Compensator::applyExtras(Output& out, double time_s, double raw_dph, const double* temp_C)
{
	if (warmup_ && time_s >= power_on_s_)
	{
		out.bias_dph += warmup_->bias_dph(time_s - power_on_s_);
		// the start-up model's own error at a turn-on, only in the first rate window after it
		if (out.model == kStartupModel && time_s - power_on_s_ <= window_s_) out.bias_dph += warmup_->startup_offset_dph;
	}
	if (magnetic_)
	{
		if (std::isnan(field_uT_))
			counters_.field_unknown_samples++;
		else
		{
			out.bias_dph += magnetic_->bias_dph(field_uT_);
			const double beyond_uT =
				std::max(magnetic_->field_min_uT - field_uT_, field_uT_ - magnetic_->field_max_uT);
			if (beyond_uT > 0)
			{
				counters_.field_outside_samples++;
				counters_.max_field_excursion_uT = std::max(counters_.max_field_excursion_uT, beyond_uT);
			}
		}
	}
	double r = raw_dph - out.bias_dph;
	if (sf_)
	{
		double T = NAN;
		if (sf_col_ >= 0)
			T = temp_C[sf_col_];
		else
		{
			// the mean (or weighted sum) of the readings when all are valid; else the value held
			double sum = 0, wsum = 0;
			int n = 0;
			for (std::size_t i = 0; i < sf_cols_.size(); i++)
			{
				const double v = temp_C[sf_cols_[i]];
				if (std::isnan(v)) continue;
				sum += v, n++;
				if (!sf_->weights.empty()) wsum += sf_->weights[i] * v;
			}
			if (n > 0 && n == static_cast<int>(sf_cols_.size())) T = sf_->weights.empty() ? sum / n : wsum;
		}
		if (!std::isnan(T)) sf_ppm_ = sf_->evaluate_ppm(T);
		r /= 1.0 + 1e-6 * sf_ppm_;
	}
	out.compensated_dph = r;
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

namespace detail
{
int countClamped(const KernelBlock* K, std::size_t blocks, const double* T, const double* R)
{
	int cl = 0;
	for (std::size_t blk = 0; blk < blocks; blk++)
		for (int j = 0; j < 4; j++)
		{
			const KernelBlock& b = K[blk];
			const double v = T[4 * blk + j], w = R[4 * blk + j];
			cl += (v < b.t_lo[j]) + (v > b.t_hi[j]) + (w < b.r_lo[j]) + (w > b.r_hi[j]);
		}
	return cl;
}
}  // namespace detail

[[gnu::noinline]] double Compensator::addGroups(const Compiled& m, const double* temp_C, double sum, int& clamped) const
{
	for (const SignalGroup& g : m.groups)
	{
		const bool of_temperature = g.kind == SignalKind::Temp || g.kind == SignalKind::Diff;
		const double* src = g.kind == SignalKind::LagRate	 ? lag_rate_.data()
							: g.kind == SignalKind::Hysteresis ? hyst_value_.data()
							: of_temperature				   ? temp_C
															   : rate_.data();
		if (g.kind == SignalKind::Diff || g.kind == SignalKind::DiffRate)
			sum += groupSumAnyDegree<true>(g.degree, g.a.data(), g.b.data(), src, g.lo.data(), g.hi.data(),
										   g.centre.data(), g.inv_scale.data(), g.p.data(), g.a.size(), clamped);
		else
			sum += groupSumAnyDegree<false>(g.degree, g.a.data(), g.b.data(), src, g.lo.data(), g.hi.data(),
											g.centre.data(), g.inv_scale.data(), g.p.data(), g.a.size(), clamped);
	}
	return sum;
}

[[gnu::noinline]] double Compensator::outsideRange(const Compiled& m, const double* temp_C)
{
	double extra = 0;
	bool temp_out = false, rate_out = false;
	for (const EdgeSignal& e : m.edges)
	{
		double v = 0;
		switch (e.kind)
		{
			case 0: v = temp_C[e.a]; break;
			case 1: v = rate_[e.a]; break;
			case 2: v = temp_C[e.a] - temp_C[e.b]; break;
			case 4: v = lag_rate_[e.a]; break;
			case 5: v = hyst_value_[e.a]; break;
			default: v = rate_[e.a] - rate_[e.b]; break;
		}
		double beyond = 0, edge = 0;
		if (v < e.lo)
		{
			beyond = e.lo - v;
			edge = e.lo;
			extra += extrapolation_ == ExtrapolationPolicy::Linear ? e.slope_lo * (v - e.lo) : 0.0;
		}
		else if (v > e.hi)
		{
			beyond = v - e.hi;
			edge = e.hi;
			extra += extrapolation_ == ExtrapolationPolicy::Linear ? e.slope_hi * (v - e.hi) : 0.0;
		}
		else
			continue;
		if (extrapolation_ == ExtrapolationPolicy::Polynomial)
		{
			const auto poly = [&](double x) {
				const double z = (x - e.centre) / e.scale;
				double h = 0;
				for (int k = 5; k >= 1; k--) h = (h + e.coef[k]) * z;
				return h;
			};
			extra += poly(v) - poly(edge);
		}
		if (e.kind == 1 || e.kind == 3 || e.kind == 4)
		{
			rate_out = true;
			counters_.max_rate_excursion_C_per_s = std::max(counters_.max_rate_excursion_C_per_s, beyond);
		}
		else
		{
			temp_out = true;
			counters_.max_temp_excursion_C = std::max(counters_.max_temp_excursion_C, beyond);
		}
	}
	counters_.temp_outside_samples += temp_out;
	counters_.rate_outside_samples += rate_out;
	return extra;
}

Compensator::Output Compensator::step(double time_s, double raw_dph, const double* temp_C)
{
	if (use_avx2_) return stepAvx2(time_s, raw_dph, temp_C);
	// Compile-time channel counts for the common layouts: the tracker's steady-state update
	// inlines and the loops over channels unroll.
	switch (channel_col_.size())
	{
		case 4: return stepFixed<4>(time_s, raw_dph, temp_C);
		case 1: return stepFixed<1>(time_s, raw_dph, temp_C);
		case 2: return stepFixed<2>(time_s, raw_dph, temp_C);
		case 3: return stepFixed<3>(time_s, raw_dph, temp_C);
		default: return stepFixed<0>(time_s, raw_dph, temp_C);
	}
}

void Compensator::stepBatch(std::size_t n, const double* time_s, const double* raw_dph, const double* temp_C,
							std::size_t stride, Output* out)
{
	if (use_avx2_) return stepBatchAvx2(n, time_s, raw_dph, temp_C, stride, out);
	switch (channel_col_.size())
	{
		case 4: return stepLoop<4, 2>(n, time_s, raw_dph, temp_C, stride, out);
		case 1: return stepLoop<1, 2>(n, time_s, raw_dph, temp_C, stride, out);
		case 2: return stepLoop<2, 2>(n, time_s, raw_dph, temp_C, stride, out);
		case 3: return stepLoop<3, 2>(n, time_s, raw_dph, temp_C, stride, out);
		default: return stepLoop<0, 2>(n, time_s, raw_dph, temp_C, stride, out);
	}
}

template <std::size_t NC>
Compensator::Output Compensator::stepFixed(double time_s, double raw_dph, const double* temp_C)
{
	return stepBody<NC, 2>(time_s, raw_dph, temp_C);
}

namespace
{
/** compensate()'s loop over a series: sink(k0, m, res) receives the outputs of rows k0..k0+m-1. */
template <class Sink>
CompensationCounters compensateChunks(const Calibration& cal, const FogSeries& series, Sink&& sink)
{
	return compensateRun(cal, FogRun(series),
						 [&](const FogSeries&, std::size_t k0, std::size_t j0, std::size_t m, const Compensator::Output* res) {
							 sink(k0 + j0, m, res);
						 });
}
}  // namespace

CompensationCounters compensateRun(const Calibration& cal, const FogRun& run, const CompensationSink& sink)
{
	run.validate();
	const FogSeries& h = run.header();
	const int axis = static_cast<int>(cal.axis);
	if (!h.has_axis[axis])
		throw std::invalid_argument(std::string("the log has no ") + axisLetter(cal.axis) +
									" axis, which the calibration is for");
	Compensator comp(cal, h.thermistors);
	// Turn-ons (only the warm-up term needs them): before the log, and 0 -> 1 power steps.
	if (cal.warmup)
	{
		comp.notePowerOnFromMetadata(h);
	}
	double prev_power = 1.0;  // sample 0 is never a turn-on
	// The batch form of step() over blocks of rows (the series stores columns).
	const std::size_t nt = h.thermistorCount(), stride = std::max<std::size_t>(nt, 1), block = 4096;
	std::vector<double> rows(block * stride);
	std::vector<Compensator::Output> res(block);
	run.forEachChunk([&](const FogSeries& c, std::size_t k0) {
		const std::size_t n = c.size();
		const bool warm = cal.warmup && !c.power.empty();
		const bool field = cal.magnetic && c.field_uT.size() == n;  // else the field stays unknown
		const auto turnOn = [&](std::size_t j) { return c.power[j] != 0.0 && (j > 0 ? c.power[j - 1] : prev_power) == 0.0; };
		for (std::size_t j0 = 0, m = 0; j0 < n; j0 += m)
		{
			if (warm && turnOn(j0)) comp.notePowerOn(c.time_s[j0]);
			m = std::min(block, n - j0);
			if (warm)  // stop at the next turn-on
				for (std::size_t j = j0 + 1; j < j0 + m; j++)
					if (turnOn(j))
					{
						m = j - j0;
						break;
					}
			for (std::size_t j = 0; j < m; j++)
				for (std::size_t i = 0; i < nt; i++) rows[j * stride + i] = c.temp_C[i][j0 + j];
			if (field)  // the field changes per sample: step() after noteField() (the same numbers as stepBatch)
				for (std::size_t j = 0; j < m; j++)
				{
					comp.noteField(c.field_uT[j0 + j]);
					res[j] = comp.step(c.time_s[j0 + j], c.rate_dph[axis][j0 + j], rows.data() + j * stride);
				}
			else
				comp.stepBatch(m, c.time_s.data() + j0, c.rate_dph[axis].data() + j0, rows.data(), stride, res.data());
			sink(c, k0, j0, m, res.data());
		}
		if (!c.power.empty() && n > 0) prev_power = c.power[n - 1];
	});
	return comp.counters();
}

std::string fieldMissingWarning(const Calibration& cal, const FogSeries& series)
{
	if (!cal.magnetic || !series.field_uT.empty()) return {};
	return "the calibration has a magnetic section (" + formatValue("%g", cal.magnetic->dph_per_uT) +
		   " deg/h per uT) but the log has no field column: compensated without the field term";
}

CompensatedSeries compensate(const Calibration& cal, const FogSeries& series)
{
	CompensatedSeries out;
	const std::size_t n = series.size();
	out.bias_dph.resize(n);
	out.compensated_dph.resize(n);
	out.flags.resize(n);
	out.counters = compensateChunks(cal, series, [&](std::size_t k0, std::size_t m, const Compensator::Output* res) {
		for (std::size_t j = 0; j < m; j++)
		{
			out.bias_dph[k0 + j] = res[j].bias_dph;
			out.compensated_dph[k0 + j] = res[j].compensated_dph;
			out.flags[k0 + j] = res[j].flags;
		}
	});
	out.time_s = series.time_s;
	out.raw_dph = series.rate_dph[static_cast<int>(cal.axis)];
	return out;
}

namespace
{
/// One output field of every sample, e.g. `&Compensator::Output::bias_dph`.
std::vector<double> compensatedField(const Calibration& cal, const FogSeries& series, CompensationCounters* counters,
	double Compensator::Output::*field)
{
	std::vector<double> values(series.size());
	const CompensationCounters c =
		compensateChunks(cal, series, [&](std::size_t k0, std::size_t m, const Compensator::Output* res) {
			for (std::size_t j = 0; j < m; j++) values[k0 + j] = res[j].*field;
		});
	if (counters) *counters = c;
	return values;
}
}  // namespace

std::vector<double> compensatedBias_dph(const Calibration& cal, const FogSeries& series, CompensationCounters* counters)
{
	return compensatedField(cal, series, counters, &Compensator::Output::bias_dph);
}

std::vector<double> compensatedRate_dph(const Calibration& cal, const FogSeries& series, CompensationCounters* counters)
{
	return compensatedField(cal, series, counters, &Compensator::Output::compensated_dph);
}

}  // namespace mrpt_fog
