/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/BaseModelDesign.h>
#include <mrpt_fog/discrepancy/CandidateEffect.h>
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <utility>

namespace mrpt_fog::discrepancy
{
double heatingCoolingSign(double dtemp_dt_Cpm) { return std::tanh(dtemp_dt_Cpm / 0.05); }

std::vector<double> hysteresisBranch(const RunSignals& s, double span_C)
{
	if (!(span_C > 0)) throw std::invalid_argument("hysteresisBranch: span_C must be > 0");
	std::vector<double> h(s.size(), 0.0);
	const bool coil = s.temp_coil_C.size() == s.size() && s.dtemp_coil_dt_Cpm.size() == s.size();
	const auto& T = coil ? s.temp_coil_C : s.temp_mean_C;  // signals built by hand may lack the coil's
	const auto& dT_dt = coil ? s.dtemp_coil_dt_Cpm : s.dtemp_dt_Cpm;
	double state = 0.0;
	for (std::size_t k = 1; k < s.size(); ++k)
	{
		double dT = 0.0;
		if (s.block[k] >= 0 && s.block[k] == s.block[k - 1])
			dT = 0.5 * (dT_dt[k] + dT_dt[k - 1]) * (s.time_s[k] - s.time_s[k - 1]) / 60.0;
		else if (std::isfinite(T[k]) && std::isfinite(T[k - 1]))
			dT = T[k] - T[k - 1];  // across a gap or power-off: raw change
		if (dT != 0.0)
		{
			const double target = dT > 0 ? 1.0 : -1.0;
			state = target + (state - target) * std::exp(-std::fabs(dT) / span_C);
		}
		h[k] = state;
	}
	return h;
}

std::vector<double> hysteresisPlay(const RunSignals& s, double half_width_C)
{
	if (!(half_width_C > 0)) throw std::invalid_argument("hysteresisPlay: half_width_C must be > 0");
	std::vector<double> h(s.size(), 0.0);
	const bool coil = s.temp_coil_C.size() == s.size() && s.dtemp_coil_dt_Cpm.size() == s.size();
	const auto& T = coil ? s.temp_coil_C : s.temp_mean_C;
	const auto& dT_dt = coil ? s.dtemp_coil_dt_Cpm : s.dtemp_dt_Cpm;
	// x: the coil temperature's change since the run start, from the same per-sample changes as
	// hysteresisBranch (smoothed rate within a block, raw change across gaps); p: the play's
	// output, which moves only when x leaves [p - w, p + w]
	double x = 0.0, p = 0.0;
	for (std::size_t k = 1; k < s.size(); ++k)
	{
		if (s.block[k] >= 0 && s.block[k] == s.block[k - 1])
			x += 0.5 * (dT_dt[k] + dT_dt[k - 1]) * (s.time_s[k] - s.time_s[k - 1]) / 60.0;
		else if (std::isfinite(T[k]) && std::isfinite(T[k - 1]))
			x += T[k] - T[k - 1];
		p = std::min(std::max(p, x - half_width_C), x + half_width_C);
		h[k] = (x - p) / half_width_C;
	}
	return h;
}

namespace
{
/** The smoothed coil temperature rate [C/min] of a sample (the mean's when the coil's is absent,
 * 0 when not finite). */
double coilRateAt(const RunSignals& s, std::size_t k)
{
	const bool coil = s.dtemp_coil_dt_Cpm.size() == s.size();
	const double r = coil ? s.dtemp_coil_dt_Cpm[k] : s.dtemp_dt_Cpm[k];
	return std::isfinite(r) ? r : 0.0;
}
}  // namespace

std::vector<double> hysteresisRateSaturation(const RunSignals& s, double width_Cpm)
{
	if (!(width_Cpm > 0)) throw std::invalid_argument("hysteresisRateSaturation: width_Cpm must be > 0");
	std::vector<double> h(s.size(), 0.0);
	for (std::size_t k = 0; k < s.size(); ++k) h[k] = std::tanh(coilRateAt(s, k) / width_Cpm);
	return h;
}

std::vector<double> hysteresisRateSign(const RunSignals& s, double dead_band_Cpm)
{
	if (!(dead_band_Cpm > 0)) throw std::invalid_argument("hysteresisRateSign: dead_band_Cpm must be > 0");
	std::vector<double> h(s.size(), 0.0);
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		const double r = coilRateAt(s, k);
		h[k] = r >= dead_band_Cpm ? 1.0 : (r <= -dead_band_Cpm ? -1.0 : 0.0);
	}
	return h;
}

HysteresisShape hysteresisShapeOf(double theta)
{
	if (!(theta != 0.0) || !std::isfinite(theta)) throw std::invalid_argument("hysteresis theta must be finite and non-zero");
	using K = HysteresisShape::Kind;
	const double a = std::fabs(theta);
	if (a < kHysteresisMaxWidth_C) return {theta > 0 ? K::ExponentialBranch : K::Play, a};
	return {theta > 0 ? K::RateSaturation : K::RateSign, a / kHysteresisRateThetaPerCpm};
}

double hysteresisTheta(HysteresisShape shape)
{
	if (!(shape.width > 0) || !std::isfinite(shape.width))
		throw std::invalid_argument("hysteresis width must be finite and > 0");
	using K = HysteresisShape::Kind;
	if (!shape.ratesOnly())
	{
		if (!(shape.width < kHysteresisMaxWidth_C))
			throw std::invalid_argument("hysteresis branch span / play half-width must be below 100 C");
		return shape.kind == K::ExponentialBranch ? shape.width : -shape.width;
	}
	if (!(shape.width >= kHysteresisMinRateWidth_Cpm))
		throw std::invalid_argument("hysteresis rate width must be at least 0.01 C/min");
	return (shape.kind == K::RateSaturation ? 1.0 : -1.0) * kHysteresisRateThetaPerCpm * shape.width;
}

std::vector<double> hysteresisColumn(const RunSignals& s, double theta)
{
	const auto shape = hysteresisShapeOf(theta);
	switch (shape.kind)
	{
		case HysteresisShape::Kind::ExponentialBranch: return hysteresisBranch(s, shape.width);
		case HysteresisShape::Kind::Play: return hysteresisPlay(s, shape.width);
		case HysteresisShape::Kind::RateSaturation: return hysteresisRateSaturation(s, shape.width);
		case HysteresisShape::Kind::RateSign: return hysteresisRateSign(s, shape.width);
	}
	throw std::logic_error("hysteresisColumn: unknown shape");
}

std::vector<double> hysteresisThetaGrid()
{
	using K = HysteresisShape::Kind;
	std::vector<double> g;
	for (auto kind : {K::ExponentialBranch, K::Play})
		for (double w : {0.5, 1.0, 2.0, 5.0, 10.0, 20.0}) g.push_back(hysteresisTheta({kind, w}));
	for (double r : {0.02, 0.05, 0.1, 0.2, 0.5, 1.0}) g.push_back(hysteresisTheta({K::RateSaturation, r}));
	g.push_back(hysteresisTheta({K::RateSign, kMovingRate_Cpm}));
	return g;
}

int hysteresisFamily(double theta) { return static_cast<int>(hysteresisShapeOf(theta).kind); }

std::string describeHysteresisTheta(double theta)
{
	const auto shape = hysteresisShapeOf(theta);
	char buf[96];
	switch (shape.kind)
	{
		case HysteresisShape::Kind::ExponentialBranch:
			std::snprintf(buf, sizeof buf, "exponential branch, span %.3g C", shape.width);
			break;
		case HysteresisShape::Kind::Play:
			std::snprintf(buf, sizeof buf, "play operator, half-width %.3g C", shape.width);
			break;
		case HysteresisShape::Kind::RateSaturation:
			std::snprintf(buf, sizeof buf, "rate saturation, tanh(dT/dt / %.3g C/min)", shape.width);
			break;
		case HysteresisShape::Kind::RateSign:
			std::snprintf(buf, sizeof buf, "sign of the rate (dead band %.3g C/min)", shape.width);
			break;
	}
	return buf;
}

namespace
{
using Mat = Eigen::MatrixXd;

double f0(double v) { return std::isfinite(v) ? v : 0.0; }

Mat column(const std::vector<double>& v, double scale = 1.0)
{
	Mat m(static_cast<Eigen::Index>(v.size()), 1);
	for (std::size_t k = 0; k < v.size(); ++k) m(static_cast<Eigen::Index>(k), 0) = scale * f0(v[k]);
	return m;
}

std::string needInnerOuter(const RunSignals& s)
{
	return s.has_inner_outer ? "" : "needs inner and outer thermistors";
}
std::string always(const RunSignals&) { return ""; }

/** Low-pass (first-order, time constant tau_s) of a column, restarted at each block. */
std::vector<double> firstOrderLag(const RunSignals& s, const std::vector<double>& u, double tau_s)
{
	std::vector<double> y(u.size(), 0.0);
	for (std::size_t k = 0; k < u.size(); ++k)
	{
		if (k == 0 || s.block[k] != s.block[k - 1] || s.block[k] < 0)
		{
			y[k] = f0(u[k]);
			continue;
		}
		const double a = std::exp(-(s.time_s[k] - s.time_s[k - 1]) / tau_s);
		y[k] = a * y[k - 1] + (1 - a) * f0(u[k]);
	}
	return y;
}

std::vector<CandidateEffect> makeLibrary();
}  // namespace

HeatingCoolingCoverage heatingCoolingCoverage(const RunSignals& s, double moving_rate_Cpm)
{
	HeatingCoolingCoverage c;
	double hLo = INFINITY, hHi = -INFINITY, cLo = INFINITY, cHi = -INFINITY;
	const bool coil = s.temp_coil_C.size() == s.size() && s.dtemp_coil_dt_Cpm.size() == s.size();
	const auto& Tc = coil ? s.temp_coil_C : s.temp_mean_C;
	const auto& rate = coil ? s.dtemp_coil_dt_Cpm : s.dtemp_dt_Cpm;
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		if (!s.usable[k] || !std::isfinite(Tc[k])) continue;
		const double r = rate[k], T = Tc[k];
		const double dt = k > 0 ? std::min(s.time_s[k] - s.time_s[k - 1], 3.0 * s.dt_s) : s.dt_s;
		if (r >= moving_rate_Cpm)
		{
			c.heating_s += dt;
			hLo = std::min(hLo, T);
			hHi = std::max(hHi, T);
		}
		else if (r <= -moving_rate_Cpm)
		{
			c.cooling_s += dt;
			cLo = std::min(cLo, T);
			cHi = std::max(cHi, T);
		}
	}
	if (c.heating_s > 0) c.heating_C = {hLo, hHi};
	if (c.cooling_s > 0) c.cooling_C = {cLo, cHi};
	if (c.heating_s > 0 && c.cooling_s > 0) c.shared_span_C = std::max(0.0, std::min(hHi, cHi) - std::max(hLo, cLo));
	return c;
}

std::string hysteresisUntestableReason(const RunSignals& s)
{
	const auto c = heatingCoolingCoverage(s);
	char buf[300];
	if (c.heating_s < 600 || c.cooling_s < 600)
	{
		std::snprintf(buf, sizeof buf,
					  "the run does not both heat and cool (heating %.0f s, cooling %.0f s at |dT/dt| >= 0.05 C/min; "
					  "at least 600 s of each is needed)",
					  c.heating_s, c.cooling_s);
		return buf;
	}
	if (c.shared_span_C < 1.0)
	{
		std::snprintf(buf, sizeof buf,
					  "heating (%.1f..%.1f C) and cooling (%.1f..%.1f C) share %.2f C of temperature range "
					  "(at least 1 C is needed)",
					  c.heating_C.first, c.heating_C.second, c.cooling_C.first, c.cooling_C.second, c.shared_span_C);
		return buf;
	}
	return {};
}

namespace
{
using Builder = decltype(CandidateEffect::build);
using UntestableReason = decltype(CandidateEffect::untestable_reason);

/** The candidate of a registry effect: its id and residual channel are the registry's. */
CandidateEffect candidateOf(sim::Effect effect, const char* description, const char* excited_by,
							const char* coefficient_unit, Builder build, UntestableReason untestable_reason)
{
	const auto& d = sim::descriptorOf(effect);
	CandidateEffect c;
	c.id = d.id;
	c.channel = d.identified_in == sim::IdentifiedIn::Temperature ? ResidualChannel::Temperature : ResidualChannel::Bias;
	c.description = description;
	c.excited_by = excited_by;
	c.coefficient_unit = coefficient_unit;
	c.build = std::move(build);
	c.untestable_reason = std::move(untestable_reason);
	return c;
}

/** The same with a nonlinear parameter found by profile search over `grid`. */
CandidateEffect withTheta(CandidateEffect c, const char* name, std::vector<double> grid)
{
	c.theta_name = name;
	c.theta_grid = std::move(grid);
	return c;
}

// Two columns when inner and outer thermistors exist: the mean rate (the seed paper's dT/dt
// term) and the radial rate difference. The Shupe integral of seed eq. (1) has zero-sum weights
// (integral of (2z - L) over the fibre is 0), so a uniform rate gives no Shupe bias; what surface
// thermistors can see of it is the rate of the radial difference. (Without inner/outer
// thermistors only dT/dt: coefficient in deg/h per degC/min.)
Eigen::MatrixXd shupeColumns(const CandidateContext& ctx, double)
{
	const auto& s = *ctx.sig;
	if (!s.has_inner_outer) return column(s.dtemp_dt_Cpm);
	Mat m(static_cast<Eigen::Index>(s.size()), 2);
	m.col(0) = column(s.dtemp_dt_Cpm);
	m.col(1) = column(s.dgradient_dt_Cpm);
	return m;
}

// Tin - Tout; with thermistors on neither side also Tout - Tother: a surface thermistor reads a
// mixture of coil layers and its mount, so the coil's radial gradient is a combination of the
// two differences with weights the run must tell (no coil geometry assumed).
Eigen::MatrixXd radialGradientColumns(const CandidateContext& ctx, double)
{
	const auto& s = *ctx.sig;
	if (s.outer_other_C.size() != s.size()) return column(s.gradient_C);
	Mat m(static_cast<Eigen::Index>(s.size()), 2);
	m.col(0) = column(s.gradient_C);
	m.col(1) = column(s.outer_other_C);
	return m;
}

Eigen::MatrixXd thermistorLagColumn(const CandidateContext& ctx, double)
{
	const auto d = localSlopePerMin(ctx.sig->time_s, ctx.base_static_dph, ctx.sig->block, 120.0);
	return column(d);
}

Eigen::MatrixXd warmupColumns(const CandidateContext& ctx, double tau_s)
{
	const auto& s = *ctx.sig;
	// column 0: after the power-on transitions seen in the run; column 1: from the run start
	// when the run starts powered (same decay, free amplitude)
	const bool startsPowered = !s.power_on_s.empty() && s.size() > 0 && s.power_on_s.front() <= s.time_s.front();
	const bool transitions = s.power_on_s.size() > (startsPowered ? 1u : 0u);
	std::vector<double> after(s.size(), 0.0), start(s.size(), 0.0);
	std::size_t on = 0;
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		while (on + 1 < s.power_on_s.size() && s.power_on_s[on + 1] <= s.time_s[k]) ++on;
		if (s.power_on_s.empty() || s.time_s[k] < s.power_on_s[on] || s.power[k] < 0.5) continue;
		const double v = std::exp(-(s.time_s[k] - s.power_on_s[on]) / tau_s);
		(startsPowered && on == 0 ? start : after)[k] = v;
	}
	if (transitions && startsPowered)
	{
		Mat m(static_cast<Eigen::Index>(s.size()), 2);
		m.col(0) = column(after);
		m.col(1) = column(start);
		return m;
	}
	return column(transitions ? after : start);
}

// a turn-on must be seen (power 0 -> 1): a run powered from its first sample does not say when
// the gyro was switched on, so a decay from the run start is not identified
std::string warmupUntestableReason(const RunSignals& s)
{
	for (double t_on : s.power_on_s)
		if (s.size() > 0 && t_on > s.time_s.front()) return std::string();
	return std::string("no turn-on in the run (power never goes from 0 to 1)");
}

Eigen::MatrixXd scaleFactorColumn(const CandidateContext& ctx, double)
{
	const auto& s = *ctx.sig;
	double sum = 0;
	std::size_t m = 0;
	for (std::size_t k = 0; k < s.size(); ++k)
		if (s.usable[k])
		{
			sum += s.temp_mean_C[k];
			++m;
		}
	const double Tm = m ? sum / m : 20.0;
	std::vector<double> v(s.size());
	for (std::size_t k = 0; k < v.size(); ++k) v[k] = 1e-6 * (f0(s.temp_mean_C[k]) - Tm) * s.table_rate_dph[k];
	return column(v);
}

Eigen::MatrixXd tempPolyColumns(const CandidateContext& ctx, double)
{
	const auto n = static_cast<Eigen::Index>(ctx.static_temp_C.size());
	Mat m(n, 2);
	for (Eigen::Index k = 0; k < n; ++k)
	{
		const double x = scaledTemp(f0(ctx.static_temp_C[static_cast<std::size_t>(k)]));
		m(k, 0) = std::pow(x, ctx.base_static_order + 1);
		m(k, 1) = std::pow(x, ctx.base_static_order + 2);
	}
	return m;
}

/** The inputs of the simulator's additive terms at each sample of a measured run: the radial
 * gradient, the axial field and the time since the last power-on at or before the sample (+inf
 * before the first); the electronics temperature is not measured (NaN). */
std::vector<sim::EffectTermInputs> termInputs(const RunSignals& s)
{
	std::vector<sim::EffectTermInputs> in(s.size());
	std::size_t on = 0;
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		while (on < s.power_on_s.size() && s.power_on_s[on] <= s.time_s[k]) ++on;
		in[k].gradient_C = s.gradient_C[k];
		in[k].field_uT = s.field_uT[k];
		in[k].time_since_power_on_s =
			on > 0 ? s.time_s[k] - s.power_on_s[on - 1] : std::numeric_limits<double>::infinity();
		in[k].electronics_C = std::numeric_limits<double>::quiet_NaN();
	}
	return in;
}

/** The effect's simulator term per coefficient on each sample of the run (NaN where not finite). */
std::vector<double> termPerCoefficient(const sim::EffectDescriptor& d, const RunSignals& s)
{
	const sim::ErrorCoefficients shape;  // the default device's shape fields
	const auto in = termInputs(s);
	std::vector<double> v(in.size());
	for (std::size_t k = 0; k < in.size(); ++k) v[k] = d.bias_per_coefficient(in[k], shape);
	return v;
}

/** The hand-written candidates: effects whose column is not their simulator term per
 * coefficient on the measured run (the term needs the simulator's state, a nonlinear parameter
 * is searched, the column is split, or the untestable reason says more). */
std::vector<CandidateEffect> handWrittenCandidates()
{
	using sim::Effect;
	std::vector<CandidateEffect> lib;
	lib.push_back(candidateOf(
		Effect::ShupeRate,
		"Shupe effect: temperature rates along the fibre make the two counter-propagating beams see "
		"different optical paths; sum_k w_k dT_k/dt with zero-sum winding weights, seen by surface "
		"thermistors as d(Tin - Tout)/dt, plus the mean-rate term dT/dt of empirical models",
		"temperature steps and a sine sweep (rates of several sizes)", "deg/h (RMS of the fitted rate terms)",
		shupeColumns, always));
	lib.push_back(candidateOf(
		Effect::RadialGradient,
		"elasto-optic / thermal-stress term: bias proportional to the radial gradient Tin - Tout, "
		"persisting while the gradient lasts",
		"a sine sweep near the coil's radial time constant and soaks right after fast steps", "deg/h per degC",
		radialGradientColumns, needInnerOuter));
	lib.push_back(candidateOf(
		Effect::GradientRate,
		"rate of the radial gradient d(Tin - Tout)/dt (radial heat-flow transients), as the thermistors see it "
		"or through a first-order lag (the gradient inside the winding follows the surface difference late)",
		"temperature steps and a sine sweep near the coil's radial time constant", "deg/h per degC/min",
		[](const CandidateContext& ctx, double lag_s) {
			return lag_s > 0 ? column(firstOrderLag(*ctx.sig, ctx.sig->dgradient_dt_Cpm, lag_s))
							 : column(ctx.sig->dgradient_dt_Cpm);
		},
		needInnerOuter));
	// the gradient inside the winding follows the surface thermistors' difference through the
	// fibre pack's own heat diffusion: a first-order lag of lag_s (0: none), on a doubling grid
	lib.back().theta_name = "lag_s";
	lib.back().theta_grid = {0, 60, 120, 240, 480, 960};
	lib.back().describe_theta = [](double lag_s) {
		if (!(lag_s > 0)) return std::string("no lag: the rate of the thermistors' difference itself");
		char buf[160];
		std::snprintf(buf, sizeof buf, "the rate of the thermistors' difference through a first-order lag of %.0f s",
					  lag_s);
		return std::string(buf);
	};
	lib.push_back(candidateOf(
		Effect::ThermistorLag,
		"thermistor lag: the thermistors read the coil temperature late by tau, so the static model "
		"f(T) misses tau * d/dt f(T) (tau < 0: the temperature driving the static bias leads the "
		"thermistors, e.g. electronics)",
		"ramps and steps in temperature bands where the static bias slope differs", "s (tau)", thermistorLagColumn,
		always));
	lib.back().coefficient_scale = 60.0;  // column is per minute
	lib.push_back(withTheta(
		candidateOf(Effect::Hysteresis,
					"heating vs cooling hysteresis: a bias offset of opposite sign on the heating and the cooling "
					"branch, kept through soaks, swapping over a temperature span (an exponential branch, or a "
					"play (backlash) operator: adhesive and jacket stress in a wound coil), or an offset that "
					"saturates with the temperature rate and returns to 0 at soaks (tanh or sign of the rate)",
					"ramps at several rates (the offset does not scale with the rate) and soaks after heating "
					"and after cooling",
					"deg/h (half heating-cooling difference)",
					[](const CandidateContext& ctx, double theta) { return column(hysteresisColumn(*ctx.sig, theta)); },
					hysteresisUntestableReason),
		"width_C", hysteresisThetaGrid()));
	lib.back().describe_theta = describeHysteresisTheta;
	lib.back().theta_continuous = true;  // a width within each shape
	lib.back().theta_family = hysteresisFamily;
	lib.push_back(withTheta(
		candidateOf(Effect::Warmup,
					"turn-on warm-up: a bias decaying as exp(-(t - t_on)/tau) after each power-on (a run that starts "
					"powered gets its own amplitude: how long before it the gyro was switched on is unknown)",
					"power cycles at constant chamber temperature",
					"deg/h at power-on (RMS of the fitted terms when the run also starts powered)", warmupColumns,
					warmupUntestableReason),
		"tau_s", {60, 120, 240, 480, 900, 1800, 3600, 7200}));
	lib.push_back(candidateOf(
		Effect::ScaleFactorTemp,
		"temperature-dependent scale factor (source wavelength): an error (T - Tmean) x applied rate",
		"rate-table segments at several temperatures", "ppm/degC", scaleFactorColumn, [](const RunSignals& s) {
			return s.has_table ? std::string() : std::string("no rate-table segments in the run");
		}));
	lib.push_back(candidateOf(
		Effect::Magnetic, "Faraday (magnetic) sensitivity: bias proportional to the axial field",
		"field segments (applied axial field switched on and off)", "deg/h per uT",
		[](const CandidateContext& ctx, double) { return column(ctx.sig->field_uT); },
		[](const RunSignals& s) { return s.has_field ? std::string() : std::string("no field segments in the run"); }));
	lib.push_back(candidateOf(Effect::TempPolyOrder,
							  "static temperature polynomial too low: the next two powers of the temperature",
							  "soaks at several temperature levels across the full range", "deg/h (RMS of the added terms)",
							  tempPolyColumns, always));
	lib.push_back(withTheta(
		candidateOf(Effect::HeatSource,
					"unmodelled internal heat source (electronics, source): the inner coil warms by a first-order "
					"response to power",
					"power cycles", "degC at full power",
					[](const CandidateContext& ctx, double tau_s) {
						return column(firstOrderLag(*ctx.sig, ctx.sig->power, tau_s));
					},
					always),
		"tau_s", {120, 300, 600, 1200, 2400, 4800}));
	return lib;
}

/** One candidate per effect a residual identifies, in the registry's order: its hand-written
 * candidate, else the one its simulator term per coefficient gives. */
std::vector<CandidateEffect> makeLibrary()
{
	const auto written = handWrittenCandidates();
	std::vector<CandidateEffect> lib;
	for (const auto& d : sim::effectDescriptors())
	{
		if (d.identified_in == sim::IdentifiedIn::NotIdentified) continue;
		const auto it = std::find_if(written.begin(), written.end(), [&](const CandidateEffect& c) { return c.id == d.id; });
		if (it != written.end())
			lib.push_back(*it);
		else if (d.bias_per_coefficient && d.identified_in == sim::IdentifiedIn::Bias)
			lib.push_back(candidateFromTerm(d));
		else
			throw std::logic_error(std::string("effect registry: ") + d.id +
								   " is identified in a residual but has neither a term per coefficient nor a "
								   "hand-written candidate (CandidateEffect.cpp)");
	}
	for (auto& c : lib)
		if (c.theta_grid.empty()) c.theta_grid = {0.0};
	return lib;
}
}  // namespace

CandidateEffect candidateFromTerm(const sim::EffectDescriptor& d)
{
	if (!d.bias_per_coefficient)
		throw std::invalid_argument(std::string("candidateFromTerm: effect ") + d.id + " has no term per coefficient");
	CandidateEffect c = candidateOf(
		d.effect, d.summary, d.identified_by, d.coefficient_unit,
		[d](const CandidateContext& ctx, double) { return column(termPerCoefficient(d, *ctx.sig)); },
		[d](const RunSignals& s)
		{
			const auto v = termPerCoefficient(d, s);
			for (std::size_t k = 0; k < v.size(); ++k)
				if (s.usable[k] && std::isfinite(v[k]) && v[k] != 0.0) return std::string();
			return std::string("the run does not excite it (its simulator term is zero on every usable sample)");
		});
	c.theta_grid = {0.0};
	return c;
}

const std::vector<CandidateEffect>& candidateLibrary()
{
	static const std::vector<CandidateEffect> lib = makeLibrary();
	return lib;
}

const CandidateEffect& candidateById(const std::string& id)
{
	for (const auto& c : candidateLibrary())
		if (c.id == id) return c;
	throw std::invalid_argument("unknown candidate effect id '" + id + "'");
}

const std::string& candidateDescription(const std::string& id) { return candidateById(id).description; }

std::string separationAdvice(const std::string& a, const std::string& b)
{
	using sim::Effect;
	const Effect ea = sim::effectFromId(a), eb = sim::effectFromId(b);
	auto is = [&](Effect x, Effect y) { return (ea == x && eb == y) || (ea == y && eb == x); };
	if (is(Effect::ShupeRate, Effect::ThermistorLag))
		return "steps and ramps in several temperature bands (a thermistor lag scales with the local slope of the "
			   "static bias curve, the Shupe term does not)";
	if (is(Effect::ShupeRate, Effect::Hysteresis))
		return "ramps at several rates and a sine sweep (Shupe scales with the rate, hysteresis does not)";
	if (is(Effect::ShupeRate, Effect::RadialGradient) || is(Effect::RadialGradient, Effect::ThermistorLag))
		return "a sine sweep near the coil's radial time constant and fast steps (the gradient lags the rate)";
	if (is(Effect::ShupeRate, Effect::GradientRate))
		return "no chamber profile with surface thermistors, when the Shupe weights are those of a symmetric "
			   "winding: the Shupe integral has zero-sum weights, so what the thermistors see of it is the rate of "
			   "the radial difference (in the simulator the two truths correlate 0.996 on the rich profile even at "
			   "1 Hz); a thermistor inside the winding, or a coil of another winding pattern, would";
	if (is(Effect::RadialGradient, Effect::GradientRate))
		return "fast steps and a sine sweep with periods near the coil's radial time constant";
	if (is(Effect::Warmup, Effect::TempPolyOrder) || is(Effect::Warmup, Effect::ThermistorLag) || is(Effect::Warmup, Effect::ShupeRate))
		return "power cycles at constant chamber temperature";
	if (is(Effect::Magnetic, Effect::ScaleFactorTemp))
		return "field segments and rate-table segments at different times and temperatures";
	const auto& ca = candidateById(a);
	const auto& cb = candidateById(b);
	return ca.excited_by + " (for " + a + "); " + cb.excited_by + " (for " + b + ")";
}

}  // namespace mrpt_fog::discrepancy
