/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "support/SyntheticChamberRun.h"

#include <mrpt_fog/common/EnumNames.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
constexpr double kPi = 3.14159265358979323846;

/** One profile segment of the chamber air temperature and lab conditions. */
struct Seg
{
	double dur_s;
	double T_end;  //!< end temperature (ramp: linear; step: jumps at start)
	bool step = false;
	bool sweep = false;  //!< log sine sweep around T_end, amplitude 8 C, periods 2400 -> 240 s
	double power = 1.0;
	double table_dph = 0.0;
	double field_uT = 0.0;
};

std::vector<Seg> profileSegments(SyntheticProfile profile)
{
	const double min = 60.0;
	if (profile == SyntheticProfile::Ramp)
		return {{20 * min, 25}, {65 * min, -40}, {120 * min, -40}};
	if (profile == SyntheticProfile::LongRamp)
		return {{10 * min, 25}, {520 * min, -40}};
	return {
		{30 * min, 25},
		{65 * min, -40},
		{45 * min, -40},
		{40 * min, -20, true},
		{20 * min, 0, true},
		{10 * min, 0, false, false, 1, 3600},
		{10 * min, 0, false, false, 1, -3600},
		{30 * min, 60},
		{10 * min, 60},
		{10 * min, 60, false, false, 1, 3600},
		{10 * min, 60, false, false, 1, -3600},
		{80 * min, 20},
		{100 * min, 20, false, true},
		{15 * min, 20, true, false, 1, 0, 100},
		{10 * min, 20},
		{15 * min, 20, false, false, 1, 0, -100},
		{10 * min, 20},
		{20 * min, 20, false, false, 0},
		{40 * min, 20},
		{60 * min, -10},
		{10 * min, -10, false, false, 1, 3600},
		{10 * min, -10, false, false, 1, -3600},
		{35 * min, 25},
		{30 * min, 25},
	};
}

struct Conditions
{
	std::vector<double> air_C, power, table_dph, field_uT;  // at 1 s
};

Conditions buildConditions(const std::vector<Seg>& segs)
{
	Conditions c;
	double T = segs.front().T_end;
	for (const auto& s : segs)
	{
		const int n = static_cast<int>(std::lround(s.dur_s));
		const double T0 = s.step ? s.T_end : T;
		const double f0 = 1.0 / 2400.0, f1 = 1.0 / 240.0, k = f1 / f0;
		for (int i = 0; i < n; ++i)
		{
			const double t = i + 1.0;
			double Ta;
			if (s.sweep)
			{
				const double ph = 2 * kPi * f0 * s.dur_s / std::log(k) * (std::pow(k, t / s.dur_s) - 1.0);
				Ta = s.T_end + 8.0 * std::sin(ph);
			}
			else
				Ta = T0 + (s.T_end - T0) * t / s.dur_s;
			c.air_C.push_back(Ta);
			c.power.push_back(s.power);
			c.table_dph.push_back(s.table_dph);
			c.field_uT.push_back(s.field_uT);
		}
		T = s.sweep ? s.T_end : s.T_end;
	}
	return c;
}

std::vector<double> lagFirstOrder(const std::vector<double>& u, double tau_s)
{
	std::vector<double> y(u);
	if (tau_s <= 0) return y;
	const double a = std::exp(-1.0 / tau_s);
	for (std::size_t k = 1; k < u.size(); ++k) y[k] = a * y[k - 1] + (1 - a) * u[k];
	return y;
}

double staticBias(double T, const double c[4])
{
	const double x = (T - 20.0) / 50.0;
	return c[0] + c[1] * x + c[2] * x * x + c[3] * x * x * x;
}

/** RMS of v's part orthogonal to {1, x, x^2, x^3} of T on the rows where mask is set. */
double unexplainedRms(const std::vector<double>& v, const std::vector<double>& T, const std::vector<unsigned char>& mask)
{
	std::vector<std::size_t> rows;
	for (std::size_t k = 0; k < v.size(); ++k)
		if (mask[k]) rows.push_back(k);
	Eigen::MatrixXd X(rows.size(), 4);
	Eigen::VectorXd y(rows.size());
	for (std::size_t i = 0; i < rows.size(); ++i)
	{
		const double x = (T[rows[i]] - 20.0) / 50.0;
		X.row(i) << 1, x, x * x, x * x * x;
		y(i) = v[rows[i]];
	}
	const Eigen::VectorXd r = y - X * X.colPivHouseholderQr().solve(y);
	return std::sqrt(r.squaredNorm() / std::max<std::size_t>(1, rows.size()));
}
}  // namespace

const char* toString(SyntheticProfile p)
{
	static constexpr EnumName<SyntheticProfile> kNames[] = {{SyntheticProfile::Ramp, "ramp"},
															{SyntheticProfile::LongRamp, "long_ramp"},
															{SyntheticProfile::AllConditions, "all_conditions"}};
	return nameIn(kNames, p, "all_conditions");
}

SyntheticRun makeSyntheticChamberRun(const SyntheticRunOptions& opt)
{
	for (const auto& [id, r] : opt.hidden)
	{
		static const std::vector<std::string> known{"shupe_rate", "radial_gradient", "gradient_rate",
													"thermistor_lag", "hysteresis", "warmup",
													"scale_factor_temp", "magnetic", "temp_poly_order"};
		if (std::find(known.begin(), known.end(), id) == known.end())
			throw std::invalid_argument("synthetic generator cannot hide effect '" + id + "'");
		if (!(r > 0)) throw std::invalid_argument("effect-to-noise ratio of '" + id + "' must be > 0");
	}
	if (!(opt.dt_s >= 1.0)) throw std::invalid_argument("dt_s must be >= 1 s");
	const Conditions cond = buildConditions(profileSegments(opt.profile));
	const std::size_t nf = cond.air_C.size();

	// thermal network at 1 s (exact first-order steps with the air piecewise constant)
	const double tauOut = 900.0, tauIn = 240.0;
	std::vector<double> To(nf), Ti(nf);
	double o = cond.air_C[0], i = cond.air_C[0];
	const double ao = std::exp(-1.0 / tauOut), ai = std::exp(-1.0 / tauIn);
	for (std::size_t k = 0; k < nf; ++k)
	{
		o = ao * o + (1 - ao) * cond.air_C[k];
		i = ai * i + (1 - ai) * o;
		To[k] = o;
		Ti[k] = i;
	}
	const std::size_t step = static_cast<std::size_t>(std::lround(opt.dt_s));
	std::vector<std::size_t> at;  // fine index of each output sample
	for (std::size_t k = 1; k + 1 < nf; k += step) at.push_back(k);
	const std::size_t n = at.size();

	std::mt19937_64 rng(opt.seed * 7919 + 17);
	std::normal_distribution<double> N01(0.0, 1.0);
	std::mt19937_64 rngCoef(opt.seed * 104729 + 3);

	std::vector<double> Tm(n), G(n), dTm(n), dG(n), pw(n), tab(n), fld(n), t(n);
	for (std::size_t k = 0; k < n; ++k)
	{
		const std::size_t f = at[k];
		t[k] = static_cast<double>(f);
		Tm[k] = 0.5 * (Ti[f] + To[f]);
		G[k] = Ti[f] - To[f];
		dTm[k] = 60.0 * 0.25 * ((Ti[f + 1] + To[f + 1]) - (Ti[f - 1] + To[f - 1]));
		dG[k] = 60.0 * 0.5 * ((Ti[f + 1] - To[f + 1]) - (Ti[f - 1] - To[f - 1]));
		pw[k] = cond.power[f];
		tab[k] = cond.table_dph[f];
		fld[k] = cond.field_uT[f];
	}
	std::vector<unsigned char> on(n);
	for (std::size_t k = 0; k < n; ++k) on[k] = pw[k] > 0.5;

	double coef[4] = {0.3, 1.5, 0.8, -0.6};
	if (opt.static_coef_error > 0)
		for (double& c : coef) c *= 1.0 + opt.static_coef_error * N01(rngCoef);

	SyntheticRun out;
	out.noise_rms_dph = std::hypot(opt.white_noise_dph, opt.ar_noise_dph);
	const double target = out.noise_rms_dph;

	// thermistor readings (lag first, offsets, noise, quantisation)
	auto readThermistors = [&](double tau_s)
	{
		const auto li = lagFirstOrder(Ti, tau_s), lo = lagFirstOrder(To, tau_s);
		std::vector<std::vector<double>> r(4, std::vector<double>(n));
		const double off[4] = {0.03, -0.02, 0.04, -0.03};
		for (std::size_t k = 0; k < n; ++k)
		{
			r[0][k] = li[at[k]] + off[0];
			r[1][k] = li[at[k]] + off[1];
			r[2][k] = lo[at[k]] + off[2];
			r[3][k] = lo[at[k]] + off[3];
		}
		return r;
	};
	auto meanOf = [&](const std::vector<std::vector<double>>& r)
	{
		std::vector<double> m(n);
		for (std::size_t k = 0; k < n; ++k) m[k] = 0.25 * (r[0][k] + r[1][k] + r[2][k] + r[3][k]);
		return m;
	};

	std::vector<double> bias(n, 0.0);
	for (std::size_t k = 0; k < n; ++k) bias[k] = staticBias(Tm[k], coef);
	double thermTau = 0.0;
	for (const auto& [id, ratio] : opt.hidden)
	{
		std::vector<double> e(n, 0.0);
		if (id == "thermistor_lag")
		{
			// tau found so that the unexplained part reaches the ratio (3 secant-like updates)
			double tau = 30.0;
			for (int it = 0; it < 4; ++it)
			{
				const auto m = meanOf(readThermistors(tau));
				for (std::size_t k = 0; k < n; ++k) e[k] = staticBias(Tm[k], coef) - staticBias(m[k] - 0.005, coef);
				const double u = unexplainedRms(e, Tm, on);
				if (!(u > 0)) break;
				tau *= ratio * target / u;
			}
			thermTau = tau;
			const auto m = meanOf(readThermistors(tau));
			for (std::size_t k = 0; k < n; ++k) e[k] = staticBias(Tm[k], coef) - staticBias(m[k] - 0.005, coef);
		}
		else
		{
			// play-type hysteresis of the true coil mean on the 1 s grid (span 2 C), as in the simulator
			std::vector<double> branch(n, 0.0);
			if (id == "hysteresis")
			{
				double state = 0.0;
				std::size_t next = 0;
				for (std::size_t f = 1; f < nf && next < n; ++f)
				{
					const double dT = 0.5 * ((Ti[f] + To[f]) - (Ti[f - 1] + To[f - 1]));
					if (dT != 0.0)
					{
						const double target = dT > 0 ? 1.0 : -1.0;
						state = target + (state - target) * std::exp(-std::fabs(dT) / 2.0);
					}
					if (f == at[next]) branch[next++] = state;
				}
			}
			for (std::size_t k = 0; k < n; ++k)
			{
				const double x = (Tm[k] - 20.0) / 50.0;
				if (id == "shupe_rate") e[k] = dTm[k];
				else if (id == "radial_gradient") e[k] = G[k];
				else if (id == "gradient_rate") e[k] = dG[k];
				else if (id == "hysteresis") e[k] = branch[k];
				else if (id == "scale_factor_temp") e[k] = (Tm[k] - 25.0) * tab[k] * 1e-6;
				else if (id == "magnetic") e[k] = fld[k];
				else if (id == "temp_poly_order") e[k] = 0.6 * std::pow(x, 4) - 0.4 * std::pow(x, 5);
			}
			if (id == "warmup")
			{
				double tOn = 0.0;
				for (std::size_t k = 0; k < n; ++k)
				{
					if (k > 0 && on[k] && !on[k - 1]) tOn = t[k];
					e[k] = on[k] ? std::exp(-(t[k] - tOn) / 700.0) : 0.0;
				}
			}
			const double u = unexplainedRms(e, Tm, on);
			const double s = u > 0 ? ratio * target / u : 0.0;
			for (auto& v : e) v *= s;
		}
		for (std::size_t k = 0; k < n; ++k) bias[k] += e[k];
		out.effect_dph[id] = e;
	}
	out.thermistor_tau_s = thermTau;

	// noise
	const double phi = std::exp(-opt.dt_s / opt.ar_corr_time_s);
	double ar = opt.ar_noise_dph * N01(rng);
	for (std::size_t k = 0; k < n; ++k)
	{
		ar = phi * ar + std::sqrt(1 - phi * phi) * opt.ar_noise_dph * N01(rng);
		bias[k] += ar + opt.white_noise_dph * N01(rng);
	}
	// outliers: isolated spikes at random powered samples
	std::uniform_int_distribution<std::size_t> pick(10, n - 10);
	for (std::size_t j = 0; j < opt.outliers; ++j)
	{
		const std::size_t k = pick(rng);
		bias[k] += (j % 2 ? -1.0 : 1.0) * opt.outlier_dph;
	}

	auto reads = readThermistors(thermTau);
	for (auto& col : reads)
		for (auto& v : col)
		{
			v += opt.thermistor_noise_C * N01(rng);
			if (opt.thermistor_quantum_C > 0) v = opt.thermistor_quantum_C * std::round(v / opt.thermistor_quantum_C);
		}

	FogSeries& s = out.series;
	s.sensor_label = "FOG_SYN";
	s.has_axis = {{false, false, true}};
	s.thermistors = {{"Ti1", CoilSide::Inner, 0.0}, {"Ti2", CoilSide::Inner, 180.0},
					 {"To1", CoilSide::Outer, 0.0}, {"To2", CoilSide::Outer, 180.0}};
	s.temp_C.assign(4, {});
	const bool hasTable = opt.profile == SyntheticProfile::AllConditions, hasField = hasTable;
	// gap: 20 min in the middle
	const double gapStart = t[n / 2], gapEnd = gapStart + 1200.0;
	for (auto& [id, e] : out.effect_dph) (void)id, (void)e;
	std::map<std::string, std::vector<double>> keptEffects;
	for (std::size_t k = 0; k < n; ++k)
	{
		if (opt.gap && t[k] >= gapStart && t[k] < gapEnd) continue;
		s.time_s.push_back(t[k]);
		s.rate_dph[2].push_back(on[k] ? bias[k] + tab[k] : 0.0);
		for (int j = 0; j < 4; ++j) s.temp_C[j].push_back(reads[j][k]);
		s.power.push_back(pw[k]);
		if (hasTable) s.table_rate_dph.push_back(tab[k]);
		if (hasField) s.field_uT.push_back(fld[k]);
		for (const auto& [id, e] : out.effect_dph) keptEffects[id].push_back(e[k]);
	}
	out.effect_dph = keptEffects;
	s.setMetadata("generator", "mrpt_fog::discrepancy::makeSyntheticChamberRun");
	s.setMetadata("profile", toString(opt.profile));
	s.setMetadata("seed", std::to_string(opt.seed));
	return out;
}

SyntheticRun makeSyntheticChamberRun(double dt_s, std::uint64_t seed, const std::map<std::string, double>& hidden)
{
	SyntheticRunOptions o;
	o.dt_s = dt_s;
	o.seed = seed;
	o.hidden = hidden;
	return makeSyntheticChamberRun(o);
}

}  // namespace mrpt_fog::discrepancy
