/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "GeneralizationBench.h"

#include "DeviceEnsemble.h"
#include "SectorCoilGenerator.h"

#include <mrpt/containers/yaml.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/RateEstimator.h>
#include <mrpt_fog/model/WarmupFit.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace fogtest
{
using mrpt_fog::sim::ChamberProfile;

namespace
{
ChamberProfile fromText(const std::string& name, const std::string& yaml)
{
	return ChamberProfile::fromYaml(mrpt::containers::yaml::FromText(yaml), name);
}
}  // namespace

ChamberProfile calibrationProfile() { return ChamberProfile::preset("seed"); }

std::vector<BenchProfile> evaluationProfiles()
{
	std::vector<BenchProfile> p;
	p.push_back({"B", ChamberProfile::preset("B"), false});
	p.push_back({"heat_first", fromText("heat_first", "name: heat_first\ninitial_temp_C: 25\npower_initially: true\n"
													  "initial_state: steady\nsegments:\n"
													  "  - {type: hold, duration_min: 20}\n"
													  "  - {type: ramp, to_C: 55, rate_C_per_min: 0.5}\n"
													  "  - {type: hold, duration_min: 60}\n"
													  "  - {type: ramp, to_C: -35, rate_C_per_min: 2}\n"
													  "  - {type: hold, duration_min: 60}\n"
													  "  - {type: ramp, to_C: 25, rate_C_per_min: 1}\n"
													  "  - {type: hold, duration_min: 30}\n"),
				 false});
	p.push_back({"sine_soaks", fromText("sine_soaks", "name: sine_soaks\ninitial_temp_C: 10\npower_initially: true\n"
													  "initial_state: steady\nsegments:\n"
													  "  - {type: hold, duration_min: 15}\n"
													  "  - {type: sine, amplitude_C: 15, period_min: 40, cycles: 4}\n"
													  "  - {type: ramp, to_C: -20, rate_C_per_min: 0.7}\n"
													  "  - {type: hold, duration_min: 30}\n"
													  "  - {type: ramp, to_C: 40, rate_C_per_min: 1.5}\n"
													  "  - {type: hold, duration_min: 20}\n"),
				 false});
	p.push_back({"cold_start", ChamberProfile::preset("warmup"), false});
	p.push_back({"out_of_range", fromText("out_of_range", "name: out_of_range\ninitial_temp_C: 25\npower_initially: true\n"
														  "initial_state: steady\nsegments:\n"
														  "  - {type: ramp, to_C: -55, rate_C_per_min: 1}\n"
														  "  - {type: hold, duration_min: 60}\n"
														  "  - {type: ramp, to_C: 75, rate_C_per_min: 1}\n"
														  "  - {type: hold, duration_min: 60}\n"),
				 true});
	return p;
}

std::vector<BenchProfile> secondCalibrationProfiles()
{
	std::vector<BenchProfile> p;
	p.push_back({"cal_sine", fromText("cal_sine", "name: cal_sine\ninitial_temp_C: 5\npower_initially: true\n"
												  "initial_state: steady\nsegments:\n"
												  "  - {type: hold, duration_min: 30}\n"
												  "  - {type: sine, amplitude_C: 20, period_min: 30, cycles: 3}\n"
												  "  - {type: ramp, to_C: -35, rate_C_per_min: 2}\n"
												  "  - {type: hold, duration_min: 45}\n"
												  "  - {type: ramp, to_C: 55, rate_C_per_min: 3}\n"
												  "  - {type: hold, duration_min: 45}\n"),
				 false});
	p.push_back({"cal_single", ChamberProfile::preset("calibration"), false});  // fog-sim's one-run calibration profile
	p.push_back({"cal_turn_on", fromText("cal_turn_on", "name: cal_turn_on\ninitial_temp_C: 10\npower_initially: true\n"
														"initial_state: cold\nsegments:\n"
														"  - {type: hold, duration_min: 180}\n"),
				 false});
	return p;
}

std::vector<BenchPreset> benchPresets()
{
	std::vector<BenchPreset> out;
	mrpt_fog::FitOptions none;
	none.selection = mrpt_fog::TermSelection::None;
	mrpt_fog::FitOptions def;
	def.stability_resamples = 0;  // reports only, never changes the chosen model: skipped for speed
	out.push_back({"default (multipoint)", "multipoint", def, false});
	mrpt_fog::FitOptions previous;  // the selection before blocked folds, whole groups, no parsimony
	previous.fold_scheme = mrpt_fog::FoldScheme::Blocks;
	previous.select_orders = false;
	previous.parsimony = false;
	previous.physics_candidates = false;
	previous.linear_base = false;
	out.push_back({"auto (blocked folds, no parsimony)", "multipoint", previous, false});
	if (std::getenv("FOG_BENCH_VARIANTS"))
	{
		for (int v = 0; v < 8; v++)
		{
			mrpt_fog::FitOptions o;
			o.stability_resamples = 0;
			o.fold_scheme = (v & 1) ? mrpt_fog::FoldScheme::Blocks : mrpt_fog::FoldScheme::Regimes;
			o.parsimony = (v & 2) == 0;
			o.linear_base = (v & 4) == 0;
			out.push_back({std::string("auto ") + ((v & 1) ? "blk" : "reg") + ((v & 2) ? " min" : " 1se") +
							   ((v & 4) ? " nobase" : " base"),
						   "multipoint", o, false});
		}
	}
	if (std::getenv("FOG_BENCH_PARSIMONY"))  // the parsimony rule and the order ceiling
	{
		mrpt_fog::FitOptions o;
		o.stability_resamples = 0;
		o.paired_se = true;
		out.push_back({"auto paired-se", "multipoint", o, false});
		o.paired_se = false;
		o.parsimony = false;
		out.push_back({"auto lowest-cv", "multipoint", o, false});
		o.parsimony = true;
		out.push_back({"auto@3/1", "multipoint@3/1", o, false});
	}
	if (std::getenv("FOG_BENCH_BINS"))  // selection scored on time-bin means
	{
		mrpt_fog::FitOptions o;
		o.stability_resamples = 0;
		for (const double b : {0.0, 1.0, 10.0, 100.0})
		{
			o.selection_bin_s = b;
			char label[40];
			std::snprintf(label, sizeof label, "auto bin %gs", b);
			out.push_back({label, "multipoint", o, false});
		}
		o.paired_se = true;
		out.push_back({"auto bin 100s paired", "multipoint", o, false});
	}
	if (std::getenv("FOG_BENCH_SCORING"))  // what the selection scores
	{
		mrpt_fog::FitOptions o;
		o.stability_resamples = 0;
		out.push_back({"auto @3/1", "multipoint@3/1", o, false});
		o.selection_bin_s = 100.0;
		out.push_back({"auto bin100", "multipoint", o, false});
		out.push_back({"auto bin100 @3/1", "multipoint@3/1", o, false});
		o.parsimony = false;
		out.push_back({"auto bin100 lowest-cv", "multipoint", o, false});
		o.parsimony = true;
		o.min_relative_gain = 0.0;
		out.push_back({"auto bin100 gain0", "multipoint", o, false});
		o.min_relative_gain = 0.005;
		o.step_rule = mrpt_fog::StepRule::Significant;
		o.paired_se = true;
		out.push_back({"auto sig bin100", "multipoint", o, false});
		o.selection_bin_s = 0.0;
		out.push_back({"auto sig", "multipoint", o, false});
	}
	if (std::getenv("FOG_BENCH_GAIN"))  // tau-binned scoring with a larger step threshold
	{
		mrpt_fog::FitOptions o;
		o.stability_resamples = 0;
		o.selection_bin_s = 100.0;
		for (const double g : {0.02, 0.05})
		{
			o.min_relative_gain = g;
			char label[40];
			std::snprintf(label, sizeof label, "auto bin100 g%g", g);
			out.push_back({label, "multipoint", o, false});
			std::snprintf(label, sizeof label, "auto bin100 @3/1 g%g", g);
			out.push_back({label, "multipoint@3/1", o, false});
		}
	}
	if (std::getenv("FOG_BENCH_COMMON"))  // common orders for all thermistors
	{
		mrpt_fog::FitOptions o;
		o.stability_resamples = 0;
		o.order_search = mrpt_fog::OrderSearch::Common;
		for (const double b : {0.0, 100.0})
		{
			o.selection_bin_s = b;
			const std::string bin = b > 0 ? " bin100" : "";
			o.parsimony = false;
			out.push_back({"auto common" + bin + " lowest", "multipoint", o, false});
			o.parsimony = true;
			out.push_back({"auto common" + bin + " 1se", "multipoint", o, false});
		}
	}
	// several calibration runs: regime folds within each run; =all: also with common orders
	if (std::getenv("FOG_BENCH_RUNFOLDS"))
	{
		mrpt_fog::FitOptions o;
		o.stability_resamples = 0;
		o.run_folds = mrpt_fog::RunFolds::RegimesWithinRuns;
		out.push_back({"auto run-regimes", "multipoint", o, false});
		if (std::string(std::getenv("FOG_BENCH_RUNFOLDS")) == "all")
		{
			o.order_search = mrpt_fog::OrderSearch::Common;
			o.selection_bin_s = 100.0;
			out.push_back({"auto run-regimes common bin100", "multipoint", o, false});
			mrpt_fog::FitOptions c;
			c.stability_resamples = 0;
			c.order_search = mrpt_fog::OrderSearch::Common;
			c.selection_bin_s = 100.0;
			out.push_back({"auto runs common bin100", "multipoint", c, false});
		}
	}
	if (const char* lag_env = std::getenv("FOG_BENCH_LAGS"))  // lag-rate variants (LagFilter.h; the default has them)
	{
		// FOG_BENCH_LAGS=1: the physics grid (kPhysicsLagTaus_s); or a list of time constants, e.g. 100,400
		std::vector<double> taus = mrpt_fog::kPhysicsLagTaus_s;
		if (std::string(lag_env) != "1")
		{
			taus.clear();
			for (const char* p = lag_env; *p;)
			{
				char* end = nullptr;
				const double t = std::strtod(p, &end);
				if (end == p) break;
				taus.push_back(t);
				p = *end == ',' ? end + 1 : end;
			}
		}
		mrpt_fog::FitOptions o;
		o.stability_resamples = 0;
		o.lag_taus_s.clear();
		out.push_back({"auto no lags", "multipoint", o, false});  // the default before the lags
		o.lag_taus_s = taus;
		o.lag_in_base = false;
		out.push_back({"auto lag steps", "multipoint", o, false});  // added by steps, not in the base
		o.lag_in_base = true;
		out.push_back({"auto lag base", "multipoint", o, false});  // = the default with FOG_BENCH_LAGS=1
		o.lag_in_base = false;
		o.lag_max_thermistors = 8;
		out.push_back({"auto lag all", "multipoint", o, false});  // by steps, any thermistor count
	}
	out.push_back({"multipoint none 5/3", "multipoint", none, true});
	out.push_back({"multipoint@3/1 none", "multipoint@3/1", none, true});
	out.push_back({"multipoint@1/1 none", "multipoint@1/1", none, true});
	out.push_back({"M2@3/1 none", "M2@3/1", none, true});
	out.push_back({"M1@3/0 none", "M1@3/0", none, true});
	return out;
}

const char* toString(Generator g) { return g == Generator::FogSim ? "fog-sim" : "sector-coil"; }

namespace
{
bool isEvaluationProfile(const std::vector<BenchProfile>& profiles, const std::string& name)
{
	for (const auto& p : profiles)
		if (p.name == name) return true;
	return false;
}

struct DeviceRuns
{
	double rate_hz = 0;
	int thermistors = 0;
	mrpt_fog::FogSeries cal;
	std::vector<mrpt_fog::FogSeries> eval, floor;
	std::vector<mrpt_fog::FogSeries> cal2, turn_on;  //!< empty or one run each (BenchCase)
};

mrpt_fog::sim::ChamberProfile secondCalibrationProfile(const std::string& name)
{
	for (const auto& p : secondCalibrationProfiles())
		if (p.name == name) return p.profile;
	throw std::invalid_argument("bench: no second calibration profile '" + name + "'");
}

DeviceRuns simulate(const BenchCase& c, const std::vector<BenchProfile>& profiles)
{
	DeviceRuns r;
	if (c.generator == Generator::FogSim)
	{
		DrawnDevice d = drawDevice(c.seed);
		if (c.ideal_thermistors)
		{
			d.device.thermistor_noise_C = 0;
			d.device.thermistor_quantum_C = 0;
		}
		mrpt_fog::sim::SimSettings st;
		st.effects = c.effects;
		st.rate_hz = std::min(d.rate_hz, c.rate_cap_hz);
		r.rate_hz = st.rate_hz;
		r.thermistors = static_cast<int>(d.device.thermistors.size());
		st.seed = 1000 * c.seed + 1;
		r.cal = mrpt_fog::sim::simulateChamber(
			c.calibration_profile.empty() ? calibrationProfile() : secondCalibrationProfile(c.calibration_profile), d.device, st);
		if (!c.second_calibration.empty() && !isEvaluationProfile(profiles, c.second_calibration))
		{
			st.seed = 1000 * c.seed + 50;
			r.cal2.push_back(mrpt_fog::sim::simulateChamber(secondCalibrationProfile(c.second_calibration), d.device, st));
		}
		if (c.warmup_calibration)
		{
			st.seed = 1000 * c.seed + 51;
			r.turn_on.push_back(mrpt_fog::sim::simulateChamber(secondCalibrationProfile("cal_turn_on"), d.device, st));
		}
		for (std::size_t i = 0; i < profiles.size(); i++)
		{
			st.seed = 1000 * c.seed + 2 + i;
			st.effects = c.effects;
			r.eval.push_back(mrpt_fog::sim::simulateChamber(profiles[i].profile, d.device, st));
			st.effects = {};  // noise only: the device's noise floor on this profile
			r.floor.push_back(mrpt_fog::sim::simulateChamber(profiles[i].profile, d.device, st));
		}
	}
	else
	{
		SectorCoilParams p = drawSectorCoil(c.seed);
		p.rate_hz = std::min(p.rate_hz, c.rate_cap_hz);
		r.rate_hz = p.rate_hz;
		r.thermistors = p.thermistors;
		r.cal = simulateSectorCoil(
			p, c.calibration_profile.empty() ? calibrationProfile() : secondCalibrationProfile(c.calibration_profile),
			1000 * c.seed + 1);
		if (!c.second_calibration.empty() && !isEvaluationProfile(profiles, c.second_calibration))
			r.cal2.push_back(simulateSectorCoil(p, secondCalibrationProfile(c.second_calibration), 1000 * c.seed + 50));
		for (std::size_t i = 0; i < profiles.size(); i++)
		{
			r.eval.push_back(simulateSectorCoil(p, profiles[i].profile, 1000 * c.seed + 2 + i));
			r.floor.push_back(simulateSectorCoil(p, profiles[i].profile, 1000 * c.seed + 2 + i, true));
		}
	}
	return r;
}

/** Diagnostic evaluation of a calibration whose rate estimator cannot run in real time (savgol):
 * the model evaluated on the run's signals with that estimator, the 100 s stability of the
 * compensated output (powered samples). */
double offlineStability_dph(const mrpt_fog::Calibration& cal, const mrpt_fog::FogSeries& s)
{
	const auto& fs = cal.model.features;
	const auto est = mrpt_fog::makeRateEstimator(cal.rate_estimator);
	std::vector<std::vector<double>> temp, rate;
	for (const auto& name : fs.thermistors())
	{
		temp.push_back(s.temp_C[static_cast<std::size_t>(s.thermistorIndex(name))]);
		rate.push_back(est->estimate(s.time_s, temp.back()));
	}
	const auto& raw = s.primaryRate_dph();
	std::vector<double> T(temp.size()), R(temp.size()), v(fs.signals().size()), t, comp;
	mrpt_fog::LagFilterBank lags(fs.lags());
	std::vector<double> L(fs.lags().size());
	for (std::size_t k = 0; k < s.size(); k++)
	{
		for (std::size_t i = 0; i < T.size(); i++) T[i] = temp[i][k];
		lags.push(s.time_s[k], T.data());  // every sample, as the compensator
		for (std::size_t i = 0; i < L.size(); i++) L[i] = lags.rate_C_per_s(i);
		if (!s.power.empty() && s.power[k] == 0.0) continue;
		bool ok = true;
		for (std::size_t i = 0; i < T.size(); i++)
		{
			T[i] = temp[i][k];
			R[i] = rate[i][k];
			ok = ok && std::isfinite(T[i]) && std::isfinite(R[i]);
		}
		if (!ok) continue;
		fs.signalValues(T.data(), R.data(), L.data(), v.data());
		t.push_back(s.time_s[k]);
		comp.push_back(raw[k] - cal.model.evaluate(v.data(), cal.extrapolation));
	}
	return mrpt_fog::biasStats(t, comp, 100.0).stability_dph;
}

/** Diagnostic (FOG_BENCH_TRACE=DIR): 100 s bin means of time, raw rate, the calibration's bias
 * estimate and every thermistor of one evaluation, to DIR/seed<N>_<profile>_<preset>.csv. */
void traceEvaluation(const char* dir, std::uint64_t seed, const std::string& profile, const std::string& preset,
					 const mrpt_fog::Calibration& cal, const mrpt_fog::FogSeries& s)
{
	std::string name = preset;
	for (char& ch : name)
		if (!std::isalnum(static_cast<unsigned char>(ch))) ch = '_';
	const std::string path = std::string(dir) + "/seed" + std::to_string(seed) + "_" + profile + "_" + name + ".csv";
	FILE* out = std::fopen(path.c_str(), "w");
	if (!out) return;
	const auto bias = mrpt_fog::compensatedBias_dph(cal, s);
	const auto& raw = s.primaryRate_dph();
	std::fprintf(out, "t_s,raw_dph,bias_dph");
	for (const auto& th : s.thermistors) std::fprintf(out, ",%s", th.name.c_str());
	std::fprintf(out, "\n");
	const std::size_t nt = s.temp_C.size();
	std::vector<double> sum(3 + nt, 0.0);
	std::size_t n = 0;
	double t0 = s.time_s.empty() ? 0 : s.time_s[0];
	for (std::size_t k = 0; k < s.size(); k++)
	{
		if (s.time_s[k] - t0 >= 100.0 && n > 0)
		{
			for (std::size_t q = 0; q < sum.size(); q++) std::fprintf(out, q ? ",%.6g" : "%.6g", sum[q] / static_cast<double>(n));
			std::fprintf(out, "\n");
			std::fill(sum.begin(), sum.end(), 0.0);
			n = 0;
			t0 = s.time_s[k];
		}
		sum[0] += s.time_s[k];
		sum[1] += raw[k];
		sum[2] += bias[k];
		for (std::size_t i = 0; i < nt; i++) sum[3 + i] += s.temp_C[i][k];
		n++;
	}
	std::fclose(out);
}

std::string describeTerms(const mrpt_fog::Calibration& cal)
{
	const auto names = cal.model.features.termNames();
	char w[64];
	std::snprintf(w, sizeof w, "window %g s, ridge %g, ", cal.rate_estimator.window_s, cal.model.ridge);
	std::string s = w + std::to_string(names.size()) + " terms:";
	for (std::size_t i = 1; i < names.size(); i++) s += " " + names[i];
	return s;
}
}  // namespace

std::vector<CaseResult> runBenchCase(const BenchCase& c, const std::vector<BenchPreset>& presets,
									 const std::vector<BenchProfile>& profiles)
{
	const DeviceRuns runs = simulate(c, profiles);
	std::vector<double> floor_dph;
	for (const auto& f : runs.floor)
	{
		const auto stats = mrpt_fog::biasStats(f.time_s, f.primaryRate_dph(), 100.0);
		floor_dph.push_back(stats.stability_dph);
	}
	std::vector<CaseResult> out;
	// A second calibration run: a profile of secondCalibrationProfiles() (runs.cal2), or an
	// evaluation profile's run (index cal2; that profile is then not evaluated).
	const std::string& second = c.second_calibration;
	std::size_t cal2 = profiles.size();
	for (std::size_t i = 0; i < profiles.size(); i++)
		if (profiles[i].name == second) cal2 = i;
	for (const auto& preset : presets)
	{
		fogtest::BenchPreset bp = preset;
		// a calibration run of another profile may hold a turn-on: its transient is the warm-up term's
		const bool single_run = !c.calibration_profile.empty();
		if (single_run && !bp.fit_on_evaluation) bp.options.turn_on_exclusion_s = c.turn_on_exclusion_s;
		mrpt_fog::Calibration cal;
		std::string error, note;
		const auto fit = [&](const mrpt_fog::FogSeries& run) {
			error.clear();
			note.clear();
			try
			{
				if (bp.fit_on_evaluation || bp.seed_run_only)
					cal = mrpt_fog::fitCalibration({run}, bp.preset, bp.options, {"calibration"});
				else if (cal2 < profiles.size())
					cal = mrpt_fog::fitCalibration({run, runs.eval[cal2]}, bp.preset, bp.options, {"calibration", "second"});
				else if (!runs.cal2.empty())
					cal = mrpt_fog::fitCalibration({run, runs.cal2[0]}, bp.preset, bp.options, {"calibration", second});
				else
					cal = mrpt_fog::fitCalibration({run}, bp.preset, bp.options, {"calibration"});
				if (single_run && c.turn_on_exclusion_s > 0 && !bp.fit_on_evaluation && !bp.no_warmup &&
					(!runs.cal.turnOnSamples().empty() || !runs.cal.metadataValue("power_on_time_s").empty()))
				{
					try
					{
						cal.warmup = mrpt_fog::fitWarmup({runs.cal}, cal, {}, nullptr, {"calibration"});
					}
					catch (const mrpt_fog::WarmupFitError& e)
					{
						note = std::string(" (no warm-up term: ") + e.what() + ")";
					}
				}
				else if (!runs.turn_on.empty() && !bp.fit_on_evaluation && !bp.seed_run_only && !bp.no_warmup)
				{
					try
					{
						cal.warmup = mrpt_fog::fitWarmup(runs.turn_on, cal, {}, nullptr, {"cal_turn_on"});
					}
					catch (const mrpt_fog::WarmupFitError& e)
					{
						note = std::string(" (no warm-up term: ") + e.what() + ")";
					}
				}
			}
			catch (const std::exception& e)
			{
				error = e.what();
			}
		};
		if (!bp.fit_on_evaluation) fit(runs.cal);
		for (std::size_t i = 0; i < profiles.size(); i++)
		{
			if (i == cal2 && !bp.fit_on_evaluation) continue;  // it was calibrated on
			if (bp.fit_on_evaluation) fit(runs.eval[i]);
			CaseResult r;
			r.generator = c.generator;
			r.seed = c.seed;
			r.rate_hz = runs.rate_hz;
			r.thermistors = runs.thermistors;
			r.profile = profiles[i].name;
			r.preset = bp.label;
			r.out_of_range = profiles[i].out_of_range;
			r.noise_floor_dph = floor_dph[i];
			r.error = error;
			if (error.empty())
			{
				mrpt_fog::FitFigures f;
				if (cal.rate_estimator.kind != mrpt_fog::RateEstimatorKind::Causal)
				{
					f.stability_dph = offlineStability_dph(cal, runs.eval[i]);
					f.raw_stability_dph = mrpt_fog::biasStats(runs.eval[i].time_s, runs.eval[i].primaryRate_dph(), 100.0).stability_dph;
					f.valid = true;
				}
				else
					f = mrpt_fog::evaluateCalibration(cal, runs.eval[i], profiles[i].name, 100.0);
				r.ok = f.valid;
				r.stability_dph = f.stability_dph;
				r.raw_stability_dph = f.raw_stability_dph;
				r.ratio = f.stability_dph / floor_dph[i];
				r.raw_over_comp = f.raw_stability_dph / f.stability_dph;
				r.model_terms = describeTerms(cal) + note;
				if (const char* dir = std::getenv("FOG_BENCH_TRACE"))
					traceEvaluation(dir, c.seed, profiles[i].name, bp.label, cal, runs.eval[i]);
				if (!f.valid) r.error = "evaluation run shorter than 2 windows";
			}
			out.push_back(r);
		}
	}
	return out;
}

double quantile(std::vector<double> v, double q)
{
	if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
	std::sort(v.begin(), v.end());
	const double pos = q * static_cast<double>(v.size() - 1);
	const auto lo = static_cast<std::size_t>(std::floor(pos));
	const std::size_t hi = std::min(lo + 1, v.size() - 1);
	if (!std::isfinite(v[hi])) return v[hi];
	return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

std::vector<PresetSummary> summarise(const std::vector<CaseResult>& results, const std::vector<BenchPreset>& presets)
{
	std::vector<PresetSummary> out;
	const double inf = std::numeric_limits<double>::infinity();
	for (const auto& bp : presets)
	{
		PresetSummary s;
		s.preset = bp.label;
		std::vector<double> in_range, oor_gain, oor_ratio;
		for (const auto& r : results)
		{
			if (r.preset != bp.label) continue;
			if (r.out_of_range)
			{
				oor_gain.push_back(r.ok ? r.raw_over_comp : 0.0);
				oor_ratio.push_back(r.ok ? r.ratio : inf);
				continue;
			}
			s.cases++;
			s.failures += !r.ok;
			in_range.push_back(r.ok ? r.ratio : inf);
		}
		s.median_ratio = quantile(in_range, 0.5);
		s.p90_ratio = quantile(in_range, 0.9);
		s.oor_median_raw_over_comp = quantile(oor_gain, 0.5);
		s.oor_median_ratio = quantile(oor_ratio, 0.5);
		out.push_back(s);
	}
	return out;
}

}  // namespace fogtest
