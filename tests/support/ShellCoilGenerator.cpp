/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "ShellCoilGenerator.h"
#include <mrpt_fog/obs/Units.h>

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

namespace fogtest
{
namespace
{
using mrpt_fog::units::kNaN;
using mrpt_fog::units::kTwoPi;
constexpr double kTable_dph = 36000.0;  // 10 deg/s

struct Step
{
	double duration_s, from_C, to_C;
	bool on = true;
	double table_dph = 0, field_uT = 0, sine_C = 0, sine_period_s = 0;
};

const std::vector<Step>& chamber()
{
	static const std::vector<Step> p = {
		{1200, 20, 20, false},
		{2400, 20, 20},
		{3600, 20, 40},
		{600, 40, 40},
		{600, 40, 40, true, kTable_dph},
		{300, 40, 40},
		{600, 40, 40, true, -kTable_dph},
		{600, 40, 40},
		{6000, 40, 0},
		{1200, 0, 0},
		{600, 0, 0, true, kTable_dph},
		{300, 0, 0},
		{600, 0, 0, true, -kTable_dph},
		{600, 0, 0},
		{1200, 0, 0, false},
		{1200, 0, 0},
		{600, 0, 20},
		{1800, 20, 20},
		{600, 20, 20, true, 0, 150},
		{600, 20, 20, true, 0, -150},
		{600, 20, 20},
		{4800, 20, 20, true, 0, 0, 6, 2400},
		{2400, 20, 30},
		{1800, 30, 30},
	};
	return p;
}

struct Drive
{
	double setpoint_C, table_dph, field_uT;
	bool on;
};

Drive driveAt(double t)
{
	double t0 = 0;
	const auto& p = chamber();
	for (const auto& s : p)
	{
		if (t < t0 + s.duration_s || &s == &p.back())
		{
			const double u = std::clamp((t - t0) / s.duration_s, 0.0, 1.0);
			double sp = s.from_C + (s.to_C - s.from_C) * u;
			if (s.sine_C > 0) sp += s.sine_C * std::sin(kTwoPi * (t - t0) / s.sine_period_s);
			return {sp, s.table_dph, s.field_uT, s.on};
		}
		t0 += s.duration_s;
	}
	return {p.back().to_C, 0, 0, true};
}

double chamberDuration_s()
{
	double d = 0;
	for (const auto& s : chamber()) d += s.duration_s;
	return d;
}

/** Air A, housing H, hub P, shells S[0..4] (inner to outer). */
struct Net
{
	double A, H, P;
	std::array<double, 5> S;
};

Net rates(const Net& n, double setpoint_C, bool on)
{
	Net d{};
	d.A = (setpoint_C - n.A) / 300.0;
	d.H = (n.A - n.H) / 1500.0 + (n.S[4] - n.H) / 3000.0 + (n.P - n.H) / 5000.0 + (on ? 2.0 / 1500.0 : 0.0);
	d.P = (n.H - n.P) / 2500.0 + (n.S[0] - n.P) / 800.0;
	for (int i = 0; i < 5; ++i)
	{
		double s = 0;
		if (i > 0) s += (n.S[i - 1] - n.S[i]) / 250.0;
		if (i < 4) s += (n.S[i + 1] - n.S[i]) / 250.0;
		if (i == 0) s += (n.P - n.S[0]) / 200.0;
		if (i == 4) s += (n.H - n.S[4]) / 700.0;
		d.S[i] = s;
	}
	return d;
}

double placeTin(const Net& n) { return 0.7 * n.S[0] + 0.3 * n.P; }
double placeTout(const Net& n) { return 0.9 * n.S[4] + 0.1 * n.H; }
double shellMean(const Net& n) { return (n.S[0] + n.S[1] + n.S[2] + n.S[3] + n.S[4]) / 5.0; }

double staticBias(double T) { const double z = (T - 20.0) / 20.0; return 0.5 * z + 0.3 * z * z; }

/** The noise process [deg/h] per sample (white + flicker + rate random walk), before the angle
 * quantisation. */
std::vector<double> noiseSequence(const ShellCoilOptions& o, std::size_t n, std::uint64_t stream)
{
	std::mt19937_64 rng(stream * 0xD1B54A32D192ED03ull + 0x7777);
	std::normal_distribution<double> g(0.0, 1.0);
	const double dt = o.dt_s;
	const double white_sd = o.arw_dpsh * 60.0 / std::sqrt(dt);
	const std::array<double, 5> taus = {10.0, 60.0, 360.0, 2160.0, 12960.0};
	const double part_sd = o.flicker_dph / std::sqrt(double(taus.size()));
	std::array<double, 5> ar{}, phi{};
	for (std::size_t j = 0; j < taus.size(); ++j)
	{
		phi[j] = std::exp(-dt / taus[j]);
		ar[j] = part_sd * g(rng);
	}
	const double rw_sd = o.rrw_dph_per_sqrth * std::sqrt(dt / 3600.0);
	double rw = 0;
	std::vector<double> e(n);
	for (std::size_t k = 0; k < n; ++k)
	{
		double f = 0;
		for (std::size_t j = 0; j < taus.size(); ++j)
		{
			if (k > 0) ar[j] = phi[j] * ar[j] + std::sqrt(1 - phi[j] * phi[j]) * part_sd * g(rng);
			f += ar[j];
		}
		if (k > 0) rw += rw_sd * g(rng);
		e[k] = white_sd * g(rng) + f + rw;
	}
	return e;
}

/** sd of the 100 s averages of a sequence sampled every dt [s]. */
double sdOf100sMeans(const std::vector<double>& e, double dt)
{
	const std::size_t m = std::max<std::size_t>(1, static_cast<std::size_t>(std::llround(100.0 / dt)));
	std::vector<double> means;
	for (std::size_t b = 0; (b + 1) * m <= e.size(); ++b)
	{
		double s = 0;
		for (std::size_t k = b * m; k < (b + 1) * m; ++k) s += e[k];
		means.push_back(s / double(m));
	}
	double mu = 0, v = 0;
	for (double x : means) mu += x;
	mu /= double(means.size());
	for (double x : means) v += (x - mu) * (x - mu);
	return std::sqrt(v / double(means.size() - 1));
}
}  // namespace

const std::vector<std::string>& shellCoilEffects()
{
	static const std::vector<std::string> ids = {"tanh_hysteresis", "scale_factor_temp", "fibre_lag",	   "mid_node_rate",
												 "warmup",			"magnetic",			 "radial_gradient", "gradient_rate"};
	return ids;
}

const std::vector<std::string>& shellCoilAcceptedIds(const std::string& effect)
{
	static const std::map<std::string, std::vector<std::string>> accepted = {
		{"tanh_hysteresis", {"hysteresis"}},
		{"scale_factor_temp", {"scale_factor_temp"}},
		{"fibre_lag", {"thermistor_lag"}},
		{"mid_node_rate", {"shupe_rate", "gradient_rate"}},
		{"warmup", {"warmup"}},
		{"magnetic", {"magnetic"}},
		{"radial_gradient", {"radial_gradient"}},
		{"gradient_rate", {"gradient_rate"}},
	};
	const auto it = accepted.find(effect);
	if (it == accepted.end()) throw std::invalid_argument("shell-coil generator: unknown effect '" + effect + "'");
	return it->second;
}

ShellCoilRun makeShellCoilRun(const ShellCoilOptions& opt)
{
	if (!(opt.dt_s >= 0.01 && opt.dt_s <= 10.0))
		throw std::invalid_argument("shell-coil generator: dt_s must be in [0.01, 10] s");
	for (const auto& [id, ratio] : opt.hidden)
	{
		shellCoilAcceptedIds(id);  // throws for an unknown id
		if (!(ratio >= 0)) throw std::invalid_argument("shell-coil generator: effect ratio must be >= 0");
	}
	const double dt = opt.dt_s;
	const std::size_t n = static_cast<std::size_t>(std::floor(chamberDuration_s() / dt)) + 1;
	std::mt19937_64 rng(opt.seed * 0x9E3779B97F4A7C15ull + 0x3131);
	std::normal_distribution<double> gauss(0.0, 1.0);

	// thermal network from a soaked start (gyro off: no self-heating yet)
	const Drive d0 = driveAt(0.0);
	Net net{d0.setpoint_C, d0.setpoint_C, d0.setpoint_C, {}};
	net.S.fill(d0.setpoint_C);
	double rTin = placeTin(net), rTout = placeTout(net), rTh = net.H;
	const double lag_s = 5.0, sub = std::min(0.5, dt);
	std::vector<double> t(n), on(n), table(n), field(n), Tin(n), dTin(n), M_rate(n), S3(n), dS3(n), grad(n), dgrad(n);
	std::vector<double> readTin(n), readTout(n), readTh(n);
	double time = 0;
	for (std::size_t k = 0; k < n; ++k)
	{
		const double tk = double(k) * dt;
		while (time < tk - 1e-9)
		{
			const double h = std::min(sub, tk - time);
			const Drive dr = driveAt(time);
			const Net r = rates(net, dr.setpoint_C, dr.on);
			net.A += h * r.A;
			net.H += h * r.H;
			net.P += h * r.P;
			for (int i = 0; i < 5; ++i) net.S[i] += h * r.S[i];
			const double a = h / lag_s;
			rTin += a * (placeTin(net) - rTin);
			rTout += a * (placeTout(net) - rTout);
			rTh += a * (net.H - rTh);
			time += h;
		}
		const Drive dr = driveAt(tk);
		const Net r = rates(net, dr.setpoint_C, dr.on);
		t[k] = tk;
		on[k] = dr.on ? 1.0 : 0.0;
		table[k] = dr.table_dph;
		field[k] = dr.field_uT;
		Tin[k] = placeTin(net);
		dTin[k] = 60.0 * (0.7 * r.S[0] + 0.3 * r.P);
		M_rate[k] = 60.0 * (r.S[0] + r.S[1] + r.S[2] + r.S[3] + r.S[4]) / 5.0;
		S3[k] = net.S[2];
		dS3[k] = 60.0 * r.S[2];
		grad[k] = net.S[0] - net.S[4];
		dgrad[k] = 60.0 * (r.S[1] - r.S[3]);
		readTin[k] = rTin;
		readTout[k] = rTout;
		readTh[k] = rTh;
	}
	(void)shellMean;

	ShellCoilRun run;
	// the scaling unit: sd of the 100 s averages of this generator's noise (reference stream)
	run.noise_100s_dph = sdOf100sMeans(noiseSequence(opt, n, 0xABCDEF), dt);
	const bool has_table = std::any_of(table.begin(), table.end(), [](double v) { return v != 0.0; });
	const double b0 = 0.8 + opt.offset_sd_dph * gauss(rng);
	std::vector<std::size_t> rows;
	for (std::size_t k = 0; k < n; ++k)
		if (on[k] > 0.5) rows.push_back(k);
	const Eigen::Index nr = static_cast<Eigen::Index>(rows.size());
	Eigen::MatrixXd X(nr, has_table ? 5 : 4);
	for (Eigen::Index r = 0; r < nr; ++r)
	{
		const std::size_t k = rows[static_cast<std::size_t>(r)];
		const double z = (Tin[k] - 20.0) / 20.0;
		X(r, 0) = 1.0;
		X(r, 1) = z;
		X(r, 2) = z * z;
		X(r, 3) = dTin[k];
		if (has_table) X(r, 4) = table[k] * 1e-6;
	}
	const auto qr = X.colPivHouseholderQr();
	for (const auto& [id, ratio] : opt.hidden)
	{
		std::vector<double> shape(n, 0.0);
		double t_on = -1;
		for (std::size_t k = 0; k < n; ++k)
		{
			if (k > 0 && on[k] > 0.5 && on[k - 1] < 0.5) t_on = t[k];
			if (id == "tanh_hysteresis") shape[k] = std::tanh(M_rate[k] / 0.15);
			else if (id == "scale_factor_temp")
				shape[k] = (S3[k] - 20.0 + 0.02 * (S3[k] - 20.0) * (S3[k] - 20.0)) * table[k] * 1e-6;
			else if (id == "fibre_lag") shape[k] = staticBias(Tin[k] + 240.0 * dTin[k] / 60.0) - staticBias(Tin[k]);
			else if (id == "mid_node_rate") shape[k] = dS3[k];
			else if (id == "warmup")
				shape[k] = t_on >= 0 ? 0.6 * std::exp(-(t[k] - t_on) / 90.0) + 0.4 * std::exp(-(t[k] - t_on) / 1200.0) : 0.0;
			else if (id == "magnetic") shape[k] = field[k] * (1.0 + 0.01 * (S3[k] - 20.0));
			else if (id == "radial_gradient") shape[k] = grad[k];
			else if (id == "gradient_rate") shape[k] = dgrad[k];
		}
		Eigen::VectorXd e(nr);
		for (Eigen::Index r = 0; r < nr; ++r) e(r) = shape[rows[static_cast<std::size_t>(r)]];
		const Eigen::VectorXd unexplained = e - X * qr.solve(e);
		const double rms = std::sqrt(unexplained.squaredNorm() / double(std::max<Eigen::Index>(nr, 1)));
		if (!(rms > 1e-12 * (1.0 + e.cwiseAbs().maxCoeff())))
			throw std::invalid_argument("shell-coil generator: effect '" + id + "' is spanned by the base model");
		const double scale = ratio * run.noise_100s_dph / rms;
		auto& out = run.effect_dph[id];
		out.assign(n, 0.0);
		for (std::size_t k = 0; k < n; ++k)
			if (on[k] > 0.5) out[k] = scale * shape[k];
	}

	auto& s = run.series;
	s.sensor_label = "FOG_SHELL";
	s.has_axis = {false, false, true};
	s.thermistors = {{"Tin", mrpt_fog::CoilSide::Inner, 90.0},
					 {"Tout", mrpt_fog::CoilSide::Outer, 270.0},
					 {"Th", mrpt_fog::CoilSide::Other, 0.0}};
	s.temp_C.assign(3, std::vector<double>(n));
	s.time_s = t;
	s.power = on;
	s.rate_dph[2].assign(n, kNaN);
	if (has_table) s.table_rate_dph = table;
	s.field_uT = field;
	s.metadata = {{"latitude_deg", "0"},
				  {"generator", "tests/support/ShellCoilGenerator (five radial shells, hub, housing)"},
				  {"seed", std::to_string(opt.seed)}};
	const auto noise = noiseSequence(opt, n, opt.seed);
	auto quantise = [](double v) { return std::round(v / 0.01) * 0.01; };
	const double q_deg = opt.angle_quantum_arcsec / 3600.0;
	double carry_deg = 0;  // angle not yet output
	for (std::size_t k = 0; k < n; ++k)
	{
		s.temp_C[0][k] = quantise(readTin[k] + 0.002 * gauss(rng));
		s.temp_C[1][k] = quantise(readTout[k] + 0.002 * gauss(rng));
		s.temp_C[2][k] = quantise(readTh[k] + 0.002 * gauss(rng));
		if (on[k] < 0.5)
		{
			carry_deg = 0;
			continue;
		}
		double b = b0 + staticBias(Tin[k]) + 0.3 * dTin[k] + noise[k];
		for (const auto& [id, e] : run.effect_dph) b += e[k];
		const double rate_dph = table[k] + b;
		// output: the angle increment in whole quanta, the rest carried over
		const double angle_deg = carry_deg + rate_dph / 3600.0 * dt;
		const double out_deg = q_deg > 0 ? std::round(angle_deg / q_deg) * q_deg : angle_deg;
		carry_deg = angle_deg - out_deg;
		s.rate_dph[2][k] = out_deg / dt * 3600.0;
	}
	return run;
}

mrpt_fog::FogSeries averagedShellCoilSeries(const mrpt_fog::FogSeries& run, double dt_s, double avg_s)
{
	if (!(dt_s > 0) || !(avg_s > 0)) throw std::invalid_argument("averaged run: dt_s and avg_s must be > 0");
	const std::size_t K = static_cast<std::size_t>(std::llround(avg_s / dt_s));
	if (K <= 1) return run;
	mrpt_fog::FogSeries out = run;
	out.resize(0);
	for (std::size_t b = 0; (b + 1) * K <= run.size(); ++b)
	{
		const std::size_t k0 = b * K;
		out.appendSampleFrom(run, k0);
		double t = 0, r = 0;
		std::vector<double> T(run.thermistorCount(), 0.0);
		for (std::size_t k = k0; k < k0 + K; ++k)
		{
			t += run.time_s[k];
			r += run.rate_dph[2][k];
			for (std::size_t i = 0; i < T.size(); ++i) T[i] += run.temp_C[i][k];
		}
		out.time_s.back() = t / double(K);
		out.rate_dph[2].back() = r / double(K);  // NaN on gyro-off rows, as in the samples
		for (std::size_t i = 0; i < T.size(); ++i) out.temp_C[i].back() = T[i] / double(K);
	}
	return out;
}

}  // namespace fogtest
