/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/DiscrepancyAnalysis.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/metrics/PlotCanvas.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <cstdio>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double> masked(const Eigen::VectorXd& r, const std::vector<unsigned char>& rows)
{
	std::vector<double> v(rows.size(), kNaN);
	for (std::size_t k = 0; k < rows.size(); ++k)
		if (rows[k]) v[k] = r(static_cast<Eigen::Index>(k));
	return v;
}

RunGap makeRunGap(const std::string& label, const RunSignals& sig, const std::vector<Segment>& segs,
				  const Eigen::VectorXd& before, const Eigen::VectorXd& after, const std::vector<unsigned char>& rows,
				  const DiscrepancyOptions& opt)
{
	RunGap g;
	g.label = label;
	g.time_s = sig.time_s;
	g.before = gapFigures(sig.time_s, before, rows, opt.tau_s);
	g.after = gapFigures(sig.time_s, after, rows, opt.tau_s);
	g.residual_before_dph = masked(before, rows);
	g.residual_after_dph = masked(after, rows);
	g.ranking_before = rankSegments(segs, before, rows);
	const auto afterRank = rankSegments(segs, after, rows);
	for (const auto& s : g.ranking_before.ranked)
	{
		SegmentGap sg;
		sg.segment = s;
		for (const auto& a : afterRank.ranked)
			if (a.begin == s.begin) sg.rms_after_dph = a.rms_dph;
		sg.flagged = s.usable > 0 && s.rms_dph >= opt.flag_rms_ratio * g.ranking_before.run_rms_dph;
		std::vector<unsigned char> segRows(rows.size(), 0);
		for (std::size_t k = s.begin; k < s.end && k < rows.size(); ++k) segRows[k] = rows[k];
		sg.before = gapFigures(sig.time_s, before, segRows, opt.tau_s);
		sg.after = gapFigures(sig.time_s, after, segRows, opt.tau_s);
		g.segments.push_back(sg);
	}
	return g;
}

JsonValue figuresJson(const GapFigures& f, double tau_s)
{
	JsonValue j = JsonValue::object();
	j["rms_dph"] = f.rms_dph;
	j["stability_dph"] = f.stability_dph;
	j["range_dph"] = f.range_dph;
	j["tau_s"] = tau_s;
	j["samples"] = static_cast<unsigned long>(f.samples);
	return j;
}

/** One segment's gap figures. rank > 0 (the ranked top-level list) adds the rank and the
 * descriptive fields, in the same key order as before. */
JsonValue segmentJson(const SegmentGap& s, int rank)
{
	const bool ranked = rank > 0;
	JsonValue e = JsonValue::object();
	if (ranked) e["rank"] = rank;
	e["type"] = toString(s.segment.type);
	e["direction"] = s.segment.direction;
	e["band"] = s.segment.band;
	if (ranked) e["description"] = s.segment.describe();
	e["t_start_s"] = s.segment.t_start_s;
	e["t_end_s"] = s.segment.t_end_s;
	if (ranked) e["mean_temp_C"] = s.segment.mean_temp_C;
	e["rms_before_dph"] = s.segment.rms_dph;
	e["rms_after_dph"] = s.rms_after_dph;
	e["stability_before_dph"] = s.before.stability_dph;
	e["stability_after_dph"] = s.after.stability_dph;
	e["range_before_dph"] = s.before.range_dph;
	e["range_after_dph"] = s.after.range_dph;
	if (ranked)
	{
		e["energy_share"] = s.segment.energy_share;
		e["time_share"] = s.segment.time_share;
		e["flagged"] = s.flagged;
	}
	return e;
}

JsonValue runGapJson(const RunGap& g, double tau_s)
{
	JsonValue j = JsonValue::object();
	j["run"] = g.label;
	j["outside_model_range_samples"] = static_cast<unsigned long>(g.outside_model_range);
	j["validity_note"] = g.validity_note;
	j["before"] = figuresJson(g.before, tau_s);
	j["after"] = figuresJson(g.after, tau_s);
	JsonValue segs = JsonValue::array();
	for (const auto& s : g.segments) segs.push_back(segmentJson(s, 0));
	j["segments"] = segs;
	return j;
}

std::string fmt(const char* f, double v)
{
	char buf[64];
	std::snprintf(buf, sizeof buf, f, v);
	return buf;
}
}  // namespace

GapFigures gapFigures(const std::vector<double>& time_s, const Eigen::VectorXd& r, const std::vector<unsigned char>& rows,
					  double tau_s)
{
	GapFigures f;
	double s = 0;
	for (std::size_t k = 0; k < rows.size(); ++k)
		if (rows[k])
		{
			s += r(static_cast<Eigen::Index>(k)) * r(static_cast<Eigen::Index>(k));
			++f.samples;
		}
	f.rms_dph = f.samples ? std::sqrt(s / f.samples) : kNaN;
	try
	{
		const auto st = biasStats(time_s, masked(r, rows), tau_s);
		f.stability_dph = st.window_count >= 2 ? st.stability_dph : kNaN;
		f.range_dph = st.window_count >= 2 ? st.range_dph : kNaN;
	}
	catch (const std::invalid_argument&)
	{
		f.stability_dph = f.range_dph = kNaN;
	}
	return f;
}

RunGap runGapFromResiduals(const std::string& label, const RunSignals& sig, const std::vector<Segment>& segments,
						   const Eigen::VectorXd& before, const Eigen::VectorXd& after,
						   const std::vector<unsigned char>& rows, const DiscrepancyOptions& opt)
{
	return makeRunGap(label, sig, segments, before, after, rows, opt);
}

std::string DiscrepancyReport::verdict() const
{
	if (!cannot_tell.empty()) return "cannot tell: " + cannot_tell;
	if (selection.named.empty()) return "no missing effect found";
	std::string v = "missing: ";
	for (std::size_t i = 0; i < selection.named.size(); ++i)
	{
		v += (i ? ", " : "") + selection.named[i].id;
		if (selection.named[i].alias_group.size() > 1)
		{
			v += " (or alias";
			for (std::size_t j = 1; j < selection.named[i].alias_group.size(); ++j) v += " " + selection.named[i].alias_group[j];
			v += ")";
		}
	}
	if (selection.named.size() > 1) v += " (strongest first)";
	return v;
}

namespace
{
double percentile(std::vector<double> v, double q)
{
	if (v.empty()) return kNaN;
	std::sort(v.begin(), v.end());
	return v[static_cast<std::size_t>(std::floor(q * static_cast<double>(v.size() - 1)))];
}

/** Why the analysed run cannot answer, or "" (see DiscrepancyOptions). */
std::string informationShortfall(const RunSignals& sig, const FogSeries& run, const DiscrepancyOptions& opt)
{
	char buf[300];
	double usable_s = 0;
	std::vector<double> temps;
	for (std::size_t k = 0; k < sig.size(); ++k)
		if (sig.usable[k])
		{
			usable_s += k > 0 ? std::min(sig.time_s[k] - sig.time_s[k - 1], 3.0 * sig.dt_s) : sig.dt_s;
			temps.push_back(sig.temp_mean_C[k]);
		}
	if (usable_s < opt.min_usable_s)
	{
		std::snprintf(buf, sizeof buf, "only %.0f min of usable data on the analysed run (at least %.0f min needed)",
					  usable_s / 60.0, opt.min_usable_s / 60.0);
		return buf;
	}
	const double span = percentile(temps, 0.99) - percentile(temps, 0.01);
	if (!(span >= opt.min_temp_span_C))
	{
		std::snprintf(buf, sizeof buf, "the mean temperature spans only %.2f C (at least %.1f C needed)", span,
					  opt.min_temp_span_C);
		return buf;
	}
	// quantisation: the most common non-zero step between consecutive readings
	std::vector<double> steps;
	for (const auto& col : run.temp_C)
		for (std::size_t k = 1; k < col.size(); ++k)
		{
			const double d = std::fabs(col[k] - col[k - 1]);
			if (std::isfinite(d) && d > 0) steps.push_back(d);
		}
	const double quantum = steps.size() >= 20 ? percentile(steps, 0.05) : 0.0;
	if (quantum > 0 && span / quantum < opt.min_span_quanta)
	{
		std::snprintf(buf, sizeof buf,
					  "the temperatures are quantised to about %.3g C over a span of %.2f C (%.0f levels, at least "
					  "%.0f needed)",
					  quantum, span, span / quantum, opt.min_span_quanta);
		return buf;
	}
	return {};
}

/** Range of each thermistor over the usable samples of the run a model was fitted on. */
std::vector<std::pair<double, double>> fittedRanges(const RunSignals& sig)
{
	std::vector<std::pair<double, double>> r(sig.thermistor_C.size(), {INFINITY, -INFINITY});
	for (std::size_t i = 0; i < r.size(); ++i)
		for (std::size_t k = 0; k < sig.size(); ++k)
			if (sig.usable[k])
			{
				r[i].first = std::min(r[i].first, sig.thermistor_C[i][k]);
				r[i].second = std::max(r[i].second, sig.thermistor_C[i][k]);
			}
	return r;
}

/** Usable rows of `sig` inside the fitted ranges; counts those outside. */
std::vector<unsigned char> rowsInsideRange(const RunSignals& sig, const std::vector<std::pair<double, double>>& range,
										   std::size_t& outside)
{
	std::vector<unsigned char> rows(sig.usable);
	outside = 0;
	for (std::size_t k = 0; k < sig.size(); ++k)
	{
		if (!rows[k]) continue;
		for (std::size_t i = 0; i < range.size() && i < sig.thermistor_C.size(); ++i)
			if (sig.thermistor_C[i][k] < range[i].first || sig.thermistor_C[i][k] > range[i].second)
			{
				rows[k] = 0;
				++outside;
				break;
			}
	}
	return rows;
}
}  // namespace

DiscrepancyReport analyseDiscrepancy(const std::vector<FogSeries>& runs, const std::vector<std::string>& labels,
									 const std::string& model, const DiscrepancyOptions& opt)
{
	if (runs.empty()) throw std::invalid_argument("no measured run given");
	if (runs.size() > 2)
		throw std::invalid_argument("at most two measured runs: the first is analysed, the second confirms");
	if (runs.size() == 2 && !runs[0].sameLayout(runs[1]))
		throw std::invalid_argument("the confirmation run has a different thermistor/axis layout from the first run");
	DiscrepancyReport rep;
	rep.model_source = model;
	rep.tau_s = opt.tau_s;
	for (std::size_t i = 0; i < runs.size(); ++i)
		rep.run_labels.push_back(i < labels.size() ? labels[i] : "run " + std::to_string(i + 1));

	const auto sig1 = computeRunSignals(runs[0], opt.signals);
	BaseModelSpec spec;
	try
	{
		spec = resolveBaseModel(model, runs[0]);
	}
	catch (const std::invalid_argument& e)
	{
		// the model cannot even be fitted: when the run holds too little information that is
		// the answer ("cannot tell"), otherwise the error stands
		rep.cannot_tell = informationShortfall(sig1, runs[0], opt);
		if (rep.cannot_tell.empty()) throw;
		rep.cannot_tell += std::string(" (the model cannot be fitted: ") + e.what() + ")";
		return rep;
	}
	const auto base1 = buildBaseDesign(spec, runs[0], sig1);
	rep.base_terms = base1.names;
	rep.selection = selectMissingEffects(sig1, base1, opt.selection);
	rep.cannot_tell = informationShortfall(sig1, runs[0], opt);
	if (rep.cannot_tell.empty() && !rep.selection.named.empty() && !rep.selection.ar.phi.empty())
	{
		// slow bias wander: a run a few correlation times long cannot tell a drift from an effect
		const double phi = rep.selection.ar.phi.front();
		if (phi > 0 && phi < 1)
		{
			const double corr_s = -sig1.dt_s / std::log(phi);
			const double spans = (sig1.time_s.back() - sig1.time_s.front()) / corr_s;
			if (spans < opt.min_wander_spans)
			{
				char buf[300];
				std::snprintf(buf, sizeof buf,
							  "the residual wanders with a correlation time of %.0f min: the run covers only %.1f of them "
							  "(at least %.0f needed to tell a slow drift from an effect)",
							  corr_s / 60.0, spans, opt.min_wander_spans);
				rep.cannot_tell = buf;
			}
		}
	}
	std::optional<RunSignals> sig2;
	std::optional<BaseDesign> base2;
	if (runs.size() == 2)
	{
		sig2 = computeRunSignals(runs[1], opt.signals);
		base2 = buildBaseDesign(spec, runs[1], *sig2);
		confirmOnRun(rep.selection, *sig2, *base2, opt.selection);
	}
	// Guard rails (after confirmation): an effect is not named when the data cannot answer,
	// when its fitted contribution is larger than the raw bias range, or when its 95 %
	// interval includes zero; it is then refitted away like an unconfirmed one.
	{
		auto& sel = rep.selection;
		double lo = INFINITY, hi = -INFINITY;
		for (std::size_t k = 0; k < sig1.size(); ++k)
			if (sel.fit_rows[k] && std::isfinite(sig1.bias_dph[k]))
			{
				lo = std::min(lo, sig1.bias_dph[k]);
				hi = std::max(hi, sig1.bias_dph[k]);
			}
		const double raw_range = hi - lo;
		const Eigen::MatrixXd X = sel.model.design(base1, sig1);
		const auto ctx = makeCandidateContext(sig1, base1, sel.model.lag_base_coef);
		Eigen::Index col = base1.X.cols();
		std::vector<std::pair<std::string, std::string>> reasons;
		for (const auto& term : sel.model.effects)
		{
			const Eigen::Index q = candidateById(term.id).build(ctx, term.theta).cols();
			std::string reason;
			if (!rep.cannot_tell.empty()) reason = "cannot tell: " + rep.cannot_tell;
			else if (col + q <= X.cols() && col + q <= sel.coef_after.size())
			{
				const Eigen::VectorXd part = X.middleCols(col, q) * sel.coef_after.segment(col, q);
				double plo = INFINITY, phi = -INFINITY;
				for (std::size_t k = 0; k < sig1.size(); ++k)
					if (sel.fit_rows[k])
					{
						plo = std::min(plo, part(static_cast<Eigen::Index>(k)));
						phi = std::max(phi, part(static_cast<Eigen::Index>(k)));
					}
				if (phi - plo > raw_range)
				{
					char buf[200];
					std::snprintf(buf, sizeof buf,
								  "implausible: its fitted contribution spans %.4g deg/h, more than the raw bias range "
								  "%.4g deg/h",
								  phi - plo, raw_range);
					reason = buf;
				}
			}
			col += q;
			if (reason.empty())
				for (const auto& ne : sel.named)
					if (ne.id == term.id && ne.ci_low <= 0 && ne.ci_high >= 0)
						reason = "its 95 % interval includes zero";
			if (reason.empty() && sig2)
			{
				// held out: with the coefficients fitted on the analysed run, the effect must shrink
				// the OTHER run's residual (a slowly varying regressor fitted to slow bias wander
				// can pass both significance tests and still not generalise)
				AugmentedModel without = sel.model;
				without.effects.erase(std::remove_if(without.effects.begin(), without.effects.end(),
													 [&](const EffectTerm& t) { return t.id == term.id; }),
									  without.effects.end());
				const Eigen::MatrixXd X1m = without.design(base1, sig1);
				std::vector<Eigen::Index> rows;
				for (std::size_t k = 0; k < sig1.size(); ++k)
					if (sel.fit_rows[k]) rows.push_back(static_cast<Eigen::Index>(k));
				Eigen::MatrixXd A(static_cast<Eigen::Index>(rows.size()), X1m.cols());
				Eigen::VectorXd yv(static_cast<Eigen::Index>(rows.size()));
				for (std::size_t i = 0; i < rows.size(); ++i)
				{
					A.row(static_cast<Eigen::Index>(i)) = X1m.row(rows[i]);
					yv(static_cast<Eigen::Index>(i)) = sig1.bias_dph[static_cast<std::size_t>(rows[i])];
				}
				const Eigen::VectorXd coefWithout = A.colPivHouseholderQr().solve(yv);
				const auto rWith = residualWithCoefficients(sel.model.design(*base2, *sig2), *sig2, sel.coef_after);
				const auto rWithout = residualWithCoefficients(without.design(*base2, *sig2), *sig2, coefWithout);
				const double with2 = rWith.squaredNorm(), without2 = rWithout.squaredNorm();
				if (!(with2 < without2))
				{
					const double nu = static_cast<double>(std::max<std::size_t>(sig2->usableCount(), 1));
					char buf[200];
					std::snprintf(buf, sizeof buf,
								  "held out: with its coefficient from the analysed run it does not shrink the other "
								  "run's residual (RMS %.4g without, %.4g with, deg/h)",
								  std::sqrt(without2 / nu), std::sqrt(with2 / nu));
					reason = buf;
				}
			}
			if (!reason.empty()) reasons.emplace_back(term.id, reason);
		}
		if (!reasons.empty())
		{
			for (auto& ne : sel.named)
				for (const auto& [id, why] : reasons)
					if (ne.id == id)
					{
						ne.confirm_tested = true;
						ne.confirmed = false;
					}
			const std::size_t before = sel.not_confirmed.size();
			keepConfirmedEffects(sel, sig1, base1);
			// the guard-railed ones go to `rejected`, not to `not_confirmed`
			std::vector<NamedEffect> still;
			for (std::size_t i = 0; i < sel.not_confirmed.size(); ++i)
			{
				bool guarded = false;
				if (i >= before)
					for (const auto& [id, why] : reasons)
						if (sel.not_confirmed[i].id == id)
						{
							rep.rejected.push_back({id, why});
							guarded = true;
						}
				if (!guarded) still.push_back(sel.not_confirmed[i]);
			}
			sel.not_confirmed = still;
		}
	}
	if (runs.size() == 2)
	{
		// only effects confirmed on the second run are added (keepConfirmedEffects); the gap is
		// computed only where the model is valid (inside the temperatures it was fitted on)
		rep.has_confirm = true;
		keepConfirmedEffects(rep.selection, sig1, base1);
		const auto rb = residualWithCoefficients(base2->X, *sig2, rep.selection.coef_before);
		const auto ra = residualWithCoefficients(rep.selection.model.design(*base2, *sig2), *sig2, rep.selection.coef_after);
		std::size_t outside = 0;
		const auto range = fittedRanges(sig1);
		const auto rows2 = rowsInsideRange(*sig2, range, outside);
		rep.gap_confirm = makeRunGap(rep.run_labels[1], *sig2, segmentRun(*sig2, opt.segmentation), rb, ra, rows2, opt);
		rep.gap_confirm.outside_model_range = outside;
		if (outside > 0)
		{
			const std::size_t usable = sig2->usableCount();
			char buf[300];
			std::snprintf(buf, sizeof buf,
						  "%.1f %% of %s's usable samples have a thermistor outside the range the model was fitted on "
						  "(e.g. %s %.2f..%.2f C): left out of its gap figures (no extrapolation)",
						  usable ? 100.0 * double(outside) / double(usable) : 0.0, rep.run_labels[1].c_str(),
						  runs[0].thermistors.empty() ? "?" : runs[0].thermistors[0].name.c_str(),
						  range.empty() ? NAN : range[0].first, range.empty() ? NAN : range[0].second);
			rep.gap_confirm.validity_note = buf;
		}
	}
	const auto segs1 = segmentRun(sig1, opt.segmentation);
	rep.gap = makeRunGap(rep.run_labels[0], sig1, segs1, rep.selection.residual_before, rep.selection.residual_after,
						 rep.selection.fit_rows, opt);
	return rep;
}

JsonValue discrepancyJson(const DiscrepancyReport& rep)
{
	const auto& sel = rep.selection;
	JsonValue j = JsonValue::object();
	j["model"] = rep.model_source;
	JsonValue terms = JsonValue::array();
	for (const auto& t : rep.base_terms) terms.push_back(t);
	j["base_terms"] = terms;
	JsonValue runs = JsonValue::array();
	for (const auto& r : rep.run_labels) runs.push_back(r);
	j["runs"] = runs;
	j["verdict"] = rep.verdict();
	JsonValue named = JsonValue::array();
	for (const auto& ne : sel.named)
	{
		JsonValue e = JsonValue::object();
		e["id"] = ne.id;
		JsonValue ag = JsonValue::array();
		for (const auto& a : ne.alias_group) ag.push_back(a);
		e["alias_group"] = ag;
		e["confidence"] = ne.confidence;
		e["group_confidence"] = ne.group_confidence;
		e["coefficient"] = ne.coefficient;
		e["coefficient_unit"] = ne.coefficient_unit;
		JsonValue ci = JsonValue::array();
		ci.push_back(ne.ci_low);
		ci.push_back(ne.ci_high);
		e["ci"] = ci;
		if (!ne.theta_name.empty()) e[ne.theta_name] = ne.theta;
		e["chi2"] = ne.chi2;
		e["p_adjusted"] = ne.p_adjusted;
		e["delta_bic"] = ne.delta_bic;
		JsonValue sep = JsonValue::array();
		for (const auto& s : ne.separating_profiles) sep.push_back(s);
		e["separating_profiles"] = sep;
		if (ne.confirm_tested)
		{
			e["confirmed"] = ne.confirmed;
			e["confirm_p"] = ne.confirm_p;
		}
		named.push_back(e);
	}
	j["named_effects"] = named;
	// named on the analysed run, not confirmed on the second run: reported, not added
	JsonValue unconfirmed = JsonValue::array();
	for (const auto& ne : sel.not_confirmed)
	{
		JsonValue e = JsonValue::object();
		e["id"] = ne.id;
		e["p_adjusted"] = ne.p_adjusted;
		e["coefficient"] = ne.coefficient;
		e["coefficient_unit"] = ne.coefficient_unit;
		e["confirm_p"] = ne.confirm_p;
		unconfirmed.push_back(e);
	}
	j["not_confirmed"] = unconfirmed;
	JsonValue rejected = JsonValue::array();
	for (const auto& r : rep.rejected)
	{
		JsonValue e = JsonValue::object();
		e["id"] = r.id;
		e["reason"] = r.reason;
		rejected.push_back(e);
	}
	j["not_named"] = rejected;
	j["cannot_tell"] = rep.cannot_tell;
	j["where"] = rep.gap.ranking_before.sentence;
	JsonValue segs = JsonValue::array();
	int rank = 1;
	for (const auto& s : rep.gap.segments) segs.push_back(segmentJson(s, rank++));
	j["segments"] = segs;
	JsonValue groups = JsonValue::array();
	for (const auto& g : rep.gap.ranking_before.groups)
	{
		JsonValue e = JsonValue::object();
		e["description"] = g.description;
		e["rms_dph"] = g.rms_dph;
		e["energy_share"] = g.energy_share;
		e["time_share"] = g.time_share;
		e["segments"] = static_cast<unsigned long>(g.segments);
		groups.push_back(e);
	}
	j["segment_groups"] = groups;
	JsonValue cands = JsonValue::array();
	if (!sel.rounds.empty())
		for (const auto& t : sel.rounds.front())
		{
			JsonValue e = JsonValue::object();
			e["id"] = t.id;
			e["status"] = t.status;
			e["note"] = t.note;
			if (t.status == "tested")
			{
				e["chi2"] = t.chi2;
				e["dof"] = t.dof;
				e["p_adjusted"] = t.p_adjusted;
				e["delta_bic"] = t.delta_bic;
				e["significant"] = t.significant;
			}
			cands.push_back(e);
		}
	j["candidates_first_round"] = cands;
	JsonValue noise = JsonValue::object();
	JsonValue phi = JsonValue::array();
	for (double p : sel.ar.phi) phi.push_back(p);
	noise["ar_phi"] = phi;
	noise["ma_theta"] = sel.ar.theta;
	noise["long_run_variance_factor"] = sel.lrv_factor;
	noise["outliers_excluded"] = static_cast<unsigned long>(sel.outliers);
	j["noise_model"] = noise;
	j["gap"] = runGapJson(rep.gap, rep.tau_s);
	if (rep.has_confirm) j["gap_confirm"] = runGapJson(rep.gap_confirm, rep.tau_s);
	return j;
}

std::string discrepancyText(const DiscrepancyReport& rep)
{
	std::ostringstream os;
	const auto& sel = rep.selection;
	if (rep.base_terms.empty() && !rep.cannot_tell.empty())
		return "Model under test: " + rep.model_source + " (not fitted)\nVerdict: " + rep.verdict() + "\n";
	os << "Model under test: " << rep.model_source << " (" << rep.base_terms.size() << " terms, refitted on "
	   << rep.run_labels[0] << ")\n";
	os << "Where: " << rep.gap.ranking_before.sentence << "\n";
	os << "Top segments by residual energy (before):\n";
	for (std::size_t i = 0; i < rep.gap.segments.size() && i < 5; ++i)
	{
		const auto& s = rep.gap.segments[i];
		os << "  " << i + 1 << ". " << s.segment.describe() << " [" << fmt("%.0f", s.segment.t_start_s) << ".."
		   << fmt("%.0f", s.segment.t_end_s) << " s] RMS " << fmt("%.3g", s.segment.rms_dph) << " -> "
		   << fmt("%.3g", s.rms_after_dph) << " deg/h, " << fmt("%.0f", 100 * s.segment.energy_share)
		   << " % of the energy" << (s.flagged ? "  (flagged)" : "") << "\n";
	}
	os << "Verdict: " << rep.verdict() << "\n";
	for (const auto& ne : sel.named)
	{
		os << "  " << ne.id << ": " << candidateById(ne.id).description << "\n";
		os << "    coefficient " << fmt("%.4g", ne.coefficient) << " " << ne.coefficient_unit << " (95 % CI "
		   << fmt("%.4g", ne.ci_low) << " .. " << fmt("%.4g", ne.ci_high) << ")";
		if (!ne.theta_name.empty()) os << ", " << ne.theta_name << " = " << fmt("%g", ne.theta);
		os << "; confidence " << fmt("%.2f", ne.confidence) << ", chi2 " << fmt("%.1f", ne.chi2) << ", Holm p "
		   << fmt("%.2g", ne.p_adjusted) << "\n";
		for (std::size_t a = 1; a < ne.alias_group.size(); ++a)
			os << "    alias: " << ne.alias_group[a] << " cannot be told apart on this run; to separate them use "
			   << ne.separating_profiles[a - 1] << "\n";
		if (ne.alias_group.size() > 1)
			os << "    confidence of the alias group: " << fmt("%.2f", ne.group_confidence) << "\n";
		if (ne.confirm_tested)
			os << "    confirmation run: " << (ne.confirmed ? "confirmed" : "NOT confirmed") << " (p "
			   << fmt("%.2g", ne.confirm_p) << ")\n";
	}
	for (const auto& ne : sel.not_confirmed)
		os << "  not confirmed (named on " << rep.run_labels[0] << ", not added): " << ne.id << ", coefficient "
		   << fmt("%.4g", ne.coefficient) << " " << ne.coefficient_unit << ", Holm p " << fmt("%.2g", ne.p_adjusted)
		   << "; on the confirmation run p " << fmt("%.2g", ne.confirm_p)
		   << (ne.confirm_p < 0.01 ? " with the opposite sign" : "") << "\n";
	for (const auto& r : rep.rejected) os << "  not named: " << r.id << " (" << r.reason << ")\n";
	if (!sel.rounds.empty())
	{
		std::string skipped;
		for (const auto& t : sel.rounds.front())
			if (t.status != "tested") skipped += "  " + t.id + ": " + t.status + " (" + t.note + ")\n";
		if (!skipped.empty()) os << "Not tested:\n" << skipped;
	}
	auto gapLine = [&](const RunGap& g)
	{
		os << "Gap on " << g.label << ": RMS " << fmt("%.4g", g.before.rms_dph) << " -> " << fmt("%.4g", g.after.rms_dph)
		   << " deg/h; " << fmt("%g", rep.tau_s) << " s stability " << fmt("%.4g", g.before.stability_dph) << " -> "
		   << fmt("%.4g", g.after.stability_dph) << " deg/h; range " << fmt("%.4g", g.before.range_dph) << " -> "
		   << fmt("%.4g", g.after.range_dph) << " deg/h\n";
	};
	gapLine(rep.gap);
	if (rep.has_confirm) gapLine(rep.gap_confirm);
	if (rep.has_confirm && !rep.gap_confirm.validity_note.empty()) os << "  (" << rep.gap_confirm.validity_note << ")\n";
	os << "Noise model: ARMA(" << sel.ar.order() << ",1) theta " << fmt("%.2f", sel.ar.theta) << ", long-run factor "
	   << fmt("%.2f", sel.lrv_factor) << ", " << sel.outliers << " outlier(s) excluded\n";
	return os.str();
}

void saveGapPlot(const RunGap& g, const std::string& path, const std::string& title)
{
	PlotCanvas fig(1200, 800);
	auto& top = fig.addPanel(1.0);
	auto& bottom = fig.addPanel(1.0);
	top.title = title + ": residual before (" + g.label + ")";
	bottom.title = "after adding the named effect(s)";
	for (auto* p : {&top, &bottom})
	{
		p->x_axis.label = "time [s]";
		p->y_axis.label = "residual [deg/h]";
		for (const auto& s : g.segments)
			if (s.flagged) p->addShade(s.segment.t_start_s, s.segment.t_end_s, cv::Scalar(160, 200, 255));
	}
	// same y limits on both panels so the reduction is visible
	double lo = 0, hi = 0;
	for (double v : g.residual_before_dph)
		if (std::isfinite(v))
		{
			lo = std::min(lo, v);
			hi = std::max(hi, v);
		}
	const double pad = 0.05 * std::max(hi - lo, 1e-3);
	for (auto* p : {&top, &bottom})
	{
		p->y_axis.min = lo - pad;
		p->y_axis.max = hi + pad;
	}
	PlotSeries b{"before", g.time_s, g.residual_before_dph};
	b.colour = plot_colour::kRed;
	top.addSeries(b);
	PlotSeries a{"after", g.time_s, g.residual_after_dph};
	a.colour = plot_colour::kBlue;
	bottom.addSeries(a);
	fig.save(path);
}

}  // namespace mrpt_fog::discrepancy
