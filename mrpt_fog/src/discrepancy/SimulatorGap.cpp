/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/SimulatorGap.h>
#include <mrpt_fog/discrepancy/EffectSelector.h>
#include <mrpt_fog/discrepancy/HeatSourceCandidate.h>
#include <mrpt_fog/discrepancy/RunGapFigures.h>
#include <mrpt_fog/discrepancy/SimulatorCalibration.h>
#include <mrpt_fog/discrepancy/ThermalFit.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
void addUnique(std::vector<std::string>& v, const std::string& s)
{
	if (!s.empty() && std::find(v.begin(), v.end(), s) == v.end()) v.push_back(s);
}

std::vector<std::string> effectList(const sim::EffectSet& e) { return {e.begin(), e.end()}; }

std::vector<std::pair<std::string, double>> calibratedValues(const SimCalibration& c)
{
	std::vector<std::pair<std::string, double>> out;
	for (const auto* slots : {&c.temp_slots, &c.bias_slots})
		for (const auto& s : *slots) out.emplace_back(s.label(), getParam(c.model, s));
	for (const auto& t : c.model.device.thermistors) out.emplace_back("thermistor_offsets_C[" + t.info.name + "]", t.offset_C);
	return out;
}

std::vector<std::pair<std::string, double>> calibratedCi95(const SimCalibration& c)
{
	std::vector<std::pair<std::string, double>> out;
	for (std::size_t j = 0; j < c.temp_slots.size() && j < c.temp_ci95_half.size(); ++j)
		out.emplace_back(c.temp_slots[j].label(), c.temp_ci95_half[j]);
	for (std::size_t j = 0; j < c.bias_slots.size() && j < c.bias_ci95_half.size(); ++j)
		out.emplace_back(c.bias_slots[j].label(), c.bias_ci95_half[j]);
	return out;
}

/** The calibrated simulator, linearised, as the selector's base design. */
BaseDesign simulatorBaseDesign(const SimCalibration& c, const RunSignals& sig)
{
	BaseDesign b;
	b.X = c.bias_jacobian;
	for (const auto& s : c.bias_slots)
	{
		b.names.push_back("d(sim)/d(" + s.label() + ")");
		const bool poly = s.id == "temp_poly_dph";
		b.is_static_temp.push_back(poly ? 1 : 0);
		b.is_nuisance.push_back(0);
		if (poly) b.max_static_order = std::max(b.max_static_order, s.index + 1);
	}
	// static temperature of the temp_poly_order candidate: the thermistor mean. The simulator's
	// own (the electronics temperature, SimTrace::electronics_C) was tried: hysteresis was still
	// named first with temp_poly_order hidden, since the candidate adds powers 2 and 3 only while
	// the hidden polynomial is mostly linear (docs/guide/model-gap-simulator.md)
	b.static_temp_C = sig.temp_mean_C;
	if (sig.has_table)
	{
		// nuisance: a constant scale-factor error (the nominal scale factor is never exact), as
		// in the bias-model base designs
		b.X.conservativeResize(Eigen::NoChange, b.X.cols() + 1);
		for (std::size_t k = 0; k < sig.size(); ++k)
			b.X(static_cast<Eigen::Index>(k), b.X.cols() - 1) = sig.usable[k] ? sig.table_rate_dph[k] * 1e-4 : 0.0;
		b.names.push_back("table_rate");
		b.is_static_temp.push_back(0);
		b.is_nuisance.push_back(0);
	}
	return b;
}

/** Log-drive mode: nuisance columns for the configured effects' response to the thermal content
 * the reconstructed air does not resolve, i.e. to the thermistors' measured-minus-simulated
 * difference d: each thermistor's d(d_i)/dt (the Shupe term and any rate effect follow node
 * rates) and d(Tin) - d(Tout) (the radial gradient). `meas` and `simu` are the signals on the
 * measured and on the simulated thermistors (same usable rows). Such a response cannot be told
 * from a missing effect of the same form, so it is taken out of every candidate's test. */
void addUnresolvedThermalColumns(BaseDesign& b, const RunSignals& meas, const RunSignals& simu)
{
	std::vector<std::vector<double>> cols;
	std::vector<std::string> names;
	for (std::size_t i = 0; i < meas.dthermistor_dt_Cpm.size() && i < simu.dthermistor_dt_Cpm.size(); ++i)
	{
		std::vector<double> c(meas.size(), 0.0);
		for (std::size_t k = 0; k < meas.size(); ++k)
			if (meas.usable[k]) c[k] = meas.dthermistor_dt_Cpm[i][k] - simu.dthermistor_dt_Cpm[i][k];
		cols.push_back(std::move(c));
		names.push_back("unresolved d(T" + std::to_string(i) + ")/dt");
	}
	if (meas.has_inner_outer)
	{
		std::vector<double> c(meas.size(), 0.0);
		for (std::size_t k = 0; k < meas.size(); ++k)
			if (meas.usable[k]) c[k] = meas.gradient_C[k] - simu.gradient_C[k];
		cols.push_back(std::move(c));
		names.push_back("unresolved Tin - Tout");
	}
	for (std::size_t j = 0; j < cols.size(); ++j)
	{
		b.X.conservativeResize(Eigen::NoChange, b.X.cols() + 1);
		for (std::size_t k = 0; k < cols[j].size(); ++k) b.X(static_cast<Eigen::Index>(k), b.X.cols() - 1) = cols[j][k];
		b.names.push_back(names[j]);
		b.is_static_temp.push_back(0);
		b.is_nuisance.push_back(1);
	}
}

/** Share of the residual energy on the usable rows that columns [p0, end) of X explain beyond
 * columns [0, p0): 1 - RSS(all) / RSS(first p0). 0 when nothing is left to explain. */
double explainedShare(const Eigen::MatrixXd& X, std::size_t p0, const Eigen::VectorXd& r, const std::vector<unsigned char>& usable)
{
	std::vector<Eigen::Index> rows;
	for (std::size_t k = 0; k < usable.size(); ++k)
		if (usable[k] && std::isfinite(r(static_cast<Eigen::Index>(k)))) rows.push_back(static_cast<Eigen::Index>(k));
	const auto n = static_cast<Eigen::Index>(rows.size());
	if (n <= X.cols()) return 0.0;
	auto rss = [&](Eigen::Index cols)
	{
		Eigen::MatrixXd A(n, cols + 1);
		Eigen::VectorXd y(n);
		for (Eigen::Index i = 0; i < n; ++i)
		{
			A(i, 0) = 1.0;  // the mean is not the unresolved content's
			A.row(i).tail(cols) = X.row(rows[static_cast<std::size_t>(i)]).head(cols);
			y(i) = r(rows[static_cast<std::size_t>(i)]);
		}
		const Eigen::VectorXd e = y - A * A.colPivHouseholderQr().solve(y);
		return e.squaredNorm();
	};
	const double base = rss(static_cast<Eigen::Index>(p0));
	return base > 0 ? std::max(0.0, 1.0 - rss(X.cols()) / base) : 0.0;
}

RunSignals withBias(RunSignals sig, const Eigen::VectorXd& r)
{
	for (std::size_t k = 0; k < sig.size(); ++k) sig.bias_dph[k] = r(static_cast<Eigen::Index>(k));
	return sig;
}

TemperatureGap temperatureGap(const std::string& label, const FogSeries& run, const SimTrace& before, const SimTrace& after)
{
	TemperatureGap g;
	g.label = label;
	const auto rb = temperatureResidual(run, before), ra = temperatureResidual(run, after);
	g.rms_before_C = rmsOfFinite(rb);
	g.rms_after_C = rmsOfFinite(ra);
	for (std::size_t i = 0; i < run.thermistorCount(); ++i)
	{
		g.names.push_back(run.thermistors[i].name);
		g.rms_before_per_C.push_back(rmsOfFinite({rb[i]}));
		g.rms_after_per_C.push_back(rmsOfFinite({ra[i]}));
	}
	return g;
}

/** The run's signals with every thermistor reading replaced by the calibrated simulator's (where
 * both exist), for the bias candidates when the drive comes from the log alone. The bias
 * residual is measured minus SIMULATED bias, and the simulated coil follows the reconstructed
 * air, which cannot follow air changes faster than its knots (steps, minute-period cycles: the
 * housing leaves them near the thermistors' noise). The gyro's response to that fast part stays
 * in the residual, and a candidate built from the MEASURED thermistors (d(Tin - Tout)/dt above
 * all) tracks it: on fog-sim `rich` with nothing missing a gradient_rate was named (chi2 336,
 * docs/guide/model-gap-simulator.md). Built from the simulated thermistors the candidates see the thermal
 * state the residual is relative to; a missing effect then has to show on the thermal history the
 * simulator reproduces. With a profile the simulated and measured thermistors agree to their noise
 * and the measured signals are kept. */
RunSignals signalsOnSimulatedThermistors(const FogSeries& run, const SimTrace& trace, const RunSignals& measured,
										 const RunSignalsOptions& opt)
{
	FogSeries s = run;
	for (std::size_t i = 0; i < s.thermistorCount() && i < trace.temp_C.size(); ++i)
		for (std::size_t k = 0; k < s.size(); ++k)
			if (std::isfinite(s.temp_C[i][k]) && std::isfinite(trace.temp_C[i][k])) s.temp_C[i][k] = trace.temp_C[i][k];
	RunSignals out = computeRunSignals(s, opt);
	out.bias_dph = measured.bias_dph;
	if (out.usable != measured.usable)
		throw std::logic_error("simulated thermistor signals changed the usable samples");  // same NaN pattern by construction
	return out;
}

NamedEffect heatNamedEffect(const HeatSourceResult& h)
{
	NamedEffect ne;
	ne.id = "heat_source";
	ne.alias_group = {"heat_source"};
	ne.confidence = ne.group_confidence = h.confidence;
	ne.coefficient = h.amplitude_C;
	ne.ci_low = h.ci_low_C;
	ne.ci_high = h.ci_high_C;
	ne.coefficient_unit = "degC at full power (mean over thermistors)";
	ne.theta_name = "tau_s";
	ne.theta = h.tau_s;
	ne.chi2 = h.chi2;
	ne.p_adjusted = h.p_adjusted;
	ne.delta_bic = h.delta_bic;
	return ne;
}
}  // namespace

SimDiscrepancyReport analyseSimulatorDiscrepancy(const std::vector<FogSeries>& runs, const std::vector<std::string>& labels,
												 const SimulatorConfig& cfg, const SimDiscrepancyOptions& opt)
{
	if (runs.empty()) throw std::invalid_argument("no measured run given");
	if (runs.size() > 2) throw std::invalid_argument("at most two measured runs: the first is analysed, the second confirms");
	if (runs.size() == 2 && !runs[0].sameLayout(runs[1]))
		throw std::invalid_argument("the confirmation run has a different thermistor/axis layout from the first run");
	SimDiscrepancyReport R;
	auto& rep = R.report;
	rep.model_source = cfg.source;
	rep.tau_s = opt.base.tau_s;
	for (std::size_t i = 0; i < runs.size(); ++i)
		rep.run_labels.push_back(i < labels.size() ? labels[i] : "run " + std::to_string(i + 1));
	R.config_source = cfg.source;

	// 1. drive + calibrate the configuration as given
	const RunSignals sig1 = computeRunSignals(runs[0], opt.base.signals);
	ChamberDrive drive1 = chamberDriveForRun(runs[0], cfg);
	R.drive = drive1.how;
	std::vector<std::string> free0 = cfg.free;
	if (std::find(free0.begin(), free0.end(), "constant_bias_dph") == free0.end())
		free0.insert(free0.begin(), "constant_bias_dph");  // the turn-on bias is never known in advance
	const SimModel model0 = simModelFromConfig(cfg);
	SimModel startModel = model0;
	if (drive1.source == DriveSource::MeasuredLog)
		// From the log alone the absolute temperature is known only up to the thermistors' common
		// offset (the reconstructed air absorbs their mean; ChamberReconstruction.h), so the scale
		// factor's reference temperature is free with its slope: k (T - T_ref) then depends on
		// temperature differences only. With T_ref fixed, a common offset d biases the slope by
		// -d / (T - T_ref) over the table segments: on fog-sim `rich` (T - 25 ~ -2.5 C there) the
		// default device's offsets (mean -0.01 C) gave 19.94 for 20 ppm/C (docs/guide/model-gap-simulator.md).
		// Active only when scale_factor_temp is on (expandSlots).
		addUnique(free0, "sf_ref_C");
	const bool logDrive = drive1.source == DriveSource::MeasuredLog;
	if (logDrive)
	{
		// the air was reconstructed through the network as configured: the thermal parameters by
		// variable projection (the air re-reconstructed for each trial), then the calibration
		const ProjectedThermal pt = projectThermalOnLogDrive(model0, free0, drive1, runs[0]);
		startModel = pt.model;
		drive1 = pt.drive;
		R.drive = drive1.how + "; thermal parameters by variable projection over the reconstructed air";
		R.simulations += pt.simulations;
	}
	const SimCalibration cal0 = calibrateSimulator(startModel, free0, runs[0], drive1, sig1.bias_dph, sig1.usable);
	R.simulations += cal0.simulations;
	if (drive1.source == DriveSource::MeasuredLog)
	{
		R.drive_air_knots = drive1.air.knot_time_s.size();
		R.drive_air_fit_rms_C = drive1.air.fit_rms_C;
		R.drive_air_ci95_mean_C = drive1.air.mean_ci95_half_C;
		R.drive_air_ci95_max_C = drive1.air.max_ci95_half_C;
	}
	R.effects_before = effectList(model0.effects);
	R.free_before = free0;
	R.calibrated_before = calibratedValues(cal0);
	R.calibrated_before_ci95_half = calibratedCi95(cal0);
	for (const auto& s : cal0.bias_slots) rep.base_terms.push_back(s.label());
	for (const auto& s : cal0.temp_slots) rep.base_terms.push_back(s.label());

	// 2. temperature channel: heat_source
	SimCalibration calT = cal0;
	std::vector<std::string> freeT = free0;
	if (model0.effects.count("heat_source"))
	{
		R.heat.untestable_reason = "heat_source is already on in the configuration";
		R.heat.sentence = "heat_source not tested: already in the model";
	}
	else
	{
		R.heat = testHeatSource(sig1.time_s, runs[0].power, temperatureResidual(runs[0], cal0.trace), runs[0].thermistors,
								opt.heat);
		if (R.heat.named)
		{
			SimModel m = cal0.model;
			m.effects.insert("heat_source");
			m.device.thermal.electronics_power_W = cfg.device.thermal.electronics_power_W;
			addUnique(freeT, "electronics_power_W");
			calT = calibrateSimulator(m, freeT, runs[0], drive1, sig1.bias_dph, sig1.usable);
			R.simulations += calT.simulations;
		}
	}

	// 2b. the thermal fit, judged before the optical part
	R.thermal = assessThermalFit(runs[0], temperatureResidual(runs[0], calT.trace), opt.thermal);

	// 3.+4. bias channel, simulator in the loop: the existing selector on the calibrated
	// simulator's residual names the strongest missing effect; it is switched on in the simulator
	// (its own physics, not the candidate's linear proxy), the simulator recalibrated, and the
	// selector asked again, until nothing is significant (at most max_effects rounds).
	struct Stage
	{
		SimCalibration cal;
		std::vector<std::string> free;
		NamedEffect named;
	};
	std::vector<Stage> stages;  // stage i: model before effect i was switched on
	SimCalibration calA = calT;
	std::vector<std::string> freeA = freeT;
	SelectionOptions selOpt = opt.base.selection;
	selOpt.max_effects = 1;
	bool firstRound = true;
	const int rounds = R.thermal.misfit ? 0 : std::max(1, opt.base.selection.max_effects);
	if (R.thermal.misfit)
	{
		rep.selection.fit_rows = sig1.usable;
		rep.selection.residual_before = rep.selection.residual_after = biasResidual(sig1.bias_dph, calA.trace, sig1.usable);
	}
	for (int round = 0; round < rounds; ++round)
	{
		std::vector<std::string> candidates;
		for (const auto& c : candidateLibrary())
			if (c.channel == ResidualChannel::Bias && sim::effectFromId(c.id) != sim::Effect::ThermistorLag && !calA.model.effects.count(c.id))
				candidates.push_back(c.id);
		const Eigen::VectorXd r = biasResidual(sig1.bias_dph, calA.trace, sig1.usable);
		const RunSignals candSig =
			logDrive ? signalsOnSimulatedThermistors(runs[0], calA.trace, sig1, opt.base.signals) : sig1;
		SelectionResult sel;
		if (candidates.empty())
		{
			sel.fit_rows = sig1.usable;
			sel.residual_before = sel.residual_after = r;
		}
		else
		{
			selOpt.candidates = candidates;
			BaseDesign base = simulatorBaseDesign(calA, candSig);
			if (logDrive)
			{
				const std::size_t p0 = static_cast<std::size_t>(base.X.cols());
				addUnresolvedThermalColumns(base, sig1, candSig);
				if (firstRound) R.unresolved_share = explainedShare(base.X, p0, r, sig1.usable);
			}
			sel = selectMissingEffects(withBias(candSig, r), base, selOpt);
		}
		if (firstRound) rep.selection = sel;  // candidates_first_round, noise model, fit rows
		firstRound = false;
		if (sel.named.empty()) break;
		const NamedEffect ne = sel.named.front();
		stages.push_back({calA, freeA, ne});
		SimModel m = calA.model;
		m.effects.insert(ne.id);
		if (sim::effectFromId(ne.id) == sim::Effect::Warmup && ne.theta > 0) m.device.errors.warmup_tau_s = ne.theta;
		addUnique(freeA, coefficientParameterOf(ne.id));
		calA = calibrateSimulator(m, freeA, runs[0], drive1, sig1.bias_dph, sig1.usable);
		R.simulations += calA.simulations;
	}
	rep.selection.named.clear();
	for (const auto& st : stages) rep.selection.named.push_back(st.named);
	const bool changed = R.heat.named || !stages.empty();
	if (R.heat.named) rep.selection.named.insert(rep.selection.named.begin(), heatNamedEffect(R.heat));
	R.effects_after = effectList(calA.model.effects);
	R.free_after = freeA;
	R.calibrated_after = calibratedValues(calA);
	R.calibrated_after_ci95_half = calibratedCi95(calA);

	const auto& rows1 = rep.selection.fit_rows.empty() ? sig1.usable : rep.selection.fit_rows;
	const auto segs1 = segmentRun(sig1, opt.base.segmentation);
	rep.gap = runGapFromResiduals(rep.run_labels[0], sig1, segs1, biasResidual(sig1.bias_dph, cal0.trace, rows1),
								  biasResidual(sig1.bias_dph, calA.trace, rows1), rows1, opt.base);
	R.temp_gap = temperatureGap(rep.run_labels[0], runs[0], cal0.trace, changed ? calA.trace : cal0.trace);

	// 5. confirmation run: parameters from run 1, only the constant bias re-estimated
	if (runs.size() == 2)
	{
		rep.has_confirm = true;
		const RunSignals sig2 = computeRunSignals(runs[1], opt.base.signals);
		const ChamberDrive drive2 = reconstructDriveWith(chamberDriveForRun(runs[1], cfg), cal0.model, runs[1]);
		R.drive_confirm = drive2.how;
		const SimCalibration b2 = applyCalibration(cal0.model, free0, runs[1], drive2, sig2.bias_dph, sig2.usable);
		const SimCalibration a2 = applyCalibration(calA.model, freeA, runs[1], drive2, sig2.bias_dph, sig2.usable);
		R.simulations += b2.simulations + a2.simulations;
		if (R.heat.named)
		{
			R.heat_confirm = confirmHeatSource(sig2.time_s, runs[1].power, temperatureResidual(runs[1], b2.trace), R.heat.tau_s,
											   opt.base.selection.alias_alpha, opt.heat.lrv_max_lag);
			auto& ne = rep.selection.named.front();
			ne.confirm_tested = R.heat_confirm.tested;
			ne.confirmed = R.heat_confirm.confirmed;
			ne.confirm_p = R.heat_confirm.p;
			ne.confirm_coefficient = R.heat_confirm.amplitude_C;
		}
		// each bias effect is confirmed against the stage it was named at
		const std::size_t first = R.heat.named ? 1 : 0;
		for (std::size_t i = 0; i < stages.size(); ++i)
		{
			const SimCalibration t2 = applyCalibration(stages[i].cal.model, stages[i].free, runs[1], drive2,
													   sig2.bias_dph, sig2.usable);
			R.simulations += t2.simulations;
			SelectionResult sel;
			sel.named = {stages[i].named};
			const RunSignals candSig2 =
				drive2.source == DriveSource::MeasuredLog
					? signalsOnSimulatedThermistors(runs[1], t2.trace, sig2, opt.base.signals)
					: sig2;
			BaseDesign base2 = simulatorBaseDesign(t2, candSig2);
			if (drive2.source == DriveSource::MeasuredLog) addUnresolvedThermalColumns(base2, sig2, candSig2);
			confirmOnRun(sel, withBias(candSig2, biasResidual(sig2.bias_dph, t2.trace, sig2.usable)), base2,
						 opt.base.selection);
			rep.selection.named[first + i] = sel.named.front();
		}
		rep.gap_confirm = runGapFromResiduals(rep.run_labels[1], sig2, segmentRun(sig2, opt.base.segmentation),
											  biasResidual(sig2.bias_dph, b2.trace, sig2.usable),
											  biasResidual(sig2.bias_dph, a2.trace, sig2.usable), sig2.usable, opt.base);
		R.temp_gap_confirm = temperatureGap(rep.run_labels[1], runs[1], b2.trace, a2.trace);
	}
	return R;
}

}  // namespace mrpt_fog::discrepancy
