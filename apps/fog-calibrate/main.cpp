/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* fog-calibrate: fits the thermal-bias model of a FOG to one or more chamber runs and writes a
 * calibration YAML (model, fallbacks, ranges, statistics). Thin main over model/Calibration.h. */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/discrepancy/MagneticFit.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/AxisRuns.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/ScaleFactorFit.h>
#include <mrpt_fog/model/WarmupFit.h>

#include <cmath>
#include <algorithm>
#include <cstdio>
#include <iostream>

#include "AppMain.h"
#include "LogInput.h"
#include "CommandLine.h"
#include "Options.h"
#include "PowerCycles.h"
#include "Progress.h"
#include "RangeWarning.h"
#include "ThermistorScreeningReport.h"

using namespace mrpt_fog;

namespace
{
const char* const kHelp = R"(
WHAT IT DOES
  Fits bias_dph = f(thermistor temperatures, their rates) to static chamber runs (the gyro
  output IS the bias; an applied table rate column is subtracted) and writes a calibration
  YAML for fog-compensate / fog-evaluate / fog-drift. Every figure is printed twice, side by
  side: IN-SAMPLE (the data the model was fitted on: optimistic) and HELD-OUT (data the model
  did not see: what to expect in use). Held-out = leave-one-run-out with several -i runs,
  leave-regime-out with one run, plus the --validate run if given.

MODEL PRESETS (--model)
  multipoint            seed eq. 2: per thermistor T^1..T^5 and dT/dt^1..^3 (all thermistors)
  multipoint:Ti1,To1    the same on chosen thermistors
  M1[:A]  M2[:A]        seed eqs. 3/4: poly5(T) [+ poly3(dT/dt)] of one thermistor
  M3[:IN,OUT]           seed eq. 5: M2(IN) + poly3(IN - OUT)
  M4[:IN,OUT]           seed eq. 6: poly3(IN - OUT) + poly3(d/dt (IN - OUT))
  points:K              multipoint on the best K-thermistor subset (by held-out error)
  terms:T(Ti1)^1;dT/dt(Ti1)^1;dT(Ti1-To1)^1   an explicit term list; also dTlag/dt(a,tau_s)^k and
                        hyst(a,play,wC)^1 / hyst(a,branch,wC)^1 (hysteresis, docs/model.md)
  Append @T/R to change the orders, e.g. multipoint@3/1, or @T for the temperature order only
  (M1:imu@3); the orders of auto are upper limits.

OUTSIDE THE CALIBRATED RANGE (--extrapolation)
  linear (default): each signal's polynomial is continued along its tangent at the range edge
    (on held-out simulated devices 1.2-1.5x better than clamp, see docs/model.md);
  clamp: the signal is held at the edge (the bias stops changing: compensated = raw beyond);
  polynomial: the raw polynomial (studies only).
  With --validate, a warning gives the share of samples outside the range and how far out.

HOW THE FIT GUARDS AGAINST OVER-FITTING (--selection)
  auto (default): features normalised to [-1, 1]; the search starts from the linear
    multipoint model (T^1 and dT/dt^1 of every thermistor of the preset: the Shupe error is
    linear in the coil's temperature rates) and raises a signal's order (T up to 5, rates up
    to 3, never above the preset's) or adds a physics-shaped candidate (inner-outer
    difference dT(in-out)^1 and its rate, pairs at the same angle) only when that lowers the
    cross-validated error; a ridge value is picked the same way. Parsimony: the simplest model
    within one standard error of the best is kept. Folds (--folds-by): whole thermal regimes of
    the run (cooling ramps, soaks, heating ramps) are held out, so the error is that of a
    temperature history the fit did not see; blocks = interleaved time blocks. points:K also
    searches thermistor subsets.
  Options measured on the generalization bench, not the default (docs/generalization.md,
  "Scoring what the product is judged on"): --order-search common (one temperature order and
  one rate order for all thermistors, 15 candidates), --selection-bin S (candidates scored on
  S-second bin means, e.g. the --tau of the stability figure, so the white noise of high sample
  rates does not decide), --step-rule significant (a step must beat two standard errors of the
  paired per-block held-out difference instead of lowering the held-out RMS by 0.5 %).
  One thermistor (most commercial FOGs expose one; --lags, default physics): the linear base
  also holds dTlag/dt(a,tau)^1 for tau = 100, 400, 1600 s, the rate of the reading through a
  first-order lag (the winding's radial diffusion to the housing's time constant): what the
  coil's interior sees of a boundary sensor, whose rates the Shupe error follows. The lag is
  carried sample to sample (warm start: the first reading); such a calibration is written as
  file version 3. --lags none: without them; --lags S,S,..: other time constants [s]. With two
  or more thermistors nothing changes (the sensors see the radial spread themselves).
  Several -i runs: by default each run is one fold (leave-one-run-out: a model fitted on the
  other runs alone must predict it); --run-folds regimes cuts each run into its thermal regimes
  and fits every fold on all the rest, the other runs included (docs/generalization.md,
  "Calibration on more than one run"). A second run with another temperature history (a sine,
  other ramp rates) is what pins the rate (Shupe) coefficients that one 1 C/min profile leaves
  open.
  none: every preset term, plain least squares (plus --ridge): the seed's method; with several
    collinear thermistors it fits the calibration run and fails on others.
  The fit refuses (with the reason) too few samples, a temperature span too narrow for the
  polynomial order, and a rank-deficient system with plain least squares.

NO SILENT EMPTY MODEL (--allow-empty-model)
  A fit that keeps no thermal term (a constant bias only: the bias does not follow the
  thermistors, the noise hides it, table rates dominate) is an error saying why, and nothing
  is written; --allow-empty-model writes it with a warning. A model whose thermal terms lower
  the held-out stability by less than 1 % (it compensates nothing) is written with a warning.

THERMISTOR SCREENING (--no-screening)
  Before fitting, every run's thermistor readings are screened as fog-compensate screens them
  (stuck, spike, out of range -> a dropout); rejected readings are counted in the summary.

RATES
  dT/dt from the causal estimator over the trailing --window seconds (default 60; order 2
  extrapolates the slope to the newest sample), the same estimator fog-compensate runs in real
  time. Without --window the window grows with the thermistors' reading quantum (the smallest
  change between consecutive readings): 60 s x q / 0.02 degC, at least 60 s, at most 1200 s
  (1/16 degC: 188 s), since a quantised reading's slope errs by about q / window (a longer
  window would delay the rates more than it saves: docs/generalization.md). The
  calibration records the window; fog-compensate uses it. Until a rate window covers half its
  length (start of a log, each burst of a burst log, after a gap) the compensator uses the
  calibration's rate-free start-up model (flag rate_free). --estimator savgol uses a
  centred Savitzky-Golay window instead (studies only: such a calibration cannot compensate in
  real time).

SCALE FACTOR VS TEMPERATURE (--scale-factor auto|off)
  A run with a table_rate_dph column turning at non-zero rates (a rate-table run: IEEE Std 952,
  both signs, several rates, at soaked temperatures) holds the scale factor. With auto (the
  default) its table segments are left out of the bias fit and fit s(T) [ppm] instead: per
  segment s = (mean(raw - bias - applied) / applied), then a polynomial in one thermistor
  temperature, thermistor and order (0..3) chosen by leave-one-temperature-out error; the
  compensator then applies omega = (raw - bias) / (1 + 1e-6 s). If the runs cannot support that
  fit (one rate sign only, one temperature, segments too short) fog-calibrate stops with the
  reason rather than return a bias-only model. --scale-factor off: table samples are treated
  as bias samples with the nominal scale factor (the behaviour before version 2 files).

  The reported 95 % interval of the mean slope also covers the thermistors' disagreement on
  the coil temperature (the fit repeated against each thermistor; docs/model.md).
  With table segments where the thermistors disagree (turn-ons, ramps: the bundled
  datasets/ratetable_transient.rawlog) a further candidate reads a weighted sum of all
  thermistors (the coil's mean temperature, which no single one reads in a transient; weights
  fitted, printed, and stored in the file); chosen only when its held-out error is lower.

WARM-UP (--warmup-run RUN, repeatable; --warmup-terms 1|2|auto)
  Runs that hold a turn-on (a 0 -> 1 power step, or metadata power_on_time_s at or before the
  first sample: a gyro switched on cold, e.g. datasets/warmup.rawlog) fit the turn-on term
  bias += A exp(-(t - t_on) / tau) [+ A2 exp(-(t - t_on) / tau2)] on the residual of the
  calibration fitted on the -i runs; they do not join the bias fit (their transient would be
  taken for a thermal effect). What the term holds is everything a turn-on adds that the bias
  model fitted on powered runs does not predict: the source's own settling, and the thermal
  model's error at a turn-on (an unpowered coil has inner/outer differences no powered run has).
  --warmup-terms auto (default): with two or more warm-up runs, one or two exponentials by
  held-out error (each run left out in turn, its binned residual scored); with one run, one.
  Also fitted: the start-up offset, the rate-free start-up model's own error in the first rate
  window after a turn-on (the compensator adds it there). Printed with standard errors and the
  residual RMS without / with the term. The compensator adds the term from each turn-on on
  (metadata power_on_time_s, 0 -> 1 steps). A run with no turn-on, a span under 600 s, or no
  decay resolved stops fog-calibrate with the reason.
  A turn-on inside an -i run (one chamber run that starts cold, e.g. fog-sim --profile
  calibration): with --turn-on-exclusion S (3600 suggested: six time constants of a 10 min
  warm-up, an estimate) the first S seconds after each turn-on stay out of the bias fit, and,
  when no --warmup-run is given, the run fits the warm-up term; a line names each such run. If
  no decay is resolved there, the reason is printed and the file is written without the term.
  Without it (0, the default) the whole run joins the bias fit, no term is fitted on it, and a
  note names the run: the transient is then taken for a thermal effect. One `calibration` run
  of the bundled device validated on datasets/chamber_B.rawlog: 11.0x with 3600 against 7.8x
  without (docs/generalization.md, "One calibration run"). The default stays 0 because runs
  with power cycles (the bundled rate-table transient run, the model-gap trials' runs) have
  documented figures fitted that way.

MAGNETIC SENSITIVITY (--magnetic auto|off)
  With auto (the default), when an -i run has a field_uT column whose value changes over its
  powered samples (field segments: an axial field switched on and off), the bias per applied
  field is fitted on the residual of the calibration (bias and scale factor) over the powered
  samples without table rate: generalised least squares on the field and a slow drift per run
  (knots every shortest constant-field stretch), standard error from the whitened fit
  (discrepancy/MagneticFit.h). It is written as the axis' magnetic section (file version 3);
  the compensator adds dph_per_uT x field_uT, the field read from the log (fog-compensate).
  Printed with its standard error; when the runs cannot support it, the reason is printed and
  no section is written. off: never fitted. The bias fit itself does not see the field.

THREE AXES (--axis x|y|z|all)
  A log with several gyro axes (rate_x/y/z_dph) is calibrated per axis, every axis the -i
  runs share unless --axis names one; the file holds one model per axis. A rate-table run
  serves only the axis its table turns about (metadata table_axis, default its first axis):
  the others see a turning Earth-rate projection there and leave it out (printed). A run
  whose metadata states the Earth rate an axis saw (earth_rate_dph.<axis>, fog-sim --triad
  writes it from the mount) has it removed from that axis' output, so that bias holds no Earth
  rate (earth_rate handling in_table_rate); state it for all runs of an axis or none.

EXAMPLES
  fog-calibrate -i datasets/chamber_A.rawlog --model multipoint -o cal.yaml --validate datasets/chamber_B.rawlog
  fog-calibrate -i datasets/chamber_A.rawlog -i datasets/ratetable_A.rawlog -o cal_sf.yaml
  fog-calibrate -i datasets/chamber_A.rawlog -i datasets/ratetable_A.rawlog -i datasets/ratetable_transient.rawlog \
                -i datasets/warmup.rawlog -o cal_full.yaml        (warm-up run in the bias fit: the recommendation before)
  fog-sim --profile calibration --seed 7 -o cal_run.rawlog && fog-calibrate -i cal_run.rawlog --turn-on-exclusion 3600 -o cal1.yaml
                (one chamber run calibrates bias, rate terms and warm-up: docs/generalization.md, "One calibration run")
  fog-calibrate -i datasets/chamber_A.rawlog -i datasets/ratetable_A.rawlog -i datasets/ratetable_transient.rawlog \
                --warmup-run datasets/warmup.rawlog --warmup-run datasets/warmup_B.rawlog --selection none \
                --model "terms:T(Ti1)^1;dT/dt(Ti1)^1;T(To1)^1;dT/dt(To1)^1;T(Ti2)^1;dT/dt(Ti2)^1;T(To2)^1;dT/dt(To2)^1;T(To1)^2" \
                -o cal_wu.yaml    (the recommended calibration: docs/nav.md, "Error budget")
  fog-calibrate -i chamber3.rawlog -i rt_x.rawlog -i rt_y.rawlog -i rt_z.rawlog -o cal3.yaml   (triad, fog-sim --triad)
  fog-calibrate -i runA.csv -i runB.csv --model points:2 -o cal2.yaml --json fit.json
  fog-calibrate -i runA.csv --model M3:Ti1,To1 --selection none -o m3.yaml
)";

std::string fmt(double v, const char* f = "%.6g") { return formatValue(f, v); }

void printFigures(const std::vector<const FitFigures*>& figs)
{
	std::printf("  %-28s", "figure [deg/h]");
	for (const auto* f : figs) std::printf(" %-34s", f->label.c_str());
	std::printf("\n");
	const auto row = [&](const char* name, double FitFigures::*m) {
		std::printf("  %-28s", name);
		for (const auto* f : figs) std::printf(" %-34s", fmt(f->*m).c_str());
		std::printf("\n");
	};
	row("raw stability (tau avg)", &FitFigures::raw_stability_dph);
	row("compensated stability", &FitFigures::stability_dph);
	row("raw range (tau avg)", &FitFigures::raw_range_dph);
	row("compensated range", &FitFigures::range_dph);
	row("compensated RMS", &FitFigures::rms_dph);
}

JsonValue figuresJson(const FitFigures& f)
{
	JsonValue j = JsonValue::object();
	j["label"] = f.label;
	j["valid"] = f.valid;
	j["samples"] = static_cast<unsigned long>(f.samples);
	j["tau_s"] = f.tau_s;
	j["raw"]["stability_dph"] = f.raw_stability_dph;
	j["raw"]["range_dph"] = f.raw_range_dph;
	j["compensated"]["stability_dph"] = f.stability_dph;
	j["compensated"]["range_dph"] = f.range_dph;
	j["compensated"]["rms_dph"] = f.rms_dph;
	return j;
}

/** Why a fit selected no thermal term, from the runs themselves (issue 14: such a calibration
 * used to be written silently as "1 terms (0 thermistors)"). */
std::string whyNoThermalTerm(const std::vector<FogRun>& runs, const BiasModel& m)
{
	std::size_t samples = 0;
	double span_C = 0.0;
	std::string span_name;
	double table_range = 0.0, residual_range = 0.0;
	for (const auto& r : runs)
	{
		samples += r.size();
		const std::size_t nt = r.header().thermistorCount();
		std::vector<double> lo(nt, INFINITY), hi(nt, -INFINITY);
		double tlo = INFINITY, thi = -INFINITY, rlo = INFINITY, rhi = -INFINITY;
		r.forEachChunk([&](const FogSeries& c, std::size_t) {
			for (std::size_t i = 0; i < nt; i++)
				for (double t : c.temp_C[i])
					if (std::isfinite(t)) lo[i] = std::min(lo[i], t), hi[i] = std::max(hi[i], t);
			if (c.table_rate_dph.empty()) return;
			const auto& rate = c.primaryRate_dph();
			for (std::size_t k = 0; k < c.size(); k++)
			{
				if (!std::isfinite(c.table_rate_dph[k]) || !std::isfinite(rate[k])) continue;
				tlo = std::min(tlo, c.table_rate_dph[k]), thi = std::max(thi, c.table_rate_dph[k]);
				const double res = rate[k] - c.table_rate_dph[k];
				rlo = std::min(rlo, res), rhi = std::max(rhi, res);
			}
		});
		for (std::size_t i = 0; i < nt; i++)
			if (hi[i] - lo[i] > span_C) span_C = hi[i] - lo[i], span_name = r.header().thermistors[i].name;
		if (thi >= tlo) table_range = std::max(table_range, thi - tlo), residual_range = std::max(residual_range, rhi - rlo);
	}
	char b[400];
	if (samples < 100 || m.samples < 100)
		std::snprintf(b, sizeof(b), "too few samples (%zu): a thermal term needs hundreds over the temperature range", samples);
	else if (span_C < 2.0)
		std::snprintf(b, sizeof(b),
					  "no temperature span: the thermistors vary by at most %.3g C (%s); a thermal model needs runs over "
					  "several degrees",
					  span_C, span_name.empty() ? "no valid reading" : span_name.c_str());
	else if (table_range > 0 && table_range > 100.0 * residual_range)
		std::snprintf(b, sizeof(b),
					  "the applied table rates dominate the output (table range %.4g deg/h, gyro minus table %.4g deg/h): "
					  "an error proportional to the rate (scale factor) hides the thermal bias",
					  table_range, residual_range);
	else
		std::snprintf(b, sizeof(b),
					  "no thermal term lowered the held-out error (thermistors span %.3g C): the bias does not follow these "
					  "thermistors, or the noise hides it",
					  span_C);
	return b;
}

/** One axis' calibration and what its summary needs. */
struct AxisFit
{
	Calibration cal;
	ScaleFactorFitReport sf_report;
	std::size_t run_count = 0;
	bool table_rates = false;
	std::string why_empty;  //!< why no thermal term was kept (empty model only)
	std::vector<std::string> skipped;  //!< -i runs left out for this axis, with the reason
	bool earth_rate_removed = false;
	bool validated = false;
	std::string warmup_terms_why;  //!< how the warm-up term count was chosen
	std::string warmup_why_not;  //!< why the turn-ons of the -i runs gave no warm-up term ("" otherwise)
	std::string magnetic_why_not;  //!< why the runs' field segments gave no magnetic section ("" otherwise)
};

CompensationCounters validationRange(const Calibration& cal)
{
	CompensationCounters range;  // of the validation run, through the compensator
	range.samples = cal.validation.samples;
	range.temp_outside_samples = cal.validation.temp_outside_samples;
	range.rate_outside_samples = cal.validation.rate_outside_samples;
	range.max_temp_excursion_C = cal.validation.max_temp_excursion_C;
	range.max_rate_excursion_C_per_s = cal.validation.max_rate_excursion_C_per_s;
	return range;
}

void printAxis(const AxisFit& f, double tau_s, bool validated)
{
	const Calibration& cal = f.cal;
	for (const auto& sk : f.skipped) std::printf("  left out: %s\n", sk.c_str());
	const auto& m = cal.model;
	std::printf("fog-calibrate: %zu run(s), preset %s, selection %s, rates %s\n", f.run_count, cal.preset.c_str(),
				toString(cal.selection), cal.rate_estimator.describe().c_str());
	std::printf("  model: %zu terms (%zu thermistors), ridge %g, condition number %.3g, rank %zu, %zu samples\n",
				m.features.termCount(), m.features.thermistors().size(), m.ridge, m.condition_number,
				m.numerical_rank, m.samples);
	std::printf("  terms:");
	for (std::size_t i = 1; i < m.features.termCount(); i++) std::printf(" %s", m.features.termNames()[i].c_str());
	std::printf("\n  fallbacks: %zu (one per thermistor of the model)\n", cal.fallbacks.size());
	const auto& st = cal.selection_stability;
	if (st.resamples > 0)
	{
		std::printf("  selection stability: %.0f %% of %zu wild-bootstrap refits (new noise, same thermal history) "
					"chose this model (held-out RMS %.4g deg/h)%s\n",
					100.0 * st.chosen_share, st.resamples, st.chosen_held_out_rms_dph,
					st.stable ? " (stable)"
					: st.alternatives_equivalent
						? ": UNSTABLE (< 90 %) among equivalent models: every alternative's held-out error is within "
						  "one standard error of this one's (the data cannot tell them apart); alternatives:"
						: ": UNSTABLE (< 90 %), the data do not settle the choice and the alternatives predict "
						  "differently; alternatives:");
		if (!st.stable)
			for (const auto& a : st.alternatives)
				std::printf("    %.0f %%  held-out RMS %.4g deg/h  %s\n", 100.0 * a.share, a.held_out_rms_dph,
							a.terms.c_str());
	}
	if (cal.reading_quantum_C > kQuantumWindowStart_C * (1 + 1e-6) && cal.rate_estimator.window_s > 60.0)
		std::printf("  rate window %g s for the thermistors' reading quantum %g degC (60 s x q / 0.02 degC; "
					"--window sets it)\n",
					cal.rate_estimator.window_s, cal.reading_quantum_C);
	if (cal.rates_unavailable)
		std::printf("  note: %zu gap(s) longer than the %g s rate window and the stretches between them shorter than "
					"half of it (a burst log): temperature rates cannot be estimated from this log, so the model has "
					"no dT/dt terms (rate-free); the compensator then runs it on every sample without a flag\n",
					cal.rate_gaps, cal.rate_estimator.window_s);
	else if (cal.rate_gaps)
		std::printf("  note: %zu gap(s) longer than the %g s rate window (a burst log?): temperature rates cannot "
					"be estimated across a gap, so the samples before each restart has a rate are left out of the fit\n",
					cal.rate_gaps, cal.rate_estimator.window_s);
	std::printf("  tau = %g s\n", tau_s);
	std::vector<const FitFigures*> figs{&cal.in_sample, &cal.held_out};
	if (validated) figs.push_back(&cal.validation);
	printFigures(figs);
	const CompensationCounters range = validationRange(cal);
	if (validated) std::fputs(app::outOfRangeWarning(range, cal.extrapolation).c_str(), stdout);
	if (cal.scale_factor)
	{
		const auto& sf = *cal.scale_factor;
		std::printf("  scale factor vs temperature: s(T(%s)) of order %zu from %zu table segments (|rate| %g..%g "
					"deg/h, %zu soaks, %.2f..%.2f degC)\n",
					sf.thermistor.c_str(), sf.order(), sf.segments, sf.table_rate_min_abs_dph,
					sf.table_rate_max_abs_dph, f.sf_report.groups, sf.min_C, sf.max_C);
		std::printf("    mean slope %.4g ppm/degC, 95 %% interval [%.4g, %.4g]; segment RMS in-sample %.3g ppm, "
					"held-out (%s) %.3g ppm\n",
					sf.slope_ppm_per_C, sf.slope_ci95_lo_ppm_per_C, sf.slope_ci95_hi_ppm_per_C, sf.rms_in_sample_ppm,
					sf.held_out_label.c_str(), sf.rms_held_out_ppm);
		std::printf("    interval = noise [%.4g, %.4g] widened to the slopes against each of %zu thermistor(s) "
					"[%.4g .. %.4g] (the coil temperature the scale factor follows is read by none)\n",
					sf.slope_noise_ci95_lo_ppm_per_C, sf.slope_noise_ci95_hi_ppm_per_C, sf.slope_thermistors,
					sf.slope_thermistor_min_ppm_per_C, sf.slope_thermistor_max_ppm_per_C);
		if (!sf.weights.empty())
		{
			std::printf("    weighted temperature T = ");
			for (std::size_t i = 0; i < sf.weights.size(); i++)
				std::printf("%s%.4g %s", i ? " + " : "", sf.weights[i], sf.thermistors[i].c_str());
			std::printf(" (weights fitted from the table segments, where the thermistors disagree)\n");
		}
		std::printf("    candidates (held-out RMS [ppm]):");
		for (const auto& c : f.sf_report.candidates) std::printf(" %s/%d:%.3g", c.thermistor.c_str(), c.order, c.rms_held_out_ppm);
		std::printf("\n");
	}
	if (cal.warmup)
	{
		const auto& w = *cal.warmup;
		std::printf("  warm-up: %.4g +- %.2g deg/h x exp(-t / (%.4g +- %.2g s)) from %zu turn-on(s) over %.0f s; "
					"residual RMS %.4g -> %.4g deg/h\n",
					w.amplitude_dph, w.amplitude_std_dph, w.tau_s, w.tau_std_s, w.turn_ons, w.fitted_span_s,
					w.rms_before_dph, w.rms_after_dph);
		if (w.hasSecondTerm())
			std::printf("    + %.4g +- %.2g deg/h x exp(-t / (%.4g +- %.2g s))\n", w.amplitude2_dph, w.amplitude2_std_dph,
						w.tau2_s, w.tau2_std_s);
		if (!f.warmup_terms_why.empty()) std::printf("    terms: %s\n", f.warmup_terms_why.c_str());
		if (w.startup_samples > 0)
			std::printf("    start-up offset %.4g +- %.2g deg/h while the rate-free start-up model runs after a turn-on "
						"(%zu samples)\n",
						w.startup_offset_dph, w.startup_offset_std_dph, w.startup_samples);
	}
	if (!f.warmup_why_not.empty())
		std::printf("  warm-up: no term from the turn-ons of the -i runs (their first hours stayed out of the bias fit): %s\n",
					f.warmup_why_not.c_str());
	if (!cal.scale_factor && f.table_rates)
		std::printf("  scale factor: not fitted (--scale-factor off): table samples used as bias samples\n");
	if (cal.magnetic)
	{
		const auto& m = *cal.magnetic;
		std::printf("  magnetic: %.4g +- %.2g deg/h per uT (95 %% interval %.4g .. %.4g) over the field %g .. %g uT, %zu "
					"samples\n",
					m.dph_per_uT, m.dph_per_uT_std, m.dph_per_uT - 1.959964 * m.dph_per_uT_std,
					m.dph_per_uT + 1.959964 * m.dph_per_uT_std, m.field_min_uT, m.field_max_uT, m.samples);
	}
	else if (!f.magnetic_why_not.empty())
		std::printf("  magnetic: not fitted: %s\n", f.magnetic_why_not.c_str());
}

JsonValue axisJson(const AxisFit& f, double tau_s, bool validated)
{
	const Calibration& cal = f.cal;
	const auto& m = cal.model;
	const CompensationCounters range = validationRange(cal);
	JsonValue j = JsonValue::object();
	j["preset"] = cal.preset;
	j["selection"] = toString(cal.selection);
	j["rate_estimator"] = cal.rate_estimator.describe();
	j["tau_s"] = tau_s;
	j["terms"] = static_cast<unsigned long>(m.features.termCount());
	JsonValue& names = j["term_names"] = JsonValue::array();
	for (const auto& n : m.features.termNames()) names.push_back(n);
	j["condition_number"] = m.condition_number;
	j["ridge"] = m.ridge;
	j["samples"] = static_cast<unsigned long>(m.samples);
	j["in_sample"] = figuresJson(cal.in_sample);
	j["held_out"] = figuresJson(cal.held_out);
	if (validated)
	{
		j["validation"] = figuresJson(cal.validation);
		j["validation"]["out_of_range"] = app::outOfRangeJson(range, cal.extrapolation);
	}
	j["extrapolation"] = toString(cal.extrapolation);
	j["rate_gaps"] = static_cast<unsigned long>(cal.rate_gaps);
	j["rates_unavailable"] = cal.rates_unavailable;
	j["reading_quantum_C"] = cal.reading_quantum_C;
	j["startup_model"] = cal.startup.has_value();
	const auto& st = cal.selection_stability;
	JsonValue& sj = j["selection_stability"] = JsonValue::object(
		{{"resamples", static_cast<unsigned long>(st.resamples)}, {"chosen_share", st.chosen_share},
		 {"stable", st.stable}, {"chosen_held_out_rms_dph", st.chosen_held_out_rms_dph},
		 {"held_out_se_mse", st.held_out_se_mse}, {"alternatives_equivalent", st.alternatives_equivalent}});
	sj["alternatives"] = JsonValue::arrayOf(st.alternatives, [](const auto& a) {
		return JsonValue::object({{"terms", a.terms}, {"share", a.share}, {"held_out_rms_dph", a.held_out_rms_dph}});
	});
	JsonValue& ts = sj["term_share"] = JsonValue::object();
	for (const auto& [t, v] : st.term_share) ts[t] = v;
	if (cal.scale_factor)
	{
		const auto& sf = *cal.scale_factor;
		JsonValue& js = j["scale_factor"];
		js["thermistor"] = sf.thermistor;
		if (!sf.thermistors.empty())  // "mean" or "weighted": the readings it combines
		{
			js["thermistors"] = JsonValue::arrayOf(sf.thermistors, [](const std::string& t) { return JsonValue(t); });
			if (!sf.weights.empty())
				js["weights"] = JsonValue::arrayOf(sf.weights, [](double w) { return JsonValue(w); });
		}
		js["order"] = static_cast<unsigned long>(sf.order());
		js["slope_ppm_per_C"] = sf.slope_ppm_per_C;
		js["slope_ci95_ppm_per_C"] = JsonValue::array();
		js["slope_ci95_ppm_per_C"].push_back(sf.slope_ci95_lo_ppm_per_C);
		js["slope_ci95_ppm_per_C"].push_back(sf.slope_ci95_hi_ppm_per_C);
		js["slope_noise_ci95_ppm_per_C"] = JsonValue::array();
		js["slope_noise_ci95_ppm_per_C"].push_back(sf.slope_noise_ci95_lo_ppm_per_C);
		js["slope_noise_ci95_ppm_per_C"].push_back(sf.slope_noise_ci95_hi_ppm_per_C);
		js["slope_thermistor_range_ppm_per_C"] = JsonValue::array();
		js["slope_thermistor_range_ppm_per_C"].push_back(sf.slope_thermistor_min_ppm_per_C);
		js["slope_thermistor_range_ppm_per_C"].push_back(sf.slope_thermistor_max_ppm_per_C);
		js["slope_thermistors"] = static_cast<unsigned long>(sf.slope_thermistors);
		js["min_C"] = sf.min_C;
		js["max_C"] = sf.max_C;
		js["table_rate_min_abs_dph"] = sf.table_rate_min_abs_dph;
		js["table_rate_max_abs_dph"] = sf.table_rate_max_abs_dph;
		js["segments"] = static_cast<unsigned long>(sf.segments);
		js["soaks"] = static_cast<unsigned long>(f.sf_report.groups);
		js["rms_in_sample_ppm"] = sf.rms_in_sample_ppm;
		js["rms_held_out_ppm"] = sf.rms_held_out_ppm;
		js["held_out_label"] = sf.held_out_label;
		js["candidates"] = JsonValue::arrayOf(f.sf_report.candidates, [](const auto& c) {
			return JsonValue::object({{"thermistor", c.thermistor}, {"order", static_cast<long>(c.order)},
									  {"rms_held_out_ppm", c.rms_held_out_ppm}});
		});
	}
	if (cal.warmup)
	{
		const auto& w = *cal.warmup;
		JsonValue& jw = j["warmup"];
		jw["amplitude_dph"] = w.amplitude_dph;
		jw["amplitude_std_dph"] = w.amplitude_std_dph;
		jw["tau_s"] = w.tau_s;
		jw["tau_std_s"] = w.tau_std_s;
		jw["turn_ons"] = static_cast<unsigned long>(w.turn_ons);
		jw["fitted_span_s"] = w.fitted_span_s;
		jw["rms_before_dph"] = w.rms_before_dph;
		jw["rms_after_dph"] = w.rms_after_dph;
		if (w.hasSecondTerm())
		{
			jw["amplitude2_dph"] = w.amplitude2_dph;
			jw["amplitude2_std_dph"] = w.amplitude2_std_dph;
			jw["tau2_s"] = w.tau2_s;
			jw["tau2_std_s"] = w.tau2_std_s;
		}
		jw["terms_choice"] = f.warmup_terms_why;
		jw["startup_offset_dph"] = w.startup_offset_dph;
		jw["startup_offset_std_dph"] = w.startup_offset_std_dph;
		jw["startup_samples"] = static_cast<unsigned long>(w.startup_samples);
	}
	if (!f.warmup_why_not.empty()) j["warmup_not_fitted"] = f.warmup_why_not;
	if (cal.magnetic)
	{
		const auto& m = *cal.magnetic;
		j["magnetic"] = JsonValue::object({{"dph_per_uT", m.dph_per_uT},
										   {"dph_per_uT_std", m.dph_per_uT_std},
										   {"field_min_uT", m.field_min_uT},
										   {"field_max_uT", m.field_max_uT},
										   {"samples", static_cast<unsigned long>(m.samples)}});
	}
	else if (!f.magnetic_why_not.empty())
		j["magnetic"] = JsonValue::object({{"not_fitted", f.magnetic_why_not}});
	if (f.earth_rate_removed) j["earth_rate"] = "removed from the bias (runs' metadata earth_rate_dph)";
	return j;
}
}  // namespace

namespace
{
/** --lags: none, physics (kPhysicsLagTaus_s) or a comma-separated list of time constants [s]. */
std::vector<double> parseLagTaus(const std::string& text)
{
	if (text == "none") return {};
	if (text == "physics") return kPhysicsLagTaus_s;
	std::vector<double> taus;
	std::size_t i = 0;
	while (i <= text.size())
	{
		const std::size_t j = std::min(text.find(',', i), text.size());
		const std::string item = text.substr(i, j - i);
		char* end = nullptr;
		const double t = std::strtod(item.c_str(), &end);
		if (item.empty() || *end != '\0' || !std::isfinite(t) || !(t > 0) || t > 1e7)
			throw std::invalid_argument("--lags must be none, physics or time constants in seconds (0, 1e7] separated by commas, got '" +
										text + "'");
		taus.push_back(t);
		i = j + 1;
	}
	return taus;
}
}  // namespace

int main(int argc, char** argv)
{
	app::returnLargeBlocksToSystem();
	return app::runApp("fog-calibrate", [&]() -> int {
		TCLAP::CmdLine cmd("fog-calibrate: fit the FOG thermal-bias model to chamber runs and write a calibration "
						   "YAML. Presets, the over-fitting guard and examples below.",
						   ' ', "0.1");
		app::InputMultiArg arg_in("i", "input", "Calibration run (.rawlog, .csv, .csv.gz); repeat for several", true, "RUN", cmd);
		TCLAP::ValueArg<std::string> arg_model("", "model", "Model preset (see below)", false, "multipoint", "PRESET", cmd);
		app::OutputArg arg_out("o", "output", "Calibration YAML to write", true, "", "CAL.yaml", cmd);
		app::InputArg arg_val("", "validate", "Independent run for held-out figures", false, "", "RUN", cmd);
		app::OutputArg arg_json("", "json", "Write the figures as JSON", false, "", "FILE", cmd);
		TCLAP::ValueArg<std::string> arg_label("", "label", "FOG sensor label in rawlogs with several", false, "", "L", cmd);
		TCLAP::ValueArg<std::string> arg_sel("", "selection", "auto (default) or none", false, "auto", "auto|none", cmd);
		app::RealArg arg_ridge(cmd, "ridge", "Fixed ridge for --selection none (relative)", "1", app::Range::closed(0, 1e6), 0.0);
		TCLAP::ValueArg<std::string> arg_est("", "estimator", "Rate estimator: causal (default) or savgol", false, "causal", "KIND", cmd);
		app::RealArg arg_window(cmd, "window", "Rate window", "s", app::Range::aboveUpTo(0, 3600), 60.0, "S");
		app::CountArg arg_order(cmd, "savgol-order", "Savitzky-Golay polynomial order", "1", 1, 4, 2);
		app::CountArg arg_corder(cmd, "causal-order",
								 "Causal estimator: 2 (default) extrapolates the window's slope to the newest sample "
								 "(no delay); 1 is the plain slope, about window/2 late",
								 "1", 1, 2, 2, "1|2");
		app::RealArg arg_selbin(cmd, "selection-bin",
								"auto: score candidates on the means of S-second bins (0 = every sample)", "s",
								app::Range::closed(0, 86400), FitOptions{}.selection_bin_s, "S");
		TCLAP::ValueArg<std::string> arg_step("", "step-rule",
											  "auto: a step must lower the held-out RMS by 0.5 % (relative) or be "
											  "significant over time blocks (significant)",
											  false, FitOptions{}.step_rule == StepRule::Significant ? "significant" : "relative",
											  "relative|significant", cmd);
		TCLAP::ValueArg<std::string> arg_osearch("", "order-search",
												 "auto: per-signal (forward, one order at a time) or common (one T order and "
												 "one rate order for all thermistors)",
												 false,
												 FitOptions{}.order_search == OrderSearch::Common ? "common" : "per-signal",
												 "per-signal|common", cmd);
		TCLAP::ValueArg<std::string> arg_runfolds("", "run-folds",
												  "several -i runs: one fold per run (runs) or each run's thermal regimes, every "
												  "fold trained on the other runs too (regimes)",
												  false, FitOptions{}.run_folds == RunFolds::RegimesWithinRuns ? "regimes" : "runs",
												  "runs|regimes", cmd);
		TCLAP::ValueArg<std::string> arg_lags("", "lags",
											  "multipoint / points:K with one thermistor: lag-rate candidates dTlag/dt(a,tau) "
											  "(none, physics = 100,400,1600 s, or a list of seconds S,S,..)",
											  false, FitOptions{}.lag_taus_s.empty() ? "none" : "physics", "none|physics|S,..", cmd);
		app::CountArg arg_lagmax(cmd, "lag-max-thermistors",
								 "offer the --lags candidates to presets reading at most N thermistors "
								 "(default 1; studies: larger)",
								 "thermistors", 0, 64, static_cast<unsigned>(FitOptions{}.lag_max_thermistors));
		app::CountArg arg_folds(cmd, "folds", "Cross-validation folds for a single run", "folds", 2, 100, 5, "K");
		app::RealArg arg_tau(cmd, "tau", "Averaging time of the stability figures", "s", app::Range::aboveUpTo(0, 1e6), 100.0, "S");
		TCLAP::SwitchArg arg_nofb("", "no-fallbacks", "Do not fit per-thermistor fallback models", cmd);
		TCLAP::ValueArg<std::string> arg_extra("", "extrapolation", "Outside the calibrated range: linear (default), clamp or polynomial",
											   false, "linear", "POLICY", cmd);
		TCLAP::ValueArg<std::string> arg_foldby("", "folds-by", "Validation folds of a single run: regimes (default) or blocks",
												false, "regimes", "SCHEME", cmd);
		TCLAP::ValueArg<std::string> arg_sf("", "scale-factor",
											"auto (default): fit the scale factor vs temperature from table-rate "
											"segments when a run has them; off: bias only",
											false, "auto", "auto|off", cmd);
		TCLAP::ValueArg<std::string> arg_sf_temp("", "sf-temperature",
												 "Temperature the scale factor is modelled in: thermistor (default: the "
												 "best single thermistor by held-out error) or mean (of all thermistors)",
												 false, "thermistor", "thermistor|mean", cmd);
		TCLAP::ValueArg<std::string> arg_mag("", "magnetic",
											 "auto (default): fit the bias per applied axial field when an -i run has a "
											 "changing field_uT column; off: never",
											 false, "auto", "auto|off", cmd);
		app::InputMultiArg arg_warm("", "warmup-run",
											  "Run holding a turn-on (cold start) to fit the warm-up term; repeatable; "
											  "not used in the bias fit",
											  false, "RUN", cmd);
		app::RealArg arg_turn_on_excl(
			cmd, "turn-on-exclusion",
			"Time after each turn-on in an -i run left out of the bias fit; without --warmup-run those "
			"runs then fit the warm-up term (3600 for a run that starts cold, e.g. fog-sim --profile "
			"calibration). 0 (default): the whole run joins the bias fit and no warm-up term is fitted on it",
			"s", app::Range::closed(0, 1e7), 0.0, "S");
		TCLAP::ValueArg<std::string> arg_warm_terms(
			"", "warmup-terms",
			"Exponential terms of the warm-up: 1, 2, or auto (default: chosen by held-out error, each "
			"--warmup-run left out in turn; with one run: 1)",
			false, "auto", "1|2|auto", cmd);
		TCLAP::SwitchArg arg_no_screen("", "no-screening",
									   "Do not screen thermistor readings (stuck / spike / out of range -> dropout) "
									   "before fitting (the screening fog-compensate runs)",
									   cmd);
		TCLAP::ValueArg<std::string> arg_axis("", "axis",
											  "Gyro axis to calibrate: x, y, z, or all (default: every axis the -i runs "
											  "share; one model per axis in one file)",
											  false, "all", "x|y|z|all", cmd);
		TCLAP::SwitchArg arg_allow_empty("", "allow-empty-model",
										 "Write the calibration even when the fit selects no thermal term (a constant "
										 "bias only); without it that is an error saying why",
										 cmd);
		TCLAP::SwitchArg arg_quiet("q", "quiet", "No progress line on stderr while the runs are read", cmd);
		app::LogInput log_input(cmd, "fog-calibrate");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-calibrate", kHelp)) return *rc;

		FitOptions opt;
		opt.selection = app::parseChoice(arg_sel, termSelectionFromString);
		opt.ridge = arg_ridge.getValue();
		opt.rate_estimator.kind = rateEstimatorKindFromString(arg_est.getValue());
		opt.rate_estimator.window_s = arg_window.getValue();
		opt.window_for_quantum = !arg_window.isSet();  // an explicit window is used as given
		opt.rate_estimator.poly_order =
			opt.rate_estimator.kind == RateEstimatorKind::SavitzkyGolay ? arg_order.get<int>() : arg_corder.get<int>();
		opt.folds = arg_folds.get<unsigned>();
		opt.turn_on_exclusion_s = arg_turn_on_excl.getValue();
		opt.selection_bin_s = arg_selbin.getValue();
		if (arg_step.getValue() != "relative" && arg_step.getValue() != "significant")
			throw std::invalid_argument("--step-rule must be relative or significant, got '" + arg_step.getValue() + "'");
		opt.step_rule = arg_step.getValue() == "significant" ? StepRule::Significant : StepRule::RelativeGain;
		if (arg_osearch.getValue() != "per-signal" && arg_osearch.getValue() != "common")
			throw std::invalid_argument("--order-search must be per-signal or common, got '" + arg_osearch.getValue() + "'");
		opt.order_search = arg_osearch.getValue() == "common" ? OrderSearch::Common : OrderSearch::PerSignal;
		if (arg_runfolds.getValue() != "runs" && arg_runfolds.getValue() != "regimes")
			throw std::invalid_argument("--run-folds must be runs or regimes, got '" + arg_runfolds.getValue() + "'");
		opt.run_folds = arg_runfolds.getValue() == "regimes" ? RunFolds::RegimesWithinRuns : RunFolds::Runs;
		opt.lag_taus_s = parseLagTaus(arg_lags.getValue());
		opt.lag_max_thermistors = arg_lagmax.get<unsigned>();
		opt.tau_s = arg_tau.getValue();
		opt.fallbacks = !arg_nofb.getValue();
		opt.extrapolation = extrapolationPolicyFromString(arg_extra.getValue());
		if (arg_foldby.getValue() != "regimes" && arg_foldby.getValue() != "blocks")
			throw std::invalid_argument("--folds-by must be regimes or blocks, got '" + arg_foldby.getValue() + "'");
		opt.fold_scheme = arg_foldby.getValue() == "regimes" ? FoldScheme::Regimes : FoldScheme::Blocks;

		if (arg_sf.getValue() != "auto" && arg_sf.getValue() != "off")
			throw std::invalid_argument("--scale-factor: '" + arg_sf.getValue() + "' is not auto or off");
		if (arg_mag.getValue() != "auto" && arg_mag.getValue() != "off")
			throw std::invalid_argument("--magnetic: '" + arg_mag.getValue() + "' is not auto or off");
		const bool screen = !arg_no_screen.getValue();
		std::string screening_text;
		// Each log is read once into a run spilled to a temporary file (memory independent of the
		// log's length, issue 14), screened on the way as fog-compensate screens it.
		// Gyro-off rows and turn-on events of each log read (apps/common/PowerCycles.h, the rule of
		// fog-evaluate and fog-compensate): those rows give no gyro sample to any fit or figure.
		struct RunPower
		{
			std::string role, path;
			app::PowerCycles counts;
		};
		std::vector<RunPower> run_power;
		const auto readScreened = [&](const std::string& path, const char* role) {
			app::StreamScreening sc(screen);
			app::Progress progress("fog-calibrate: reading " + path, arg_quiet.getValue());
			FogRun run = readFogRun(path, arg_label.getValue(), sc.hook(),
									[&](std::uint64_t n, std::uint64_t done, std::uint64_t total) { progress.update(n, done, total); },
									log_input.options());
			progress.finish();
			const ThermistorScreening counts = sc.result(run);
			if (!screen || counts.rejected_readings > 0) screening_text += "  " + path + ":\n" + app::screeningText(counts, screen);
			RunPower rp{role, path, {}};
			run.forEachChunk([&](const FogSeries& c, std::size_t) {
				for (std::size_t k = 0; k < c.size(); k++) rp.counts.add(c.power.empty() ? NAN : c.power[k]);
			});
			run_power.push_back(std::move(rp));
			return run;
		};
		// The scale-factor and warm-up fits take their runs in memory (rate-table and turn-on runs).
		const auto inMemory = [](const std::vector<FogRun>& rs) {
			std::vector<FogSeries> out;
			for (const auto& r : rs)
			{
				out.push_back(r.load());
				std::vector<double>().swap(out.back().field_uT);  // not read by these fits (memory)
			}
			return out;
		};
		const auto hasTableRates = [](const std::vector<FogRun>& rs) {  // chunk by chunk
			bool any = false;
			for (const auto& r : rs)
				r.forEachChunk([&](const FogSeries& c, std::size_t) {
					for (std::size_t k = 0; k < c.table_rate_dph.size() && !any; k++)
						any = c.table_rate_dph[k] != 0.0 && c.gyroOn(k);
				});
			return any;
		};
		std::vector<FogRun> runs;
		for (const auto& path : arg_in.getValue()) runs.push_back(readScreened(path, "-i"));
		// -i runs that hold a turn-on (a 0 -> 1 power step, or metadata power_on_time_s): with
		// --turn-on-exclusion > 0 their first hour after it stays out of the bias fit and they fit
		// the warm-up term, beside the --warmup-run runs (one chamber run that starts cold
		// calibrates both: docs/calibration.md, "One chamber run").
		std::vector<std::size_t> turn_on_inputs;
		for (std::size_t i = 0; i < runs.size(); i++)
			if (run_power[i].counts.turn_ons > 0 || !runs[i].header().metadataValue("power_on_time_s").empty())
				turn_on_inputs.push_back(i);
		std::vector<std::size_t> turn_on_in_fit;  // without --turn-on-exclusion: in the bias fit, no term
		if (!(opt.turn_on_exclusion_s > 0)) turn_on_in_fit.swap(turn_on_inputs);

		// The axes to calibrate: --axis, else every axis the -i runs share.
		std::vector<GyroAxis> axes;
		if (arg_axis.getValue() == "all" || arg_axis.getValue().empty())
		{
			axes = commonAxes(runs);
			if (axes.empty()) throw std::invalid_argument("the -i runs share no gyro axis; give --axis");
		}
		else if (arg_axis.getValue() == "x" || arg_axis.getValue() == "y" || arg_axis.getValue() == "z")
			axes.push_back(static_cast<GyroAxis>(arg_axis.getValue()[0] - 'x'));
		else
			throw std::invalid_argument("--axis: '" + arg_axis.getValue() + "' is not x, y, z or all");
		const bool several = axes.size() > 1;
		if (arg_sf_temp.getValue() != "thermistor" && arg_sf_temp.getValue() != "mean")
			throw std::invalid_argument("--sf-temperature: '" + arg_sf_temp.getValue() + "' is not thermistor or mean");
		ScaleFactorFitOptions sf_opt;
		sf_opt.thermistor_mean = arg_sf_temp.getValue() == "mean";

		std::vector<AxisFit> fits;
		for (std::size_t ia = 0; ia < axes.size(); ia++)
		{
			const GyroAxis axis = axes[ia];
			const std::string who = several ? std::string("axis ") + axisLetter(axis) + ": " : std::string();
			AxisRunViews set = runsForAxis(runs, arg_in.getValue(), axis);
			if (set.runs.empty())
			{
				std::string why;
				for (const auto& sk : set.skipped) why += "; " + sk;
				throw std::invalid_argument(who + "no -i run serves axis " + std::string(1, axisLetter(axis)) + why);
			}
			AxisFit f;
			f.skipped = set.skipped;
			f.earth_rate_removed = set.earth_rate_removed;
			FitOptions aopt = opt;
			const bool fit_sf = arg_sf.getValue() == "auto" && hasTableRates(set.runs);
			if (fit_sf) aopt.table_samples = TableSamples::Exclude;
			f.cal = fitCalibrationRuns(set.runs, arg_model.getValue(), aopt, set.labels);
			if (set.earth_rate_removed) f.cal.earth_rate = EarthRateHandling::InTableRate;
			if (fit_sf)
			{
				try
				{
					f.cal.scale_factor = fitScaleFactor(inMemory(set.runs), f.cal, sf_opt, &f.sf_report, set.labels);
				}
				catch (const ScaleFactorFitError& e)
				{
					throw std::runtime_error(who + e.what() +
											 "; the runs apply table rates, so a bias-only calibration would be wrong "
											 "there (give --scale-factor off to fit the bias alone anyway)");
				}
			}
			// The magnetic sensitivity on the residual of the calibration so far (MagneticFit.h),
			// when a run has field segments; the runs with a field column in memory for it.
			bool any_field = false;
			for (const auto& r : set.runs) any_field |= r.hasField();
			if (arg_mag.getValue() == "auto" && any_field)
			{
				std::vector<FogSeries> with_field;
				for (const auto& r : set.runs)
					if (r.hasField()) with_field.push_back(r.load());
				if (discrepancy::hasFieldVariation(with_field))
				{
					try
					{
						f.cal.magnetic = discrepancy::fitMagneticSensitivity(f.cal, with_field);
					}
					catch (const discrepancy::MagneticFitError& e)
					{
						f.magnetic_why_not = e.what();
					}
				}
			}
			// What the summary needs from the runs, then they are freed before the warm-up and
			// validation runs are read (memory: one log at a time, issue 14).
			f.run_count = set.runs.size();
			f.table_rates = hasTableRates(set.runs);
			if (f.cal.model.features.thermistors().empty()) f.why_empty = whyNoThermalTerm(set.runs, f.cal.model);
			fits.push_back(std::move(f));
		}
		// the warm-up term: from the --warmup-run runs when given (the user's choice), else from the
		// -i runs holding a turn-on
		std::vector<FogRun> warm;
		std::vector<std::string> warm_paths;
		if (arg_warm.getValue().empty())
			for (std::size_t i : turn_on_inputs)
			{
				warm.push_back(std::move(runs[i]));
				warm_paths.push_back(arg_in.getValue()[i]);
			}
		std::vector<FogRun>().swap(runs);
		if (!warm.empty() || !arg_warm.getValue().empty())
		{
			for (const auto& path : arg_warm.getValue())
			{
				warm.push_back(readScreened(path, "--warmup-run"));
				warm_paths.push_back(path);
			}
			// a failed warm-up fit stops fog-calibrate when --warmup-run asked for it; from -i runs
			// alone it is reported and the calibration written without the term
			const bool asked = !arg_warm.getValue().empty();
			for (std::size_t ia = 0; ia < fits.size(); ia++)
			{
				Calibration& cal = fits[ia].cal;
				AxisRunViews set = runsForAxis(warm, warm_paths, cal.axis);
				const std::string who = several ? std::string("axis ") + axisLetter(cal.axis) + ": " : std::string();
				if (set.earth_rate_removed != fits[ia].earth_rate_removed)
					throw std::runtime_error(who + "--warmup-run: the warm-up runs " +
											 (set.earth_rate_removed ? "state" : "do not state") +
											 " the Earth rate (metadata earth_rate_dph) and the -i runs " +
											 (set.earth_rate_removed ? "do not" : "do"));
				try
				{
					if (set.runs.empty()) throw WarmupFitError("no warm-up run has this axis");
					WarmupFitOptions wo;
					const std::string& terms = arg_warm_terms.getValue();
					if (terms == "auto")
					{
						const WarmupTermsChoice ch = selectWarmupTerms(inMemory(set.runs), cal, wo, set.labels);
						wo.exponentials = ch.exponentials;
						fits[ia].warmup_terms_why = ch.why;
					}
					else if (terms == "1" || terms == "2")
					{
						wo.exponentials = terms == "1" ? 1 : 2;
						fits[ia].warmup_terms_why = "--warmup-terms " + terms;
					}
					else
						throw std::invalid_argument("--warmup-terms: '" + terms + "' is not 1, 2 or auto");
					cal.warmup = fitWarmup(inMemory(set.runs), cal, wo, nullptr, set.labels);
				}
				catch (const WarmupFitError& e)
				{
					if (asked) throw std::runtime_error(who + e.what() + " (--warmup-run)");
					fits[ia].warmup_why_not = e.what();
				}
			}
		}
		if (!arg_val.getValue().empty())
		{
			std::vector<FogRun> val;
			val.push_back(readScreened(arg_val.getValue(), "--validate"));
			for (std::size_t ia = 0; ia < fits.size(); ia++)
			{
				Calibration& cal = fits[ia].cal;
				AxisRunViews set = runsForAxis(val, {arg_val.getValue()}, cal.axis);
				if (set.runs.empty())
				{
					cal.validation.label = "validation run " + arg_val.getValue() + ": " + set.skipped.front();
					continue;
				}
				if (set.earth_rate_removed != fits[ia].earth_rate_removed)
					throw std::runtime_error(arg_val.getValue() + ": --validate run and -i runs disagree on stating the "
											 "Earth rate (metadata earth_rate_dph." +
											 std::string(1, axisLetter(cal.axis)) + ")");
				cal.validation =
					evaluateCalibration(cal, set.runs.front(), "validation run " + arg_val.getValue(), opt.tau_s);
				fits[ia].validated = true;
			}
		}
		else
			for (auto& f : fits) f.cal.validation.label = "validation run (none given)";
		for (const auto& f : fits)
		{
			const Calibration& cal = f.cal;
			const std::string who = several ? std::string("axis ") + axisLetter(cal.axis) + ": " : std::string();
			if (cal.model.features.thermistors().empty())
			{
				if (!arg_allow_empty.getValue())
					throw std::runtime_error(who + "the fitted model has no thermal term (a constant bias only): " +
											 f.why_empty + "; nothing written (--allow-empty-model writes it anyway)");
				std::fprintf(stderr,
							 "fog-calibrate: warning: %sthe fitted model has no thermal term (a constant bias only): %s\n",
							 who.c_str(), f.why_empty.c_str());
			}
			else if (cal.held_out.valid && !(cal.held_out.stability_dph < 0.99 * cal.held_out.raw_stability_dph))
				std::fprintf(stderr,
							 "fog-calibrate: warning: %sthe thermal terms lower the held-out stability by less than 1 %% "
							 "(%.4g -> %.4g deg/h): the model compensates nothing these runs can show\n",
							 who.c_str(), cal.held_out.raw_stability_dph, cal.held_out.stability_dph);
		}
		CalibrationSet cal_set;
		for (const auto& f : fits) cal_set.axes.push_back(f.cal);
		saveCalibrationSet(cal_set, arg_out.getValue());

		for (const auto& f : fits)
		{
			if (several)
				std::printf("axis %c%s:\n", axisLetter(f.cal.axis),
							f.earth_rate_removed ? " (the runs' stated Earth rate removed from the bias)" : "");
			printAxis(f, opt.tau_s, f.validated);
		}
		std::fputs(screening_text.c_str(), stdout);
		std::size_t off_rows = 0, turn_ons = 0;
		for (const auto& rp : run_power)
		{
			off_rows += rp.counts.gyro_off_rows, turn_ons += rp.counts.turn_ons;
			if (rp.counts.gyro_off_rows)
				std::printf("  gyro off: %s %s: %zu rows (no gyro sample: left out of every fit and figure, thermistors "
							"kept); turn-on events: %zu\n",
							rp.role.c_str(), rp.path.c_str(), rp.counts.gyro_off_rows, rp.counts.turn_ons);
		}
		for (std::size_t i : turn_on_inputs)
			std::printf("  turn-on in -i %s: the first %.0f s after each turn-on stayed out of the bias fit%s "
						"(--turn-on-exclusion)\n",
						arg_in.getValue()[i].c_str(), opt.turn_on_exclusion_s,
						arg_warm.getValue().empty() ? " and went to the warm-up fit" : " (the warm-up term: from --warmup-run)");
		for (std::size_t i : turn_on_in_fit)
			std::printf("  note: -i %s holds a turn-on; its warm-up joined the bias fit (taken for a thermal effect) and "
						"no warm-up term was fitted (--turn-on-exclusion %.0f keeps the first hour out and fits the term)\n",
						arg_in.getValue()[i].c_str(), kSuggestedTurnOnExclusion_s);
		std::printf("  wrote %s\n", arg_out.getValue().c_str());

		if (!arg_json.getValue().empty())
		{
			JsonValue j = JsonValue::object();
			if (several)
			{
				JsonValue& ja = j["axes"] = JsonValue::object();
				for (const auto& f : fits) ja[std::string(1, axisLetter(f.cal.axis))] = axisJson(f, opt.tau_s, f.validated);
			}
			else
				j = axisJson(fits.front(), opt.tau_s, fits.front().validated);
			j["calibration"] = arg_out.getValue();
			j["input_notices"] = log_input.json();
			// every log read (-i, --warmup-run, --validate), summed and per log
			j["gyro_off_rows"] = static_cast<unsigned long>(off_rows);
			j["turn_on_events"] = static_cast<unsigned long>(turn_ons);
			j["turn_on_exclusion_s"] = opt.turn_on_exclusion_s;
			JsonValue& excl = j["turn_on_excluded_inputs"] = JsonValue::array();
			for (std::size_t i : turn_on_inputs) excl.push_back(JsonValue(arg_in.getValue()[i]));
			JsonValue& per = j["power_by_run"] = JsonValue::array();
			for (const auto& rp : run_power)
			{
				JsonValue r = JsonValue::object();
				r["role"] = rp.role;
				r["input"] = rp.path;
				r["gyro_off_rows"] = static_cast<unsigned long>(rp.counts.gyro_off_rows);
				r["turn_on_events"] = static_cast<unsigned long>(rp.counts.turn_ons);
				per.push_back(std::move(r));
			}
			writeTextFileAtomically(arg_json.getValue(), j.dump());
		}
		return app::kExitOk;
	});
}
