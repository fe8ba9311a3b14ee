/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "LumpedCoilGenerator.h"
#include <mrpt_fog/obs/Units.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace fogtest
{
namespace
{
using mrpt_fog::units::kNaN;
using mrpt_fog::units::kTwoPi;

/** One piece of the set-point programme. */
struct Piece
{
	double duration_s;
	double start_C, end_C;  //!< set point, linear over the piece
	bool on = true;
	double table_dph = 0.0;
	double field_uT = 0.0;
	double sine_amp_C = 0.0, sine_period_s = 0.0;
};

std::vector<Piece> programme(const std::string& profile)
{
	const double tbl = 36000.0;  // 10 deg/s [deg/h]
	if (profile == "lab")
		return {
			{600, 25, 25, false},
			{2400, 25, 25},
			{2400, 25, 45},
			{600, 45, 45},
			{600, 45, 45, true, tbl},
			{300, 45, 45},
			{600, 45, 45, true, -tbl},
			{600, 45, 45},
			{4800, 45, 5},
			{1200, 5, 5},
			{1200, 5, 5, false},
			{1200, 5, 5},
			{600, 5, 5, true, tbl},
			{300, 5, 5},
			{600, 5, 5, true, -tbl},
			{600, 5, 5},
			{1200, 25, 25},
			{600, 25, 25, true, 0, 100},
			{600, 25, 25, true, 0, -100},
			{600, 25, 25},
			{3600, 25, 25, true, 0, 0, 8, 1800},
			{1800, 25, 25},
		};
	if (profile == "cooling") return {{2400, 24, 24}, {12000, 24, 16}, {3600, 16, 16}};
	if (profile == "short") return {{1200, 25, 25, true, 0, 0, 0.4, 600}};
	throw std::invalid_argument("lumped-coil generator: unknown profile '" + profile + "' (lab, cooling, short)");
}

struct State
{
	double setpoint_C, table_dph, field_uT;
	bool on;
};

State stateAt(const std::vector<Piece>& prog, double t)
{
	double t0 = 0;
	for (const auto& p : prog)
	{
		if (t < t0 + p.duration_s || &p == &prog.back())
		{
			const double u = std::clamp((t - t0) / p.duration_s, 0.0, 1.0);
			double sp = p.start_C + (p.end_C - p.start_C) * u;
			if (p.sine_amp_C > 0) sp += p.sine_amp_C * std::sin(kTwoPi * (t - t0) / p.sine_period_s);
			return {sp, p.table_dph, p.field_uT, p.on};
		}
		t0 += p.duration_s;
	}
	return {prog.back().end_C, 0, 0, true};
}

double totalDuration(const std::vector<Piece>& prog)
{
	double d = 0;
	for (const auto& p : prog) d += p.duration_s;
	return d;
}

/** Node temperatures and their derivatives [C/s]. */
struct Nodes
{
	double A, H, O, I;
};
Nodes derivative(const Nodes& n, double setpoint_C, bool on)
{
	Nodes d;
	d.A = (setpoint_C - n.A) / 120.0;
	d.H = (n.A - n.H) / 1200.0 + (n.O - n.H) / 2000.0 + (on ? 3.0 / 1200.0 : 0.0);
	d.O = (n.H - n.O) / 400.0 + (n.I - n.O) / 600.0;
	d.I = (n.O - n.I) / 150.0;
	return d;
}

double placeCa(const Nodes& n) { return 0.85 * n.I + 0.15 * n.O; }
double placeCb(const Nodes& n) { return 0.8 * n.O + 0.2 * n.H; }
}  // namespace

const std::vector<std::string>& lumpedCoilEffects()
{
	static const std::vector<std::string> ids = {"hysteresis",	"warmup",		  "scale_factor_temp", "magnetic",
												 "radial_gradient", "gradient_rate", "temp_poly_order"};
	return ids;
}

LumpedCoilRun makeLumpedCoilRun(const LumpedCoilOptions& opt)
{
	if (!(opt.dt_s >= 0.1 && opt.dt_s <= 60.0))
		throw std::invalid_argument("lumped-coil generator: dt_s must be in [0.1, 60] s");
	const auto prog = programme(opt.profile);
	for (const auto& [id, ratio] : opt.hidden)
	{
		if (std::find(lumpedCoilEffects().begin(), lumpedCoilEffects().end(), id) == lumpedCoilEffects().end())
			throw std::invalid_argument("lumped-coil generator: unknown effect '" + id + "'");
		if (!(ratio >= 0)) throw std::invalid_argument("lumped-coil generator: effect ratio must be >= 0");
	}
	std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull + 0x5151);
	std::normal_distribution<double> gauss(0.0, 1.0);

	const double duration = totalDuration(prog);
	const std::size_t n = static_cast<std::size_t>(std::floor(duration / opt.dt_s)) + 1;
	const double sub = 0.25;
	const State s0 = stateAt(prog, 0.0);
	// soaked start: with the gyro on, every node sits at the 3 C self-heating above the air
	const double start_C = s0.setpoint_C + (s0.on ? 3.0 : 0.0);
	Nodes nd{s0.setpoint_C, start_C, start_C, start_C};
	// thermistor readings: first-order 8 s lag of the place temperature
	double rCa = placeCa(nd), rCb = placeCb(nd), rHs = nd.H;
	const double therm_tau_s = 8.0;

	std::vector<double> t(n), M(n), grad(n), dgrad_Cpm(n), Ca_true(n), dCa_Cpm(n), table(n), field(n), on(n);
	std::vector<double> readCa(n), readCb(n), readHs(n);
	double time = 0.0;
	for (std::size_t k = 0; k < n; ++k)
	{
		const double tk = static_cast<double>(k) * opt.dt_s;
		while (time < tk - 1e-9)
		{
			const double h = std::min(sub, tk - time);
			const State st = stateAt(prog, time);
			const Nodes d = derivative(nd, st.setpoint_C, st.on);
			nd.A += h * d.A;
			nd.H += h * d.H;
			nd.O += h * d.O;
			nd.I += h * d.I;
			const double a = h / therm_tau_s;
			rCa += a * (placeCa(nd) - rCa);
			rCb += a * (placeCb(nd) - rCb);
			rHs += a * (nd.H - rHs);
			time += h;
		}
		const State st = stateAt(prog, tk);
		const Nodes d = derivative(nd, st.setpoint_C, st.on);
		t[k] = tk;
		M[k] = 0.5 * (nd.I + nd.O);
		grad[k] = nd.I - nd.O;
		dgrad_Cpm[k] = 60.0 * (d.I - d.O);
		Ca_true[k] = placeCa(nd);
		dCa_Cpm[k] = 60.0 * (0.85 * d.I + 0.15 * d.O);
		table[k] = st.table_dph;
		field[k] = st.field_uT;
		on[k] = st.on ? 1.0 : 0.0;
		readCa[k] = rCa;
		readCb[k] = rCb;
		readHs[k] = rHs;
	}

	LumpedCoilRun run;
	run.noise_rms_dph = std::hypot(opt.white_noise_dph, opt.wander_dph);
	const bool has_table = std::any_of(table.begin(), table.end(), [](double v) { return v != 0.0; });
	const bool has_field = std::any_of(field.begin(), field.end(), [](double v) { return v != 0.0; });
	bool has_turn_on = false;
	for (std::size_t k = 1; k < n; ++k) has_turn_on = has_turn_on || (on[k] > 0.5 && on[k - 1] < 0.5);

	// base bias, on the TRUE temperature at Ca's place
	const double b0 = 1.0 + opt.offset_sd_dph * gauss(rng);
	run.base_bias_dph.assign(n, kNaN);
	std::vector<std::size_t> rows;
	for (std::size_t k = 0; k < n; ++k)
		if (on[k] > 0.5)
		{
			const double z = (Ca_true[k] - 25.0) / 20.0;
			run.base_bias_dph[k] = b0 + 0.6 * z + 0.25 * z * z - 0.15 * z * z * z + 0.4 * dCa_Cpm[k];
			rows.push_back(k);
		}

	// base columns on the true signals, for the "not explained by the base" scaling
	const Eigen::Index nr = static_cast<Eigen::Index>(rows.size());
	Eigen::MatrixXd X(nr, has_table ? 6 : 5);
	for (Eigen::Index r = 0; r < nr; ++r)
	{
		const std::size_t k = rows[static_cast<std::size_t>(r)];
		const double z = (Ca_true[k] - 25.0) / 20.0;
		X(r, 0) = 1.0;
		X(r, 1) = z;
		X(r, 2) = z * z;
		X(r, 3) = z * z * z;
		X(r, 4) = dCa_Cpm[k];
		if (has_table) X(r, 5) = table[k] * 1e-6;
	}
	const auto qr = X.colPivHouseholderQr();

	for (const auto& [id, ratio] : opt.hidden)
	{
		std::vector<double> shape(n, 0.0);
		if (id == "hysteresis")
		{
			const double w = opt.hysteresis_half_width_C;
			if (!(w > 0)) throw std::invalid_argument("lumped-coil generator: hysteresis_half_width_C must be > 0");
			double p = M[0];
			for (std::size_t k = 0; k < n; ++k)
			{
				p = std::min(std::max(p, M[k] - w), M[k] + w);
				shape[k] = (M[k] - p) / w;
			}
		}
		else if (id == "warmup")
		{
			if (!has_turn_on)
				throw std::invalid_argument("lumped-coil generator: warmup needs a turn-on; profile '" + opt.profile +
											"' has none");
			double t_on = -1;
			for (std::size_t k = 0; k < n; ++k)
			{
				if (k > 0 && on[k] > 0.5 && on[k - 1] < 0.5) t_on = t[k];
				shape[k] = t_on >= 0 ? std::exp(-(t[k] - t_on) / 400.0) : 0.0;
			}
		}
		else if (id == "scale_factor_temp")
		{
			if (!has_table)
				throw std::invalid_argument("lumped-coil generator: scale_factor_temp needs table-rate segments; "
											"profile '" + opt.profile + "' has none");
			for (std::size_t k = 0; k < n; ++k) shape[k] = (M[k] - 25.0) * table[k] * 1e-6;
		}
		else if (id == "magnetic")
		{
			if (!has_field)
				throw std::invalid_argument("lumped-coil generator: magnetic needs field changes; profile '" +
											opt.profile + "' has none");
			shape = field;
		}
		else if (id == "radial_gradient")
			shape = grad;
		else if (id == "gradient_rate")
			shape = dgrad_Cpm;
		else if (id == "temp_poly_order")
			for (std::size_t k = 0; k < n; ++k) shape[k] = std::pow((Ca_true[k] - 25.0) / 20.0, 5);
		Eigen::VectorXd e(nr);
		for (Eigen::Index r = 0; r < nr; ++r) e(r) = shape[rows[static_cast<std::size_t>(r)]];
		const Eigen::VectorXd unexplained = e - X * qr.solve(e);
		const double rms = std::sqrt(unexplained.squaredNorm() / static_cast<double>(std::max<Eigen::Index>(nr, 1)));
		if (!(rms > 1e-12 * (1.0 + e.cwiseAbs().maxCoeff())))
			throw std::invalid_argument("lumped-coil generator: effect '" + id + "' is spanned by the base model on "
										"profile '" + opt.profile + "'");
		const double scale = ratio * run.noise_rms_dph / rms;
		auto& out = run.effect_dph[id];
		out.assign(n, 0.0);
		for (std::size_t k = 0; k < n; ++k)
			if (on[k] > 0.5) out[k] = scale * shape[k];
	}

	// series
	auto& s = run.series;
	s.sensor_label = "FOG_LUMPED";
	s.has_axis = {false, false, true};
	s.thermistors = {{"Ca", mrpt_fog::CoilSide::Inner, 30.0},
					 {"Cb", mrpt_fog::CoilSide::Outer, 210.0},
					 {"Hs", mrpt_fog::CoilSide::Other, 0.0}};
	s.temp_C.assign(3, std::vector<double>(n));
	s.time_s = t;
	s.power = on;
	s.rate_dph[2].assign(n, kNaN);
	if (has_table) s.table_rate_dph = table;
	if (has_field) s.field_uT = field;
	s.metadata = {{"latitude_deg", "0"}, {"generator", "tests/support/LumpedCoilGenerator (lumped 3-node coil)"},
				  {"profile", opt.profile}, {"seed", std::to_string(opt.seed)}};
	const double phi = std::exp(-opt.dt_s / opt.wander_tau_s);
	double wander = opt.wander_dph * gauss(rng);
	auto quantise = [](double v) { return std::round(v / 0.01) * 0.01; };
	for (std::size_t k = 0; k < n; ++k)
	{
		if (k > 0) wander = phi * wander + std::sqrt(1.0 - phi * phi) * opt.wander_dph * gauss(rng);
		const double white = opt.white_noise_dph * gauss(rng);
		s.temp_C[0][k] = quantise(readCa[k] + 0.003 * gauss(rng));
		s.temp_C[1][k] = quantise(readCb[k] + 0.003 * gauss(rng));
		s.temp_C[2][k] = quantise(readHs[k] + 0.003 * gauss(rng));
		if (on[k] < 0.5) continue;  // gyro off: no rate sample
		double b = run.base_bias_dph[k] + wander + white;
		for (const auto& [id, e] : run.effect_dph) b += e[k];
		s.rate_dph[2][k] = table[k] + b;
	}
	return run;
}

std::pair<LumpedCoilRun, LumpedCoilRun> makeLumpedCoilRunPair(const std::string& hidden, double ratio,
															   std::uint64_t seed, double dt_s)
{
	LumpedCoilOptions o1, o2;
	o1.dt_s = o2.dt_s = dt_s;
	o1.seed = seed;
	o2.seed = seed + 1;
	o1.hidden[hidden] = o2.hidden[hidden] = ratio;
	return {makeLumpedCoilRun(o1), makeLumpedCoilRun(o2)};
}

}  // namespace fogtest
