/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/CalibrationAugment.h>
#include <mrpt_fog/discrepancy/BaseModelDesign.h>
#include <mrpt_fog/discrepancy/CandidateEffect.h>
#include <mrpt_fog/discrepancy/EffectSelector.h>
#include <mrpt_fog/discrepancy/MagneticFit.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/ScaleFactorFit.h>
#include <mrpt_fog/model/WarmupFit.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/FitFigureStats.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <cmath>
#include <limits>

#include <algorithm>
#include <optional>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
/** Why a named effect adds no term to the calibration (the branches of augmentCalibration's loop
 * that did not apply). */
const char* notWrittenReason(sim::Effect effect)
{
	switch (effect)
	{
		case sim::Effect::RadialGradient:
		case sim::Effect::GradientRate: return "needs an inner and an outer thermistor";
		case sim::Effect::TempPolyOrder: return "the temperature polynomial is already of order 5";
		case sim::Effect::Warmup:
			return "no turn-on inside the analysed run: the warm-up amplitude is not separated from the "
				   "unknown earlier turn-on";
		case sim::Effect::ScaleFactorTemp: return "the analysed run applies no table rate";
		case sim::Effect::Hysteresis: return "no branch shape and width named (theta 0 or not finite)";
		default: return "no compensator term for it in this calibration schema";
	}
}

/** A turn-on (power 0 -> 1) inside the run (FogSeries::turnOnSamples: never at its first sample). */
bool hasTurnOnInside(const FogSeries& run) { return !run.turnOnSamples().empty(); }

std::string firstOnSide(const FogSeries& run, CoilSide side)
{
	for (const auto& t : run.thermistors)
		if (t.side == side) return t.name;
	return {};
}
/** Figures of a calibration run through the compensator on a series: evaluateCalibration (the
 * bias column) when it has no scale-factor model; with one, the compensated rate fog-compensate
 * outputs (bias and scale factor applied) minus the applied table rate, with the same
 * definitions (RMS about the mean over powered samples, stability and range of tau-s averages). */
FitFigures throughCompensator(const Calibration& cal, const FogSeries& series, const std::string& label)
{
	const double tau_s = 100.0;
	if (!cal.scale_factor) return evaluateCalibration(cal, series, label, tau_s);
	std::vector<double> comp = compensatedRate_dph(cal, series);
	std::vector<double> raw(series.rate_dph[static_cast<int>(cal.axis)]);
	for (std::size_t k = 0; k < raw.size(); ++k)
	{
		const double table = series.table_rate_dph.empty() ? 0.0 : series.table_rate_dph[k];
		const bool on = series.power.empty() || series.power[k] != 0.0;
		raw[k] -= table;
		comp[k] = on ? comp[k] - table : std::numeric_limits<double>::quiet_NaN();
	}
	FitFigures f;
	f.label = label;
	const auto pass = [&series](const std::vector<double>& v) -> RecordPass {
		return [&series, &v](const RecordVisitor& visit) {
			for (std::size_t k = 0; k < v.size(); k++) visit(series.time_s[k], v[k]);
		};
	};
	fitFiguresOfPasses(f, pass(comp), pass(raw), tau_s);
	return f;
}
}  // namespace

AugmentedCalibration augmentCalibration(const std::string& text, const std::vector<NamedEffect>& named,
										const FogSeries& run, const FogSeries* confirm, const std::string& confirm_label,
										ScaleFactorFitting sf)
{
	AugmentedCalibration out;
	out.base = calibrationUnderTest(text, run, FitScope::Full, sf);
	std::optional<WarmupModel> warmup;
	bool refit_magnetic = false;
	bool refit_scale_factor = false;
	bool refit_warmup = false;
	std::vector<std::string> terms;
	for (const auto& n : out.base.model.features.termNames())
		if (n != "1") terms.push_back(n);
	// the static polynomial's thermistor and order
	std::string S;
	int p = 0;
	for (const auto& t : out.base.model.features.terms())
		if (!t.constant && t.signal.kind == SignalKind::Temp)
		{
			if (S.empty()) S = t.signal.a;
			if (t.signal.a == S) p = std::max(p, t.power);
		}
	const std::string in = firstOnSide(run, CoilSide::Inner), outer = firstOnSide(run, CoilSide::Outer);
	if (S.empty()) S = in.empty() ? run.thermistors.front().name : in;
	auto add = [&](const std::string& term) {
		if (std::find(terms.begin(), terms.end(), term) == terms.end())
		{
			terms.push_back(term);
			out.added_terms.push_back(term);
		}
	};
	for (const auto& ne : named)
	{
		const bool pair = !in.empty() && !outer.empty();
		const sim::Effect effect = sim::effectFromId(ne.id);
		if (effect == sim::Effect::RadialGradient && pair)
		{
			add("dT(" + in + "-" + outer + ")^1");
			// the candidate's second column (RunSignals::outer_other_C) when the run has it
			const std::string other = firstOnSide(run, CoilSide::Other);
			if (!other.empty()) add("dT(" + outer + "-" + other + ")^1");
		}
		else if (effect == sim::Effect::GradientRate && pair && std::isfinite(ne.theta) && ne.theta > 0)
		{
			// named through a first-order lag: the lag is linear, so the lagged rate of Tin - Tout
			// is the lagged rate of Tin minus that of Tout, which the compensator runs as lag
			// terms (calibration version 3, LagFilter.h); one coefficient each
			add(ThermalTerm::lagRate(in, ne.theta, 1).name());
			add(ThermalTerm::lagRate(outer, ne.theta, 1).name());
		}
		else if (effect == sim::Effect::GradientRate && pair)
			add("d/dt dT(" + in + "-" + outer + ")^1");
		else if (effect == sim::Effect::ShupeRate)
		{
			add("dT/dt(" + (in.empty() ? S : in) + ")^1");
			if (pair) add("d/dt dT(" + in + "-" + outer + ")^1");
		}
		else if (effect == sim::Effect::TempPolyOrder && p < 5)
			for (int k = p + 1; k <= std::min(p + 2, 5); ++k) add("T(" + S + ")^" + std::to_string(k));
		else if (effect == sim::Effect::Magnetic)
			refit_magnetic = true;  // after the thermal refit: the field term is fitted on its residual
		else if (effect == sim::Effect::Hysteresis && std::isfinite(ne.theta) && ne.theta != 0.0 &&
				 hysteresisShapeOf(ne.theta).ratesOnly())
			out.not_written.emplace_back(ne.id, "the compensator has no operator for a rate-dependent saturation (" +
													describeHysteresisTheta(ne.theta) +
													"): only play and exponential-branch hysteresis are written");
		else if (effect == sim::Effect::Hysteresis && std::isfinite(ne.theta) && ne.theta != 0.0)
		{
			// the named shape and width on S (HysteresisFilter.h: the same operators, run on S's
			// reading; the exponential branch behind the filter's dead band)
			const HysteresisShape shape = hysteresisShapeOf(ne.theta);
			add(ThermalTerm::hysteresis(S,
										shape.kind == HysteresisShape::Kind::Play ? HysteresisOperator::Play
																				  : HysteresisOperator::Branch,
										shape.width)
					.name());
		}
		else if (effect == sim::Effect::ScaleFactorTemp && hasTableRates({run}))
			refit_scale_factor = true;
		else if (effect == sim::Effect::Warmup && ne.theta > 0 && !run.power.empty() && run.power.front() == 0.0)
		{
			// calibration v2 warm-up term (the compensator adds it after each turn-on); only when
			// the run starts with the gyro off: then the candidate had one column, its coefficient
			// is the amplitude at the turn-on
			WarmupModel w;
			w.amplitude_dph = ne.coefficient;
			w.amplitude_std_dph = (ne.ci_high - ne.ci_low) / (2 * 1.959964);
			w.tau_s = ne.theta;
			w.turn_ons = run.turnOnSamples().size();
			warmup = w;
			out.added_terms.push_back("warmup(amplitude_dph, tau_s)");
		}
		else if (effect == sim::Effect::Warmup && hasTurnOnInside(run))
		{
			// the run starts powered (its first turn-on unknown) but holds turn-ons: the warm-up
			// term by the calibration's own fit (WarmupFit.h) on those turn-ons, after the bias
			refit_warmup = true;
			out.added_terms.push_back("warmup(amplitude_dph, tau_s)");
		}
		else
			out.not_written.emplace_back(ne.id, notWrittenReason(effect));
	}
	std::size_t thermal_added = 0;
	for (const auto& t : out.added_terms) thermal_added += t.rfind("warmup", 0) == 0 ? 0 : 1;
	// table samples left out of the bias fit exactly when the base did so (fog-calibrate)
	const bool table = out.base.scale_factor.has_value() || (sf == ScaleFactorFitting::Auto && hasTableRates({run}));
	if (thermal_added == 0 && !refit_scale_factor)
		out.augmented = out.base;
	else
	{
		std::string preset = "terms:";
		bool first = true;
		for (const auto& t : terms)
		{
			preset += (first ? "" : ";") + t;
			first = false;
		}
		FitOptions fo;
		fo.selection = TermSelection::None;
		fo.rate_estimator = out.base.rate_estimator;
		fo.window_for_quantum = false;  // the base's window already is the one for the quantum
		fo.extrapolation = out.base.extrapolation;
		if (table) fo.table_samples = TableSamples::Exclude;  // as calibrationUnderTest / fog-calibrate
		if (thermal_added == 0)
			out.augmented = out.base;
		else
		{
			out.augmented = fitCalibration({run}, preset, fo);
			// an added term that reads a rate (gradient_rate, shupe_rate) carries the causal rate
			// estimate's noise times its coefficient: the window is chosen among 1, 2 and 4 x the
			// base's by the refit's residual RMS on the analysed run (same terms, same count of
			// coefficients; the confirmation run is not looked at)
			bool rate_added = false;
			for (const auto& t : out.added_terms) rate_added = rate_added || t.find("/dt") != std::string::npos;
			if (rate_added)
			{
				const double own_rms = evaluateCalibration(out.augmented, run, "analysed").rms_dph;
				double best_rms = own_rms;
				for (double factor : {2.0, 4.0})
				{
					FitOptions fw = fo;
					fw.rate_estimator.window_s = factor * out.base.rate_estimator.window_s;
					Calibration c = fitCalibration({run}, preset, fw);
					const double rms = evaluateCalibration(c, run, "analysed").rms_dph;
					if (rms < best_rms)
					{
						best_rms = rms;
						out.augmented = std::move(c);
					}
				}
				out.rate_window.changed = !(out.augmented.rate_estimator == out.base.rate_estimator);
				out.rate_window.rms_dph = best_rms;
				out.rate_window.base_window_rms_dph = own_rms;
			}
		}
		out.augmented.scale_factor.reset();
		out.augmented.warmup = out.base.warmup;
		if (refit_scale_factor)
		{
			// the scale factor versus temperature by the calibration's own fit (ScaleFactorFit.h:
			// table segments, thermistor and order chosen by leave-one-temperature-out error).
			// The naming has already tested the temperature dependence (the GLS test on the
			// analysed run, the held-out check on the confirmation run), so the held-out error
			// chooses among orders >= 1: with three soaks it would often keep a constant at
			// effect/noise 1, writing no term for an effect the workflow has just confirmed.
			try
			{
				ScaleFactorFitOptions sf_opt;
				sf_opt.min_order = 1;
				out.augmented.scale_factor = fitScaleFactor({run}, out.augmented, sf_opt);
				out.scale_factor_added = true;
			}
			catch (const ScaleFactorFitError& e)
			{
				out.augmented.scale_factor = out.base.scale_factor;
				out.not_written.emplace_back("scale_factor_temp", std::string("the scale-factor fit refused: ") + e.what());
			}
		}
		else
			out.augmented.scale_factor = out.base.scale_factor;
	}
	if (warmup) out.augmented.warmup = *warmup;
	if (refit_warmup)
	{
		out.augmented.warmup.reset();
		try
		{
			out.augmented.warmup = fitWarmup({run}, out.augmented);
		}
		catch (const WarmupFitError& e)
		{
			out.augmented.warmup = out.base.warmup;
			out.added_terms.erase(std::remove(out.added_terms.begin(), out.added_terms.end(), "warmup(amplitude_dph, tau_s)"),
								  out.added_terms.end());
			out.not_written.emplace_back("warmup", std::string("the warm-up fit on the run's turn-ons refused: ") + e.what());
		}
	}
	out.augmented.magnetic = out.base.magnetic;
	if (refit_magnetic)
	{
		// on the augmented calibration's residual (MagneticFit.h), its own magnetic section left out
		try
		{
			out.augmented.magnetic = fitMagneticSensitivity(out.augmented, {run});
			out.magnetic_added = true;
		}
		catch (const MagneticFitError& e)
		{
			out.not_written.emplace_back("magnetic", std::string("the field fit on the analysed run: ") + e.what());
		}
	}
	if (confirm)
	{
		out.has_confirm = true;
		out.before = throughCompensator(out.base, *confirm, confirm_label + " (calibration under test)");
		out.after = throughCompensator(out.augmented, *confirm, confirm_label + " (with the added terms)");
	}
	return out;
}

}  // namespace mrpt_fog::discrepancy
