/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "support/SimEffectTrial.h"
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
/** Static cubic of the thermistor-lag runs [deg/h], x = (T - 20)/50 (same as the synthetic
 * generator's static bias). */
double staticCubic_dph(double temp_C)
{
	const double x = (temp_C - 20.0) / 50.0;
	return 0.3 + x * (1.5 + x * (0.8 - 0.6 * x));
}

/** A simulated run with its per-sample truth. */
struct RawRun
{
	FogSeries series;
	std::vector<double> thermal_error_dph;  //!< all enabled thermal terms (simulator truth)
	std::vector<double> thermistor_mean_C;  //!< mean thermistor reading (as read)
};

struct DeviceSetup
{
	sim::FogDevice device = sim::FogDevice::defaultDevice();
	sim::EffectSet effects{"earth_rate"};
	bool static_cubic = false;  //!< add staticCubic_dph(true temperature at the thermistors)
};

RawRun simulate(const sim::ChamberProfile& profile, const DeviceSetup& d, double rate_hz, std::uint64_t seed)
{
	sim::FogSimulator sim(d.device, d.effects, seed);
	const double dt = 1.0 / rate_hz;
	const auto n = static_cast<std::size_t>(std::floor(profile.duration_s() * rate_hz + 1e-9)) + 1;
	bool uses_table = false, uses_field = false;
	for (const auto& s : profile.segments())
	{
		if (s.kind == sim::ProfileSegment::Kind::Table && s.value != 0) uses_table = true;
		if (s.kind == sim::ProfileSegment::Kind::Field && s.value != 0) uses_field = true;
	}
	RawRun r;
	FogSeries& out = r.series;
	out.sensor_label = "FOG";
	out.epoch_s = sim::kSimEpoch_s;
	out.has_axis = {false, false, true};
	for (const auto& t : d.device.thermistors) out.thermistors.push_back(t.info);
	out.temp_C.assign(d.device.thermistors.size(), {});
	const auto& th = sim.thermal();
	const int S = d.device.thermal.sectors, L = d.device.thermal.layers;
	for (std::size_t k = 0; k < n; k++)
	{
		const double t = static_cast<double>(k) / rate_hz;
		const sim::ChamberState st = profile.stateAt(t);
		const sim::FogSample s = k == 0 ? sim.start(st, profile.initialState()) : sim.advance(dt, st);
		double rate = s.rate_dph;
		if (d.static_cubic && s.power_on)
		{
			// true temperature at the thermistor positions (their node, nearest sector)
			const auto& T = sim.nodeTemperatures_C();
			double sum = 0;
			for (const auto& ts : d.device.thermistors)
			{
				const int layer = ts.info.side == CoilSide::Outer ? L - 1 : 0;
				const int sector = static_cast<int>(std::lround(ts.info.angle_deg / 360.0 * S)) % S;
				sum += T(th.coilNode(layer, (sector + S) % S));
			}
			rate += staticCubic_dph(sum / static_cast<double>(d.device.thermistors.size()));
		}
		out.time_s.push_back(t);
		out.rate_dph[2].push_back(rate);
		double tm = 0;
		for (std::size_t i = 0; i < s.temp_C.size(); i++)
		{
			out.temp_C[i].push_back(s.temp_C[i]);
			tm += s.temp_C[i];
		}
		r.thermistor_mean_C.push_back(tm / static_cast<double>(s.temp_C.size()));
		out.power.push_back(s.power_on ? 1.0 : 0.0);
		if (uses_table) out.table_rate_dph.push_back(st.table_rate_dph);
		if (uses_field) out.field_uT.push_back(st.field_uT);
		r.thermal_error_dph.push_back(s.power_on ? s.thermal_error_dph : 0.0);
	}
	return r;
}

/** Reference setting of the hidden effect's parameter, multiplied by `scale`. */
void applyScale(DeviceSetup& d, const std::string& id, double scale, SimTrialDevice& info)
{
	auto& e = d.device.errors;
	info.scale = scale;
	// effects with one scalar coefficient in errors (the registry's descriptor names it)
	for (const auto& de : sim::effectDescriptors())
		if (double* c = sim::coefficientIn(de, e); id == de.id && c && de.identified_in == sim::IdentifiedIn::Bias)
		{
			*c *= scale;
			info.parameter = de.coefficient_key;
			info.parameter_value = *c;
			return;
		}
	if (id == "shupe_rate")
	{
		d.device.winding.dn_dT_per_K *= scale;
		d.device.winding.expansion_per_K *= scale;
		info.parameter = "coil.dn_dT_per_K (and expansion_per_K alike)";
		info.parameter_value = d.device.winding.dn_dT_per_K;
	}
	else if (id == "temp_poly_order")
	{
		e.temp_poly_dph = {0.0, 0.0, 0.0, 1e-6 * scale, -2e-8 * scale};
		info.parameter = "errors.temp_poly_dph[3] (x^4; x^5 = -0.02 x it)";
		info.parameter_value = e.temp_poly_dph[3];
	}
	else if (id == "thermistor_lag")
	{
		for (auto& t : d.device.thermistors) t.tau_s = 10.0 * scale;
		info.parameter = "thermistors[*].tau_s";
		info.parameter_value = 10.0 * scale;
	}
	else
		throw std::invalid_argument("simulator trial: unknown or non-bias effect '" + id + "'");
}

/** RMS over usable rows of the OLS residual of v on the base design. */
double unexplainedRms(const Eigen::MatrixXd& X, const std::vector<double>& v, const RunSignals& sig)
{
	std::vector<std::size_t> rows;
	for (std::size_t k = 0; k < sig.size(); ++k)
		if (sig.usable[k]) rows.push_back(k);
	Eigen::MatrixXd Xr(rows.size(), X.cols());
	Eigen::VectorXd y(rows.size());
	for (std::size_t i = 0; i < rows.size(); ++i)
	{
		Xr.row(static_cast<Eigen::Index>(i)) = X.row(static_cast<Eigen::Index>(rows[i]));
		y(static_cast<Eigen::Index>(i)) = v[rows[i]];
	}
	const auto f = leastSquares(Xr, y);
	return rows.empty() ? 0.0 : std::sqrt(f.rss / static_cast<double>(rows.size()));
}

/** Contribution of the hidden effect: run with it minus the same-seed run without it. */
std::vector<double> contribution(const std::string& id, const RawRun& with, const RawRun& without)
{
	std::vector<double> e(with.thermal_error_dph.size(), 0.0);
	for (std::size_t k = 0; k < e.size(); ++k)
	{
		if (without.series.power[k] < 0.5) continue;
		if (id == "thermistor_lag")
			e[k] = staticCubic_dph(without.thermistor_mean_C[k]) - staticCubic_dph(with.thermistor_mean_C[k]);
		else
			e[k] = with.thermal_error_dph[k] - without.thermal_error_dph[k];
	}
	return e;
}

SimTrialRun finish(RawRun with, const RawRun& without, const std::string& id, const BaseModelSpec& bspec)
{
	SimTrialRun r;
	const auto sig0 = computeRunSignals(without.series);
	const auto base0 = buildBaseDesign(bspec, without.series, sig0);
	r.noise_rms_dph = unexplainedRms(base0.X, sig0.bias_dph, sig0);
	if (!id.empty())
	{
		r.effect_dph = contribution(id, with, without);
		const auto sig = computeRunSignals(with.series);
		r.effect_rms_dph = unexplainedRms(buildBaseDesign(bspec, with.series, sig).X, r.effect_dph, sig);
	}
	r.series = std::move(with.series);
	return r;
}
}  // namespace

const std::vector<std::string>& simTrialEffects()
{
	static const std::vector<std::string> ids = []
	{
		std::vector<std::string> v;  // every bias-channel effect the registry says is trialled
		for (const auto& d : sim::effectDescriptors())
			if (d.identified_in == sim::IdentifiedIn::Bias && *d.trial_scaling) v.push_back(d.id);
		return v;
	}();
	return ids;
}

SimTrialRuns makeSimTrialRuns(const SimTrialSpec& spec)
{
	if (!spec.hidden.empty() && !(spec.ratio > 0))
		throw std::invalid_argument("simulator trial: effect-to-noise ratio must be > 0");
	const auto profile = sim::ChamberProfile::preset(spec.profile);
	const std::uint64_t s1 = 2 * spec.seed + 1, s2 = 2 * spec.seed + 2;
	DeviceSetup base;
	base.static_cubic = spec.hidden == "thermistor_lag";
	SimTrialRuns out;
	out.device.hidden = spec.hidden;
	if (spec.hidden.empty())
	{
		RawRun a = simulate(profile, base, spec.rate_hz, s1), b = simulate(profile, base, spec.rate_hz, s2);
		const auto bspec = resolveBaseModel(spec.base_preset, a.series);
		out.analysed = finish(a, a, "", bspec);
		out.confirm = finish(b, b, "", bspec);
		return out;
	}
	const RawRun without1 = simulate(profile, base, spec.rate_hz, s1);
	const auto bspec = resolveBaseModel(spec.base_preset, without1.series);
	DeviceSetup with = base;
	with.effects.insert(spec.hidden);
	applyScale(with, spec.hidden, 1.0, out.device);
	SimTrialRun ref = finish(simulate(profile, with, spec.rate_hz, s1), without1, spec.hidden, bspec);
	if (!(ref.effect_rms_dph > 0))
		throw std::invalid_argument("simulator trial: effect '" + spec.hidden + "' leaves nothing on profile " +
									spec.profile);
	const double target = spec.ratio * ref.noise_rms_dph;
	double scale = target / ref.effect_rms_dph;
	// the lag is not linear in tau: two secant refinements (computed, not tuned)
	const int refinements = spec.hidden == "thermistor_lag" ? 2 : 0;
	for (int it = 0; it <= refinements; ++it)
	{
		DeviceSetup d = base;
		d.effects.insert(spec.hidden);
		applyScale(d, spec.hidden, scale, out.device);
		out.analysed = finish(simulate(profile, d, spec.rate_hz, s1), without1, spec.hidden, bspec);
		if (it == refinements) break;
		scale *= target / out.analysed.effect_rms_dph;
	}
	DeviceSetup d = base;
	d.effects.insert(spec.hidden);
	applyScale(d, spec.hidden, scale, out.device);
	out.confirm = finish(simulate(profile, d, spec.rate_hz, s2), simulate(profile, base, spec.rate_hz, s2), spec.hidden,
						 bspec);
	return out;
}

TrialOutcome runSimEffectTrial(const SimTrialSpec& spec, const SelectionOptions& opt)
{
	const auto runs = makeSimTrialRuns(spec);
	const auto bspec = resolveBaseModel(spec.base_preset, runs.analysed.series);
	const auto sig1 = computeRunSignals(runs.analysed.series), sig2 = computeRunSignals(runs.confirm.series);
	const auto base1 = buildBaseDesign(bspec, runs.analysed.series, sig1);
	const auto base2 = buildBaseDesign(bspec, runs.confirm.series, sig2);
	auto sel = selectMissingEffects(sig1, base1, opt);
	confirmOnRun(sel, sig2, base2, opt);
	keepConfirmedEffects(sel, sig1, base1);  // the verdict rule of analyseDiscrepancy
	std::vector<std::string> hidden;
	std::vector<std::vector<double>> t1, t2;
	if (!spec.hidden.empty())
	{
		hidden.push_back(spec.hidden);
		t1.push_back(runs.analysed.effect_dph);
		t2.push_back(runs.confirm.effect_dph);
	}
	TrialOutcome out = scoreTrial(hidden, true, sel, sig1, base1, sig2, base2, t1, t2);
	std::ostringstream os;
	os << "sim hidden=" << (spec.hidden.empty() ? "none" : spec.hidden) << "@" << spec.ratio << " seed=" << spec.seed;
	if (!spec.hidden.empty()) os << " " << runs.device.parameter << "=" << runs.device.parameter_value;
	os << " noise=" << runs.analysed.noise_rms_dph << " " << out.summary;
	out.summary = os.str();
	return out;
}

}  // namespace mrpt_fog::discrepancy
