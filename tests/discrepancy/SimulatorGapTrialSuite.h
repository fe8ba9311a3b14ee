/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/** Proof trials of `fog-discrepancy --sim` (SimulatorGap.h) at set effect-to-noise ratios,
 * shared by the default suite (test_SimulatorGap.cpp, 1 seed per cell) and the long suite
 * (long/test_SimulatorGapTrials.cpp, 10 seeds per cell, 100 null trials).
 *
 * Truth ("measured" runs A and B): fog-sim's library, `rich` profile at 0.05 Hz, default device,
 * effects CORE = {shupe_rate, radial_gradient, heat_source, earth_rate, thermistor_lag} plus the
 * hidden effect E, E's size scaled by a knob k (linear in every case, see scaleEffect).
 * Configuration under test: CORE minus E, from WRONG starting values (see baseConfig), default
 * free set. So the bias-channel candidates are always gradient_rate, hysteresis, warmup,
 * scale_factor_temp, magnetic, temp_poly_order (+ E when E is in CORE): a real choice.
 *
 * Effect-to-noise ratio, from the definition (never from trial outcomes; see effectScale):
 *   noise  = RMS of the residual of the calibrated base on noisy runs with NOTHING hidden
 *            (2 reference seeds, not trial seeds): bias over the usable rows with the
 *            calibrated-simulator Jacobian and the table-rate nuisance projected out (the base
 *            design the selector sees), or every thermistor residual for heat_source;
 *   effect = the same RMS on a NOISE-FREE run with E present at size k: the part of E the
 *            calibrated base cannot absorb;
 *   k(ratio) solves effect(k) = ratio x noise (log-secant search, to 2 %).
 * Scoring: "named" = E is the first named id or in its alias group; "clean" = E is the only
 * named id; gap target = on run B the residual RMS (bias, or thermistors for heat_source) falls
 * by >= half of E's share, share = RMS before - RMS of the TRUE model (the truth device and
 * effects, noise-free, i.e. the pure noise floor); null: false naming = anything named.
 */
#include <mrpt_fog/discrepancy/SimulatorGap.h>
#include <mrpt_fog/discrepancy/EffectSelector.h>
#include <mrpt_fog/discrepancy/HeatSourceCandidate.h>
#include <mrpt_fog/discrepancy/RunGapFigures.h>
#include <mrpt_fog/discrepancy/SimulatorCalibration.h>
#include <mrpt_fog/discrepancy/ThermalFit.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace simgap_trials
{
using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

constexpr double kRateHz = 0.05;

inline const sim::EffectSet& coreEffects()
{
	static const sim::EffectSet s{"shupe_rate", "radial_gradient", "heat_source", "earth_rate", "thermistor_lag"};
	return s;
}

/** Every simulator effect that --sim can name (thermistor_lag is a sensor lag, earth_rate not
 * an error: neither is a candidate). */
inline const std::vector<std::string>& hiddenEffects()
{
	static const std::vector<std::string> ids{"heat_source", "shupe_rate",		  "radial_gradient",
											  "gradient_rate", "hysteresis",		  "warmup",
											  "scale_factor_temp", "magnetic", "temp_poly_order"};
	return ids;
}

inline sim::EffectSet truthEffects(const std::string& hidden)
{
	auto s = coreEffects();
	if (!hidden.empty()) s.insert(hidden);
	return s;
}

inline sim::EffectSet baseEffects(const std::string& hidden)
{
	auto s = coreEffects();
	s.erase(hidden);
	return s;
}

/** Multiplies the size of one simulator effect by k. Each knob enters the simulated bias (or the
 * temperatures) linearly: heat_source the electronics power (linear thermal network), shupe_rate
 * dn/dT and the expansion together (the Shupe gain, CoilWinding.h), temp_poly_order every
 * polynomial coefficient, the others their one coefficient. */
inline void scaleEffect(sim::FogDevice& d, const std::string& id, double k)
{
	auto& e = d.errors;
	if (id == "heat_source") d.thermal.electronics_power_W *= k;
	else if (id == "shupe_rate")
	{
		d.winding.dn_dT_per_K *= k;
		d.winding.expansion_per_K *= k;
	}
	else if (id == "radial_gradient") e.radial_gradient_dph_per_C() *= k;
	else if (id == "gradient_rate") e.gradient_rate_dph_per_C_per_min() *= k;
	else if (id == "hysteresis") e.hysteresis_dph() *= k;
	else if (id == "warmup") e.warmup_dph() *= k;
	else if (id == "scale_factor_temp") e.sf_ppm_per_C() *= k;
	else if (id == "magnetic") e.magnetic_dph_per_uT() *= k;
	else if (id == "temp_poly_order")
		for (auto& c : e.temp_poly_dph) c *= k;
	else throw std::invalid_argument("no size knob for effect '" + id + "'");
}

inline sim::FogDevice truthDevice(const std::string& hidden, double k)
{
	auto d = sim::FogDevice::defaultDevice();
	if (!hidden.empty()) scaleEffect(d, hidden, k);
	return d;
}

inline sim::FogDevice quiet(const sim::FogDevice& d) { return d.withoutNoise(); }

inline FogSeries simulateRun(const sim::FogDevice& d, const sim::EffectSet& effects, std::uint64_t seed)
{
	sim::SimSettings st;
	st.rate_hz = kRateHz;
	st.effects = effects;
	st.profile_source = "rich";
	st.seed = seed;
	return sim::simulateChamber(sim::ChamberProfile::preset("rich"), d, st);
}

/** The configuration under test for hidden effect `hidden` (size knob k): CORE minus it, default
 * device with WRONG starting values: elasto-optic 0.7 x the truth, winding asymmetry 0.75 x it,
 * gradient rate 0.05 (0.1), hysteresis 0.01 (0.02), warm-up 0.05 (0.1), SF 10 ppm/C (20),
 * magnetic 1e-4 (2e-4), polynomial x 0.5, electronics 2.0 W (2.5), every heat capacity x 1.1,
 * thermistor offsets 0. The Shupe gain (dn/dT, a material constant) is the truth's. */
inline SimulatorConfig baseConfig(const std::string& hidden, double k)
{
	SimulatorConfig c;
	c.source = "trial config (CORE minus " + (hidden.empty() ? std::string("nothing") : hidden) + ")";
	c.effects = baseEffects(hidden);
	auto& d = c.device;
	if (hidden == "shupe_rate") scaleEffect(d, hidden, k);
	const sim::FogDevice truth = sim::FogDevice::defaultDevice();
	d.errors.radial_gradient_dph_per_C() = 0.7 * truth.errors.radial_gradient_dph_per_C();
	d.winding.midpoint_offset_m = 0.75 * truth.winding.midpoint_offset_m;
	d.errors.gradient_rate_dph_per_C_per_min() = 0.05;
	d.errors.hysteresis_dph() = 0.01;
	d.errors.warmup_dph() = 0.05;
	d.errors.sf_ppm_per_C() = 10;
	d.errors.magnetic_dph_per_uT() = 1e-4;
	for (auto& x : d.errors.temp_poly_dph) x *= 0.5;
	d.thermal.electronics_power_W = 2.0;
	d.thermal.scaleHeatCapacities(1.1);
	for (auto& t : d.thermistors) t.offset_C = 0;
	c.free = defaultFreeParameters(c.effects);
	return c;
}

/** Residual RMS of the calibrated base on a run: bias (Jacobian + table-rate nuisance projected
 * out, usable rows) and every thermistor. */
struct BaseResidual
{
	double bias_rms_dph = 0, temp_rms_C = 0;
};

inline BaseResidual calibratedBaseResidual(const SimulatorConfig& cfg, const FogSeries& run)
{
	const auto sig = computeRunSignals(run);
	const auto drive = chamberDriveForRun(run, cfg);
	const auto cal = calibrateSimulator(simModelFromConfig(cfg), cfg.free, run, drive, sig.bias_dph, sig.usable);
	const Eigen::VectorXd r = biasResidual(sig.bias_dph, cal.trace, sig.usable);
	Eigen::MatrixXd X = cal.bias_jacobian;
	if (sig.has_table)
	{
		X.conservativeResize(Eigen::NoChange, X.cols() + 1);
		for (std::size_t k = 0; k < sig.size(); ++k)
			X(static_cast<Eigen::Index>(k), X.cols() - 1) = sig.usable[k] ? sig.table_rate_dph[k] : 0.0;
	}
	const Eigen::VectorXd rp = r - X * X.colPivHouseholderQr().solve(r);
	std::size_t m = 0;
	for (auto u : sig.usable) m += u != 0;
	return {std::sqrt(rp.squaredNorm() / static_cast<double>(m)), cal.temp_rms_C};
}

/** Size of the hidden effect for a ratio (see file comment). */
struct EffectScale
{
	std::string id;
	bool temperature = false;  //!< ratio on the thermistor residual (heat_source)
	double noise_rms = 0;  //!< deg/h or degC
	double effect_at_default = 0;  //!< contribution at k = 1 (the device's default size)
	std::map<double, double> knob;  //!< ratio -> k
	std::map<double, double> realised;  //!< ratio -> contribution(k) / noise
};

/** k for ratios 1 and 3 by a log-secant search on contribution(k) = ratio x noise (the
 * contribution is not always linear in k: a nonlinear base parameter, the winding asymmetry,
 * absorbs more of a large gradient_rate), to 2 % or 6 evaluations. */
inline EffectScale effectScale(const std::string& id)
{
	static std::map<std::string, EffectScale> cache;
	if (auto it = cache.find(id); it != cache.end()) return it->second;
	EffectScale s;
	s.id = id;
	s.temperature = id == "heat_source";
	auto pick = [&](const BaseResidual& b) { return s.temperature ? b.temp_rms_C : b.bias_rms_dph; };
	double ms = 0;
	for (std::uint64_t seed : {900001u, 900002u})
	{
		const double x = pick(calibratedBaseResidual(baseConfig(id, 1.0), simulateRun(truthDevice("", 1.0), baseEffects(id), seed)));
		ms += x * x / 2;
	}
	s.noise_rms = std::sqrt(ms);
	auto contribution = [&](double k)
	{ return pick(calibratedBaseResidual(baseConfig(id, k), simulateRun(quiet(truthDevice(id, k)), truthEffects(id), 1))); };
	s.effect_at_default = contribution(1.0);
	for (double ratio : {1.0, 3.0})
	{
		const double target = ratio * s.noise_rms;
		double kPrev = 1.0, cPrev = s.effect_at_default;
		double k = target / s.effect_at_default, c = contribution(k);
		for (int it = 0; it < 5 && std::abs(c / target - 1) > 0.02; ++it)
		{
			double slope = std::log(c / cPrev) / std::log(k / kPrev);  // d log c / d log k
			if (!(slope > 0.05) || !std::isfinite(slope)) slope = 1;
			kPrev = k;
			cPrev = c;
			k = k * std::exp(std::log(target / c) / slope);
			c = contribution(k);
		}
		s.knob[ratio] = k;
		s.realised[ratio] = c / s.noise_rms;
	}
	std::printf("SIMGAP-SCALE %-18s noise %.4g %s; default size = ratio %.3g; ratio 1: k = %.4g (realised %.3f); "
				"ratio 3: k = %.4g (realised %.3f)\n",
				id.c_str(), s.noise_rms, s.temperature ? "C" : "deg/h", s.effect_at_default / s.noise_rms, s.knob[1.0],
				s.realised[1.0], s.knob[3.0], s.realised[3.0]);
	std::fflush(stdout);
	cache[id] = s;
	return s;
}

struct TrialOutcome
{
	bool named_ok = false, clean = false, gap_ok = false, false_naming = false;
	std::vector<std::string> named_ids;  //!< strongest first (heat_source first when named)
	std::string summary;
};

/** One trial: `hidden` ("" = null) at `ratio`, runs A/B with seeds 2 seed + 1, 2 seed + 2. */
inline TrialOutcome runTrial(const std::string& hidden, double ratio, std::uint64_t seed)
{
	const double k = hidden.empty() ? 1.0 : effectScale(hidden).knob.at(ratio);
	const auto dev = truthDevice(hidden, k);
	const auto eff = truthEffects(hidden);
	const std::vector<FogSeries> runs{simulateRun(dev, eff, 2 * seed + 1), simulateRun(dev, eff, 2 * seed + 2)};
	const auto cfg = baseConfig(hidden, k);
	const auto rep = analyseSimulatorDiscrepancy(runs, {"A", "B"}, cfg);
	const auto& named = rep.report.selection.named;

	TrialOutcome o;
	std::string ids;
	for (const auto& n : named)
	{
		ids += (ids.empty() ? "" : " ") + n.id;
		o.named_ids.push_back(n.id);
	}
	const bool temp = hidden == "heat_source";
	double before = 0, after = 0, truth = 0;
	{
		SimModel trueModel;
		trueModel.device = dev;
		trueModel.effects = eff;
		const auto& b = runs[1];
		const auto tr = simulateOnRun(trueModel, chamberDriveForRun(b, cfg), b);
		if (temp)
		{
			before = rep.temp_gap_confirm.rms_before_C;
			after = rep.temp_gap_confirm.rms_after_C;
			truth = rmsOfFinite(temperatureResidual(b, tr));
		}
		else
		{
			const auto sig2 = computeRunSignals(b);
			const Eigen::VectorXd rT = biasResidual(sig2.bias_dph, tr, sig2.usable);
			truth = runGapFromResiduals("B", sig2, segmentRun(sig2), rT, rT, sig2.usable, DiscrepancyOptions{}).before.rms_dph;
			before = rep.report.gap_confirm.before.rms_dph;
			after = rep.report.gap_confirm.after.rms_dph;
		}
	}
	if (hidden.empty())
	{
		o.false_naming = !named.empty();
		o.named_ok = named.empty();
		o.clean = named.empty();
		o.gap_ok = std::abs(after - before) < 1e-12;
	}
	else
	{
		if (!named.empty())
		{
			const auto& g = named.front().alias_group;
			o.named_ok = named.front().id == hidden || std::find(g.begin(), g.end(), hidden) != g.end();
		}
		o.clean = named.size() == 1 && named.front().id == hidden;
		o.gap_ok = before - after >= 0.5 * (before - truth);
	}
	char buf[512];
	std::snprintf(buf, sizeof buf, "%s@%g seed %llu (k %.4g): named {%s}; %s RMS on B %.5g -> %.5g (true model %.5g)",
				  hidden.empty() ? "none" : hidden.c_str(), ratio, static_cast<unsigned long long>(seed), k, ids.c_str(),
				  temp ? "thermistor [C]" : "bias [deg/h]", before, after, truth);
	o.summary = buf;
	return o;
}

struct Tally
{
	int trials = 0, named = 0, clean = 0, gap_ok = 0, false_naming = 0;
	std::vector<std::string> misses;
};

inline Tally runSeeds(const std::string& hidden, double ratio, int seeds, std::uint64_t first_seed, bool verbose = false)
{
	Tally t;
	for (int s = 0; s < seeds; ++s)
	{
		const auto o = runTrial(hidden, ratio, first_seed + static_cast<std::uint64_t>(s));
		++t.trials;
		t.named += o.named_ok;
		t.clean += o.clean;
		t.gap_ok += o.gap_ok;
		t.false_naming += o.false_naming;
		if (verbose) std::printf("  %s\n", o.summary.c_str());
		if (!o.named_ok || !o.gap_ok) t.misses.push_back(o.summary);
	}
	return t;
}

/** Exact (Clopper-Pearson) 95 % interval of a binomial proportion k / n. */
inline std::pair<double, double> clopperPearson95(int k, int n)
{
	auto cdf = [&](int x, double p)  // P(X <= x)
	{
		double s = 0;
		for (int i = 0; i <= x; ++i)
			s += std::exp(std::lgamma(n + 1.0) - std::lgamma(i + 1.0) - std::lgamma(n - i + 1.0) + i * std::log(p) +
						  (n - i) * std::log1p(-p));
		return s;
	};
	auto solve = [&](auto f)  // f increasing in p, root of f(p) = 0 on (0, 1)
	{
		double lo = 0, hi = 1;
		for (int it = 0; it < 100; ++it)
		{
			const double mid = 0.5 * (lo + hi);
			(f(mid) < 0 ? lo : hi) = mid;
		}
		return 0.5 * (lo + hi);
	};
	const double low = k == 0 ? 0.0 : solve([&](double p) { return 0.975 - cdf(k - 1, p); });  // P(X >= k) = 0.025
	const double high = k == n ? 1.0 : solve([&](double p) { return 0.025 - cdf(k, p); });  // P(X <= k) = 0.025
	return {low, high};
}

inline void print(const std::string& hidden, double ratio, const Tally& t)
{
	if (hidden.empty())
	{
		const auto [lo, hi] = clopperPearson95(t.false_naming, t.trials);
		std::printf("SIMGAP %-18s ratio -   false naming %d/%d = %.1f %% (95 %% CI %.1f .. %.1f %%)\n", "none",
					t.false_naming, t.trials, 100.0 * t.false_naming / t.trials, 100 * lo, 100 * hi);
	}
	else
		std::printf("SIMGAP %-18s ratio %g   named %d/%d  clean %d/%d  gap target %d/%d\n", hidden.c_str(), ratio, t.named,
					t.trials, t.clean, t.trials, t.gap_ok, t.trials);
	for (const auto& m : t.misses) std::printf("  miss: %s\n", m.c_str());
	std::fflush(stdout);
}

}  // namespace simgap_trials
