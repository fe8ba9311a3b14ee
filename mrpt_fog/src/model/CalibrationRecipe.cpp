/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/model/AxisRuns.h>
#include <mrpt_fog/model/CalibrationRecipe.h>
#include <mrpt_fog/model/WarmupFit.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <stdexcept>

namespace mrpt_fog
{
constexpr EnumName<PartFit> kPartFits[] = {{PartFit::Auto, "auto"}, {PartFit::Off, "off"}};

const char* toString(PartFit p) { return nameIn(kPartFits, p, "auto"); }

PartFit partFitFromString(const std::string& text)
{
	if (const auto p = valueIn(kPartFits, text)) return *p;
	throw std::invalid_argument("'" + text + "' is not auto or off");
}

CalibrationSet CalibrationOutcome::set() const
{
	CalibrationSet s;
	for (const auto& a : axes) s.axes.push_back(a.cal);
	return s;
}

TurnOnUse turnOnsOf(const FogRun& run, const std::string& label)
{
	TurnOnUse u;
	u.label = label;
	const std::string meta = run.header().metadataValue("power_on_time_s");
	const double t_on = meta.empty() ? std::numeric_limits<double>::quiet_NaN() : std::strtod(meta.c_str(), nullptr);
	double prev = std::numeric_limits<double>::quiet_NaN();
	bool first = true, powered_after_on = false;
	run.forEachChunk([&](const FogSeries& c, std::size_t) {
		for (std::size_t k = 0; k < c.size(); k++)
		{
			const double p = c.power.empty() ? std::numeric_limits<double>::quiet_NaN() : c.power[k];
			if (first)
			{
				u.power_on_metadata = std::isfinite(t_on) && t_on <= c.time_s[k];
				first = false;
			}
			if (p == 0.0) u.gyro_off_rows++;
			if (p == 1.0 && prev == 0.0) u.turn_on_events++;
			if (c.gyroOn(k)) powered_after_on = true;
			prev = p;
		}
	});
	// metadata naming a turn-on of a run that is never powered: no turn-on to fit or leave out
	u.power_on_metadata = u.power_on_metadata && powered_after_on;
	return u;
}

namespace
{
/** The scale-factor and warm-up fits take their runs in memory (rate-table and turn-on runs). */
std::vector<FogSeries> inMemory(const std::vector<FogRun>& rs)
{
	std::vector<FogSeries> out;
	for (const auto& r : rs)
	{
		out.push_back(r.load());
		std::vector<double>().swap(out.back().field_uT);  // not read by these fits (memory)
	}
	return out;
}

bool anyTableRates(const std::vector<FogRun>& rs)
{
	bool any = false;
	for (const auto& r : rs)
		r.forEachChunk([&](const FogSeries& c, std::size_t) {
			for (std::size_t k = 0; k < c.table_rate_dph.size() && !any; k++)
				any = c.table_rate_dph[k] != 0.0 && c.gyroOn(k);
		});
	return any;
}

/** Why a fit selected no thermal term, from the runs themselves. */
std::string whyNoThermalTerm(const std::vector<FogRun>& runs, const BiasModel& m)
{
	std::size_t samples = 0;
	double span_C = 0.0;
	std::string span_name;
	double table_range = 0.0, residual_range = 0.0;
	constexpr double kInf = std::numeric_limits<double>::infinity();
	for (const auto& r : runs)
	{
		samples += r.size();
		const std::size_t nt = r.header().thermistorCount();
		std::vector<double> lo(nt, kInf), hi(nt, -kInf);
		double tlo = kInf, thi = -kInf, rlo = kInf, rhi = -kInf;
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

/** The magnetic section when the runs support it and its coefficient is resolved: a coefficient
 * whose 95 % interval spans zero was not excited by the data and is not written. */
void fitMagnetic(AxisCalibration& f, const std::vector<FogRun>& runs, const CalibrateOptions& opt)
{
	if (opt.magnetic == PartFit::Off) return;
	bool any_field = false;
	for (const auto& r : runs) any_field |= r.hasField();
	if (!any_field) return;
	if (!opt.magnetic_fit)
	{
		f.magnetic_why_not = "no magnetic fitter given (CalibrateOptions::magnetic_fit)";
		return;
	}
	std::vector<FogSeries> with_field;
	for (const auto& r : runs)
		if (r.hasField()) with_field.push_back(r.load());
	std::string why;
	const std::optional<MagneticModel> m = opt.magnetic_fit(f.cal, with_field, why);
	if (!m)
	{
		f.magnetic_why_not = why;
		return;
	}
	constexpr double kZ95 = 1.959964;
	if (!(std::abs(m->dph_per_uT) > kZ95 * m->dph_per_uT_std))
	{
		char b[400];
		std::snprintf(b, sizeof(b),
					  "the coefficient %.4g +- %.2g deg/h per uT is not resolved (95 %% interval %.4g .. %.4g spans "
					  "zero: the field over %zu samples, %g .. %g uT, does not excite it); not written",
					  m->dph_per_uT, m->dph_per_uT_std, m->dph_per_uT - kZ95 * m->dph_per_uT_std,
					  m->dph_per_uT + kZ95 * m->dph_per_uT_std, m->samples, m->field_min_uT, m->field_max_uT);
		f.magnetic_why_not = b;
		return;
	}
	f.cal.magnetic = *m;
}

/** The refinement of an automatically selected model by held-out stability
 * (CalibrateOptions::refine). Candidates are refitted with every term given (selection none) and
 * the chosen model's ridge. */
void refineByHeldOutStability(AxisCalibration& f, const std::vector<FogRun>& runs, const std::vector<std::string>& labels,
							  const FitOptions& aopt, const CalibrateOptions& opt)
{
	const BiasModel& m = f.cal.model;
	if (opt.refine == PartFit::Off || aopt.selection != TermSelection::Auto || m.features.thermistors().size() != 1 ||
		!f.cal.held_out.valid || !(f.cal.held_out.stability_dph > 0))
		return;
	std::vector<std::string> base = m.features.termNames(), no_lag;
	base.erase(base.begin());  // the constant
	bool has_lag = false;
	for (std::size_t i = 1; i < m.features.termCount(); i++)
	{
		const ThermalTerm& term = m.features.terms()[i];
		if (term.signal.isLag())
			has_lag = true;
		else
			no_lag.push_back(term.name());
	}
	const auto has = [](const std::vector<std::string>& terms, const std::string& name) {
		return std::find(terms.begin(), terms.end(), name) != terms.end();
	};
	const auto& names = m.features.thermistors();
	const int top = 3;  // up to the cubic (the PX4 model of a one-sensor IMU)
	std::vector<std::vector<std::string>> cands;
	const auto withCurvature = [&](const std::vector<std::string>& terms) {
		for (const auto& a : names)
		{
			std::vector<std::string> c = terms;
			bool added = false;
			for (int k = 2; k <= top; k++)
			{
				const std::string name = "T(" + a + ")^" + std::to_string(k);
				if (!has(c, name))
				{
					c.push_back(name);
					added = true;
				}
				if (added) cands.push_back(c);
			}
		}
	};
	withCurvature(base);
	if (has_lag && !no_lag.empty())
	{
		cands.push_back(no_lag);
		withCurvature(no_lag);
	}
	char b[300];
	std::snprintf(b, sizeof(b), "selected model: held-out stability %.4g deg/h", f.cal.held_out.stability_dph);
	f.refinement.push_back(b);
	double best = f.cal.held_out.stability_dph;
	std::optional<Calibration> pick;
	std::string pick_terms;
	for (const auto& c : cands)
	{
		std::string preset = "terms:";
		for (std::size_t i = 0; i < c.size(); i++) preset += (i ? ";" : "") + c[i];
		FitOptions o = aopt;
		o.selection = TermSelection::None;
		o.ridge = m.ridge;
		try
		{
			Calibration cal = fitCalibrationRuns(runs, preset, o, labels);
			std::snprintf(b, sizeof(b), "%s: held-out stability %.4g deg/h", preset.c_str() + 6,
						  cal.held_out.valid ? cal.held_out.stability_dph : std::numeric_limits<double>::quiet_NaN());
			f.refinement.push_back(b);
			if (cal.held_out.valid && cal.held_out.stability_dph < best)
			{
				best = cal.held_out.stability_dph;
				pick = std::move(cal);
				pick_terms = preset.substr(6);
			}
		}
		catch (const std::invalid_argument& e)
		{
			f.refinement.push_back(preset.substr(6) + ": not fitted (" + e.what() + ")");
		}
	}
	if (pick && best < (1.0 - opt.refine_min_gain) * f.cal.held_out.stability_dph)
	{
		std::snprintf(b, sizeof(b), "kept %s: held-out stability %.4g -> %.4g deg/h (at least %.0f %% lower)",
					  pick_terms.c_str(), f.cal.held_out.stability_dph, best, 100.0 * opt.refine_min_gain);
		f.refinement.push_back(b);
		pick->selection_stability = f.cal.selection_stability;  // of the selection the refinement started from
		f.cal = std::move(*pick);
	}
	else
	{
		std::snprintf(b, sizeof(b), "kept the selected model (no candidate lowers its held-out stability by %.0f %%)",
					  100.0 * opt.refine_min_gain);
		f.refinement.push_back(b);
	}
}

/** Why held-out figures have no data behind them: the runs that gave no usable sample. */
std::string heldOutWhyNot(const Calibration& cal, const std::vector<FogRun>& runs,
						  const std::vector<std::string>& labels)
{
	if (cal.held_out.valid) return "";
	std::string empty;
	for (std::size_t i = 0; i < runs.size(); i++)
	{
		std::size_t on = 0;
		runs[i].forEachChunk([&](const FogSeries& c, std::size_t) {
			for (std::size_t k = 0; k < c.size(); k++) on += c.gyroOn(k);
		});
		if (on == 0)
			empty += (empty.empty() ? "" : "; ") + labels[i] + " is gyro-off throughout";
		else if (runs[i].size() < 2)
			empty += (empty.empty() ? "" : "; ") + labels[i] + " has " + std::to_string(runs[i].size()) + " sample";
	}
	if (empty.empty())
		empty = "a run gives no usable sample (inside the turn-on exclusion, no rate window yet, or dropouts)";
	return "no held-out sample: " + empty +
		   ", so some fold has nothing to train on or to judge (the in-sample figures are still computed)";
}
}  // namespace

CalibrationOutcome calibrate(const CalibrationRuns& in, const CalibrateOptions& opt)
{
	if (in.runs.empty()) throw std::invalid_argument("calibrate: no calibration run given");
	if (in.labels.size() != in.runs.size() || in.warmup_labels.size() != in.warmup_runs.size())
		throw std::invalid_argument("calibrate: one label per run");
	if (in.validation.size() > 1) throw std::invalid_argument("calibrate: at most one validation run");
	if (!(opt.warmup_exponentials <= 2)) throw std::invalid_argument("calibrate: warm-up exponentials must be 0 (auto), 1 or 2");
	CalibrationOutcome out;
	const bool exclude = opt.fit.turn_on_exclusion_s > 0;
	const bool separate_warmup = !in.warmup_runs.empty();
	std::vector<std::size_t> warmup_inputs;  // calibration runs that fit the warm-up term
	for (std::size_t i = 0; i < in.runs.size(); i++)
	{
		TurnOnUse u = turnOnsOf(in.runs[i], in.labels[i]);
		if (u.turn_on_events > 0 || u.power_on_metadata)
		{
			u.use = !exclude ? TurnOnUse::Use::InBiasFit
				  : separate_warmup ? TurnOnUse::Use::ExcludedWarmupFromOtherRuns
									: TurnOnUse::Use::ExcludedToWarmupFit;
			if (u.use == TurnOnUse::Use::ExcludedToWarmupFit) warmup_inputs.push_back(i);
		}
		out.turn_ons.push_back(u);
	}
	for (const auto& w : in.warmup_labels)
		if (std::find(in.labels.begin(), in.labels.end(), w) != in.labels.end()) out.warmup_also_calibration.push_back(w);

	std::vector<GyroAxis> axes = opt.axes;
	if (axes.empty())
	{
		axes = commonAxes(in.runs);
		if (axes.empty()) throw std::invalid_argument("the calibration runs share no gyro axis; name one");
	}
	const bool several = axes.size() > 1;
	for (const GyroAxis axis : axes)
	{
		const std::string who = several ? std::string("axis ") + axisLetter(axis) + ": " : std::string();
		AxisRunViews set = runsForAxis(in.runs, in.labels, axis);
		if (set.runs.empty())
		{
			std::string why;
			for (const auto& sk : set.skipped) why += "; " + sk;
			throw std::invalid_argument(who + "no calibration run serves axis " + std::string(1, axisLetter(axis)) + why);
		}
		AxisCalibration f;
		f.skipped = set.skipped;
		f.earth_rate_removed = set.earth_rate_removed;
		FitOptions aopt = opt.fit;
		aopt.axis.reset();
		const bool fit_sf = opt.scale_factor == PartFit::Auto && anyTableRates(set.runs);
		if (fit_sf) aopt.table_samples = TableSamples::Exclude;
		f.cal = fitCalibrationRuns(set.runs, opt.model, aopt, set.labels);
		refineByHeldOutStability(f, set.runs, set.labels, aopt, opt);
		if (set.earth_rate_removed) f.cal.earth_rate = EarthRateHandling::InTableRate;
		if (fit_sf)
		{
			try
			{
				f.cal.scale_factor = fitScaleFactor(inMemory(set.runs), f.cal, opt.scale_factor_fit, &f.sf_report, set.labels);
			}
			catch (const ScaleFactorFitError& e)
			{
				throw std::runtime_error(who + e.what() +
										 "; the runs apply table rates, so a bias-only calibration would be wrong there "
										 "(switch the scale factor off to fit the bias alone anyway)");
			}
		}
		fitMagnetic(f, set.runs, opt);
		f.run_count = set.runs.size();
		f.table_rates = anyTableRates(set.runs);
		if (f.cal.model.features.thermistors().empty()) f.why_empty = whyNoThermalTerm(set.runs, f.cal.model);
		f.held_out_why_not = heldOutWhyNot(f.cal, set.runs, set.labels);

		// the warm-up term: from the separate warm-up runs when given, else from the calibration
		// runs holding a turn-on (their first hour stayed out of the bias fit)
		std::vector<FogRun> warm_views;
		std::vector<std::string> warm_labels;
		if (separate_warmup)
		{
			AxisRunViews w = runsForAxis(in.warmup_runs, in.warmup_labels, axis);
			if (w.earth_rate_removed != set.earth_rate_removed)
				throw std::runtime_error(who + "the warm-up runs " + (w.earth_rate_removed ? "state" : "do not state") +
										 " the Earth rate (metadata earth_rate_dph) and the calibration runs " +
										 (w.earth_rate_removed ? "do not" : "do"));
			warm_views = std::move(w.runs);
			warm_labels = std::move(w.labels);
		}
		else if (!warmup_inputs.empty())
		{
			AxisRunViews all = runsForAxis(in.runs, in.labels, axis);
			for (std::size_t k = 0; k < all.runs.size(); k++)
				for (std::size_t i : warmup_inputs)
					if (all.labels[k] == in.labels[i])
					{
						warm_views.push_back(std::move(all.runs[k]));
						warm_labels.push_back(all.labels[k]);
						break;
					}
		}
		if (separate_warmup || !warm_views.empty())
		{
			try
			{
				if (warm_views.empty()) throw WarmupFitError("no warm-up run has this axis");
				const std::vector<FogSeries> warm = inMemory(warm_views);
				WarmupFitOptions wo;
				if (opt.warmup_exponentials == 0)
				{
					const WarmupTermsChoice ch = selectWarmupTerms(warm, f.cal, wo, warm_labels);
					wo.exponentials = ch.exponentials;
					f.warmup_terms_why = ch.why;
				}
				else
				{
					wo.exponentials = opt.warmup_exponentials;
					f.warmup_terms_why = std::to_string(opt.warmup_exponentials) + " exponential(s), as asked";
				}
				f.cal.warmup = fitWarmup(warm, f.cal, wo, nullptr, warm_labels);
			}
			catch (const WarmupFitError& e)
			{
				// separate warm-up runs were given for this term: they must support it
				if (separate_warmup) throw std::runtime_error(who + e.what() + " (warm-up runs)");
				f.warmup_why_not = e.what();
			}
		}
		if (!in.validation.empty())
		{
			AxisRunViews v = runsForAxis(in.validation, {in.validation_label}, axis);
			if (v.runs.empty())
				f.cal.validation.label = "validation run " + in.validation_label + ": " + v.skipped.front();
			else
			{
				if (v.earth_rate_removed != set.earth_rate_removed)
					throw std::runtime_error(in.validation_label +
											 ": the validation run and the calibration runs disagree on stating the Earth "
											 "rate (metadata earth_rate_dph." +
											 std::string(1, axisLetter(axis)) + ")");
				f.cal.validation = evaluateCalibration(f.cal, v.runs.front(), "validation run " + in.validation_label, opt.fit.tau_s);
				f.validated = true;
			}
		}
		else
			f.cal.validation.label = "validation run (none given)";
		out.axes.push_back(std::move(f));
	}
	return out;
}

}  // namespace mrpt_fog
