/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/AnalysisTimescale.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/discrepancy/DiscrepancyAnalysis.h>
#include <mrpt_fog/discrepancy/EffectSelector.h>
#include <mrpt_fog/discrepancy/RunGapFigures.h>
#include <mrpt_fog/metrics/BiasMetrics.h>

#include <algorithm>
#include <map>
#include <cmath>
#include <optional>
#include <cstdio>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
using mrpt_fog::units::kNaN;

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
	const double quantum =
		opt.thermistor_quantum_C > 0 ? opt.thermistor_quantum_C : (steps.size() >= 20 ? percentile(steps, 0.05) : 0.0);
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

namespace
{
/** True when two runs hold the same samples (times, rates and temperatures). */
bool sameSamples(const FogSeries& a, const FogSeries& b)
{
	auto same = [](const std::vector<double>& x, const std::vector<double>& y) {
		if (x.size() != y.size()) return false;
		for (std::size_t k = 0; k < x.size(); ++k)
			if (!(x[k] == y[k] || (std::isnan(x[k]) && std::isnan(y[k])))) return false;
		return true;
	};
	if (!same(a.time_s, b.time_s) || a.temp_C.size() != b.temp_C.size()) return false;
	for (int ax = 0; ax < 3; ++ax)
		if (!same(a.rate_dph[ax], b.rate_dph[ax])) return false;
	for (std::size_t i = 0; i < a.temp_C.size(); ++i)
		if (!same(a.temp_C[i], b.temp_C[i])) return false;
	return true;
}

/** Runs f; an std::invalid_argument it throws is re-thrown with the run's label in front. */
template <class F>
auto aboutRun(const std::string& label, F&& f)
{
	try
	{
		return f();
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(label + ": " + e.what());
	}
}
}  // namespace

namespace
{
/** Residual structure left after the named effects that reproduces on the confirmation run:
 * a segment group (type, direction, temperature band) whose RMS is at least flag_rms_ratio x
 * its run's on BOTH runs, over at least 2 % of each run's time; with the temperature range it
 * covers and the candidate closest to explaining it (the last round's largest chi-square). */
std::vector<DiscrepancyReport::Unexplained> unexplainedStructure(const DiscrepancyReport& rep,
																 const std::vector<Segment>& segs1, const RunSignals& sig1,
																 const std::vector<Segment>& segs2,
																 const Eigen::VectorXd& residual2,
																 const std::vector<unsigned char>& rows2,
																 const DiscrepancyOptions& opt)
{
	std::vector<DiscrepancyReport::Unexplained> out;
	const auto r1 = rankSegments(segs1, rep.selection.residual_after, rep.selection.fit_rows);
	const auto r2 = rankSegments(segs2, residual2, rows2);
	std::string closest;
	double closestChi2 = 0, closestP = 1;
	if (!rep.selection.rounds.empty())
		for (const auto& t : rep.selection.rounds.back())
			if (t.status == CandidateStatus::Tested && t.dof > 0 && t.chi2 / t.dof > closestChi2)
			{
				closestChi2 = t.chi2 / t.dof;
				closest = t.id;
				closestP = t.p_adjusted;
			}
	for (const auto& g1 : r1.groups)
	{
		if (!(g1.rms_dph >= opt.flag_rms_ratio * r1.run_rms_dph) || g1.time_share < 0.02) continue;
		for (const auto& g2 : r2.groups)
			if (g2.description == g1.description && g2.rms_dph >= opt.flag_rms_ratio * r2.run_rms_dph &&
				g2.time_share >= 0.02)
			{
				DiscrepancyReport::Unexplained u;
				u.where = g1.description;
				u.rms_dph = g1.rms_dph;
				u.ratio = g1.rms_dph / r1.run_rms_dph;
				u.rms_confirm_dph = g2.rms_dph;
				u.ratio_confirm = g2.rms_dph / r2.run_rms_dph;
				u.time_share = g1.time_share;
				u.temp_low_C = INFINITY;
				u.temp_high_C = -INFINITY;
				// the temperatures the group's segments cover (a segment describes itself in the
				// singular, "cooling ramp below 0 C"; its group in the plural, "cooling ramps ...")
				for (const auto& sg : segs1)
				{
					const std::string d = sg.describe();
					if (sg.band.empty() || d.size() <= sg.band.size() || g1.description.size() <= sg.band.size() ||
						g1.description.compare(g1.description.size() - sg.band.size(), sg.band.size(), sg.band) != 0)
						continue;
					const std::string kind = d.substr(0, d.size() - sg.band.size());
					const std::string groupKind = g1.description.substr(0, g1.description.size() - sg.band.size());
					if (groupKind.rfind(kind.substr(0, kind.size() - 1), 0) != 0 || groupKind.size() > kind.size() + 2)
						continue;
					for (std::size_t k = sg.begin; k < sg.end && k < sig1.size(); ++k)
						if (rep.selection.fit_rows[k])
						{
							u.temp_low_C = std::min(u.temp_low_C, sig1.temp_mean_C[k]);
							u.temp_high_C = std::max(u.temp_high_C, sig1.temp_mean_C[k]);
						}
				}
				u.closest_candidate = closest;
				u.closest_chi2_per_dof = closestChi2;
				u.closest_p_adjusted = closestP;
				out.push_back(u);
			}
	}
	return out;
}

/** The selected effects whose fitted contribution on the analysed run spans more than the raw
 * bias range there (a fit that cancels against the base model's own terms): id, reason. */
std::vector<std::pair<std::string, std::string>> implausibleFits(const SelectionResult& sel, const RunSignals& sig1,
																  const BaseDesign& base1)
{
	std::vector<std::pair<std::string, std::string>> out;
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
	for (const auto& term : sel.model.effects)
	{
		const Eigen::Index q = candidateById(term.id).build(ctx, term.theta).cols();
		if (col + q <= X.cols() && col + q <= sel.coef_after.size())
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
				out.emplace_back(term.id, buf);
			}
		}
		col += q;
	}
	return out;
}
}  // namespace

DiscrepancyReport analyseDiscrepancy(const std::vector<FogSeries>& given_runs, const std::vector<std::string>& labels,
									 const std::string& model, const DiscrepancyOptions& opt)
{
	if (given_runs.empty()) throw std::invalid_argument("no measured run given");
	if (given_runs.size() > 2)
		throw std::invalid_argument("at most two measured runs: the first is analysed, the second confirms");
	DiscrepancyReport rep;
	rep.model_source = model;
	rep.tau_s = opt.tau_s;
	for (std::size_t i = 0; i < given_runs.size(); ++i)
		rep.run_labels.push_back(i < labels.size() ? labels[i] : "run " + std::to_string(i + 1));
	if (given_runs.size() == 2 && !given_runs[0].sameLayout(given_runs[1]))
		throw std::invalid_argument(rep.run_labels[1] + ": the confirmation run has a different thermistor/axis layout "
									"from the first run");
	if (given_runs.size() == 2 && sameSamples(given_runs[0], given_runs[1]))
		throw std::invalid_argument(rep.run_labels[1] + ": the confirmation run holds the same samples as the analysed run " +
									rep.run_labels[0] + ": a confirmation needs another run");

	if (given_runs.size() == 2)  // a confirmation run that cannot be analysed at all: say so first, naming it
		aboutRun(rep.run_labels[1], [&] { return computeRunSignals(given_runs[1], opt.signals); });
	BaseModelSpec spec;
	{
		const auto sigGiven = aboutRun(rep.run_labels[0], [&] { return computeRunSignals(given_runs[0], opt.signals); });
		try
		{
			spec = resolveBaseModel(model, given_runs[0], opt.scale_factor);
		}
		catch (const std::invalid_argument& e)
		{
			// the model cannot even be fitted: when the run holds too little information that is
			// the answer ("cannot tell"), otherwise the error stands
			rep.cannot_tell = informationShortfall(sigGiven, given_runs[0], opt);
			if (rep.cannot_tell.empty()) throw std::invalid_argument(rep.run_labels[0] + ": " + e.what());
			rep.cannot_tell += std::string(" (the model cannot be fitted: ") + e.what() + ")";
			return rep;
		}
		// the analysis timescale (AnalysisTimescale.h): from the base residual's white corner, or
		// as requested, within what the model's shortest slope window can serve
		auto sigG = sigGiven;
		const auto baseG = aboutRun(rep.run_labels[0], [&] { return buildBaseDesign(spec, given_runs[0], sigG); });
		restrictToDefinedRows(sigG, baseG);
		const bool readsRate =
			std::any_of(baseG.is_nuisance.begin(), baseG.is_nuisance.end(), [](unsigned char c) { return c != 0; });
		auto& ts = rep.timescale;
		ts.row_period_s = medianRowPeriod_s(given_runs[0]);
		const double window_s = readsRate ? spec.rate_estimator.window_s : opt.signals.derivative_window_s;
		ts.limit_s = window_s / kBlocksPerWindow;
		{
			char buf[200];
			std::snprintf(buf, sizeof buf, "%s of %g s needs at least %g block means",
						  readsRate ? "the calibration's causal rate window" : "the analysis' derivative window", window_s,
						  kBlocksPerWindow);
			ts.limit_reason = buf;
		}
		if (opt.analysis_block_s > 0)
		{
			if (opt.analysis_block_s > ts.limit_s * (1 + 1e-9))
			{
				char buf[400];
				std::snprintf(buf, sizeof buf,
							  "a block of %g s is longer than this model can be analysed at: %s (longest block %g s); "
							  "use a block of at most %g s, or a calibration with a longer rate window",
							  opt.analysis_block_s, ts.limit_reason.c_str(), ts.limit_s, ts.limit_s);
				throw std::invalid_argument(buf);
			}
			ts.block_s = std::max(opt.analysis_block_s, ts.row_period_s);
		}
		else if (opt.analysis_block_s == 0)
		{
			const Eigen::VectorXd coef = coefficientsOnRows(baseG.X, sigG, sigG.usable);
			const Eigen::VectorXd res = residualWithCoefficients(baseG.X, sigG, coef);
			ts.white_corner_s = whiteNoiseCorner_s(masked(res, sigG.usable), ts.row_period_s);
			const double wanted = std::isfinite(ts.white_corner_s) ? ts.white_corner_s / 4.0 : ts.limit_s;
			ts.block_s = std::max(ts.row_period_s, std::min(wanted, ts.limit_s));
			ts.from_data = true;
		}
		else
			ts.block_s = ts.row_period_s;
	}
	// the rows analysed: block means of the chosen length (a confirmation run too short for
	// them keeps its rows: it is judged with its own noise model either way)
	std::vector<FogSeries> coarse;
	const bool merge = rep.timescale.row_period_s > 0 &&
					   std::floor(rep.timescale.block_s / rep.timescale.row_period_s + 1e-9) >= 2;
	if (merge)
		for (const auto& r : given_runs)
		{
			coarse.push_back(blockMeansOfRows(r, rep.timescale.block_s));
			if (coarse.size() == 2 && coarse.back().size() < 64) coarse.back() = r;
		}
	const std::vector<FogSeries>& runs = merge ? coarse : given_runs;
	DiscrepancyOptions optRows = opt;
	if (merge && optRows.thermistor_quantum_C <= 0)
	{
		// the quantum as the given rows show it (block means step by fractions of it)
		std::vector<double> steps;
		for (const auto& col : given_runs[0].temp_C)
			for (std::size_t k = 1; k < col.size(); ++k)
			{
				const double d = std::fabs(col[k] - col[k - 1]);
				if (std::isfinite(d) && d > 0) steps.push_back(d);
			}
		if (steps.size() >= 20) optRows.thermistor_quantum_C = percentile(steps, 0.05);
	}

	auto sig1 = aboutRun(rep.run_labels[0], [&] { return computeRunSignals(runs[0], opt.signals); });
	const auto base1 = aboutRun(rep.run_labels[0], [&] { return buildBaseDesign(spec, runs[0], sig1); });
	restrictToDefinedRows(sig1, base1);  // the calibration's rate estimator still filling its window
	rep.base_terms = base1.names;
	rep.selection = aboutRun(rep.run_labels[0], [&] { return selectMissingEffects(sig1, base1, opt.selection); });
	rep.cannot_tell = informationShortfall(sig1, runs[0], optRows);
	// An implausible fit (the rail below) is never named, and while it is in the model its
	// columns take part of what the other candidates would explain: the selection is redone
	// without it (at most twice), and it is reported with its reason.
	if (rep.cannot_tell.empty())
	{
		SelectionOptions without = opt.selection;
		for (int again = 0; again < 2; ++again)
		{
			const auto implausible = implausibleFits(rep.selection, sig1, base1);
			if (implausible.empty()) break;
			for (const auto& [id, why] : implausible)
			{
				without.left_out.push_back(id);
				rep.rejected.push_back({id, why});
			}
			rep.selection =
				aboutRun(rep.run_labels[0], [&] { return selectMissingEffects(sig1, base1, without); });
		}
	}
	// slow wander: with one run it ends in "cannot tell"; with a confirmation run an effect that
	// the other run (its own, independent wander) confirms and that passes the held-out rail
	// there is not a drift of the analysed run: only the effects the other run cannot show are
	// held back, and the wander is stated as a note
	std::string wander;
	if (rep.cannot_tell.empty() && !rep.selection.named.empty() && !rep.selection.ar_after.phi.empty())
	{
		// slow bias wander: a run a few correlation times long cannot tell a drift from an effect.
		// Judged on what is left AFTER the named effects (their GLS noise model): the first
		// round's residual still holds the very effects being named, whose slow signatures
		// (e.g. a scale-factor excursion over a rate-table segment) would read as wander.
		const double phi = rep.selection.ar_after.phi.front();
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
				wander = buf;
				if (runs.size() < 2) rep.cannot_tell = wander;
			}
		}
	}
	std::optional<RunSignals> sig2;
	std::optional<BaseDesign> base2;
	if (runs.size() == 2)
	{
		aboutRun(rep.run_labels[1], [&] {
			sig2 = computeRunSignals(runs[1], opt.signals);
			base2 = buildBaseDesign(spec, runs[1], *sig2);
			restrictToDefinedRows(*sig2, *base2);
			if (sig2->usableCount() == 0)
				throw std::invalid_argument("no usable row (the model's rate estimator has no estimate on this run)");
			confirmOnRun(rep.selection, *sig2, *base2, opt.selection);
			return 0;
		});
	}
	// Guard rails (after confirmation): an effect is not named when the data cannot answer,
	// when its fitted contribution is larger than the raw bias range, or when its 95 %
	// interval includes zero; it is then refitted away like an unconfirmed one.
	{
		auto& sel = rep.selection;
		const auto implausible = implausibleFits(sel, sig1, base1);
		const auto ctx = makeCandidateContext(sig1, base1, sel.model.lag_base_coef);
		std::vector<std::pair<std::string, std::string>> reasons;
		for (const auto& term : sel.model.effects)
		{
			const Eigen::Index q = candidateById(term.id).build(ctx, term.theta).cols();
			std::string reason;
			if (!rep.cannot_tell.empty()) reason = "cannot tell: " + rep.cannot_tell;
			else if (!wander.empty())
			{
				for (const auto& ne : sel.named)
					if (ne.id == term.id && !(ne.confirm_tested && ne.confirmed))
						reason = "cannot tell: " + wander + ", and the confirmation run cannot show it";
			}
			else
			{
				for (const auto& [id, why] : implausible)
					if (id == term.id) reason = why;
			}
			// zero not excluded at 95 %: one column, its interval; several, their joint test (an
			// interval on the RMS of the terms is bounded by zero and is no test of it)
			if (reason.empty())
			{
				for (const auto& ne : sel.named)
				{
					if (ne.id == term.id && q == 1 && ne.ci_low <= 0 && ne.ci_high >= 0)
						reason = "its 95 % interval includes zero";
					else if (ne.id == term.id && q > 1 && !(ne.zero_p < 0.05))
					{
						char buf[160];
						std::snprintf(buf, sizeof buf,
									  "its %d terms are not jointly different from zero at 95 %% (Wald p %.2g)",
									  static_cast<int>(q), ne.zero_p);
						reason = buf;
					}
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
		// Held out (needs the confirmation run): with the coefficients fitted on the analysed
		// run, each effect must shrink the OTHER run's residual, and by a size worth naming: its
		// held-out part (the drop of the residual's mean square) must be at least
		// min_held_out_effect_ratio^2 x the mean square left with it. A slowly varying regressor
		// fitted to slow bias wander, or to what a noisy rate column leaves, can pass both
		// significance tests (whitened, they weigh the fast part of the residual) and still not
		// generalise. Checked on the set of effects still named, one rejection at a time (the
		// worst first), since effects in one set share what they explain.
		if (sig2 && rep.cannot_tell.empty())
		{
			keepConfirmedEffects(sel, sig1, base1);
			auto fitOnRun1 = [&](const Eigen::MatrixXd& X1) { return coefficientsOnRows(X1, sig1, sel.fit_rows); };
			// what a user reads on the other run: the spread of its tau-s averages (the "100 s
			// stability"); per-row RMS would be mostly white noise, whatever the rows' length
			auto spread2 = [&](const Eigen::VectorXd& r) {
				const double st = gapFigures(sig2->time_s, r, sig2->usable, opt.tau_s).stability_dph;
				return st * st;
			};
			// an effect the other run cannot show (confirmOnRun: confirm_cannot_tell) is not
			// judged on it either
			auto heldOutTestable = [&](const std::string& id) {
				for (const auto& ne : sel.named)
					if (ne.id == id) return ne.confirm_tested;
				return true;
			};
			const double rmin2 = opt.min_held_out_effect_ratio * opt.min_held_out_effect_ratio;
			// rank in the forward selection (named is "strongest first"): an effect moved into
			// another's held-out alias group lends the group its rank, so that a group whose
			// member was named first is not listed after effects named later, given that member
			std::map<std::string, std::size_t> rankOf;
			for (std::size_t i = 0; i < sel.named.size(); ++i) rankOf[sel.named[i].id] = i;
			while (!sel.model.effects.empty())
			{
				const Eigen::VectorXd coefWith = fitOnRun1(sel.model.design(base1, sig1));
				const double with2 = spread2(residualWithCoefficients(sel.model.design(*base2, *sig2), *sig2, coefWith));
				if (!std::isfinite(with2)) break;  // fewer than two tau-s windows: the rail cannot judge
				std::string worstId, worstWhy;
				double worstRatio = INFINITY;
				// held-out residual mean square without the listed effects (coefficients from run 1)
				auto heldOutWithout2 = [&](const std::vector<std::string>& ids) {
					AugmentedModel without = sel.model;
					without.effects.erase(std::remove_if(without.effects.begin(), without.effects.end(),
														 [&](const EffectTerm& t) {
															 return std::find(ids.begin(), ids.end(), t.id) != ids.end();
														 }),
										  without.effects.end());
					const Eigen::VectorXd coefWithout = fitOnRun1(without.design(base1, sig1));
					return spread2(residualWithCoefficients(without.design(*base2, *sig2), *sig2, coefWithout));
				};
				std::map<std::string, double> ratioOf;
				for (const auto& term : sel.model.effects)
				{
					if (!heldOutTestable(term.id)) continue;
					const double without2 = heldOutWithout2({term.id});
					const double ratio2 = with2 > 0 ? (without2 - with2) / with2 : INFINITY;
					ratioOf[term.id] = ratio2;
					if (ratio2 >= rmin2 || ratio2 >= worstRatio) continue;
					worstRatio = ratio2;
					worstId = term.id;
					char buf[300];
					if (without2 <= with2)
						std::snprintf(buf, sizeof buf,
									  "held out: with its coefficient from the analysed run it does not shrink the other "
									  "run's %g s stability (%.4g without, %.4g with, deg/h)",
									  opt.tau_s, std::sqrt(without2), std::sqrt(with2));
					else
						std::snprintf(buf, sizeof buf,
									  "held out: with its coefficient from the analysed run it explains %.2g x the %g s "
									  "stability left on the other run (%.4g without, %.4g with, deg/h), below the %.2g "
									  "worth naming",
									  std::sqrt(ratio2), opt.tau_s, std::sqrt(without2), std::sqrt(with2),
									  opt.min_held_out_effect_ratio);
					worstWhy = buf;
				}
				if (worstId.empty()) break;
				// held-out alias: another named effect B that the other run cannot tell from this
				// one either (B's own held-out part beyond it is also below the rail) while the
				// two together are worth naming: the rejected one joins B's alias group
				for (const auto& term : sel.model.effects)
				{
					if (term.id == worstId || !ratioOf.count(term.id) || !(ratioOf[term.id] < rmin2)) continue;
					const double pair2 = with2 > 0 ? (heldOutWithout2({term.id, worstId}) - with2) / with2 : 0.0;
					if (!(pair2 >= rmin2)) continue;
					for (auto& ne : sel.named)
						if (ne.id == term.id &&
							std::find(ne.alias_group.begin(), ne.alias_group.end(), worstId) == ne.alias_group.end())
						{
							ne.alias_group.push_back(worstId);
							ne.separating_profiles.push_back(separationAdvice(ne.id, worstId));
							double theta = 0.0;
							for (const auto& t : sel.model.effects)
								if (t.id == worstId) theta = t.theta;
							ne.alias_theta.push_back(theta);
							ne.alias_sign.push_back(0);
							rankOf[ne.id] = std::min(rankOf[ne.id], rankOf[worstId]);
						}
					char buf[300];
					std::snprintf(buf, sizeof buf,
								  "; the other run cannot tell it from %s (each explains %.2g and %.2g x the RMS left "
								  "beyond the other, together %.2g): in %s's alias group",
								  term.id.c_str(), std::sqrt(std::max(0.0, worstRatio)),
								  std::sqrt(std::max(0.0, ratioOf[term.id])), std::sqrt(pair2), term.id.c_str());
					worstWhy += buf;
					break;
				}
				for (auto& ne : sel.named)
					if (ne.id == worstId)
					{
						ne.confirm_tested = true;
						ne.confirmed = false;
					}
				keepConfirmedEffects(sel, sig1, base1);
				sel.not_confirmed.erase(std::remove_if(sel.not_confirmed.begin(), sel.not_confirmed.end(),
													   [&](const NamedEffect& e) { return e.id == worstId; }),
										sel.not_confirmed.end());
				rep.rejected.push_back({worstId, worstWhy});
			}
			std::stable_sort(sel.named.begin(), sel.named.end(), [&](const NamedEffect& a, const NamedEffect& b) {
				return rankOf.at(a.id) < rankOf.at(b.id);
			});
		}
	}
	if (!wander.empty() && rep.cannot_tell.empty())
	{
		if (rep.selection.named.empty()) rep.cannot_tell = wander;
		else
			rep.notes.push_back(wander + "; the effects named were confirmed on " + rep.run_labels[1] +
								" and pass the held-out rail there");
	}
	// the compensator's rate estimate as a gap of its own: the base with and without the
	// "centred minus causal" nuisance columns, fitted on the analysed run, judged on the other
	{
		std::vector<Eigen::Index> keep;
		for (std::size_t c = 0; c < base1.is_nuisance.size(); ++c)
			if (!base1.is_nuisance[c]) keep.push_back(static_cast<Eigen::Index>(c));
		if (keep.size() < base1.is_nuisance.size())
		{
			const RunSignals& sigJ = sig2 ? *sig2 : sig1;
			const BaseDesign& baseJ = sig2 ? *base2 : base1;
			auto columns = [&](const Eigen::MatrixXd& X) {
				Eigen::MatrixXd K(X.rows(), static_cast<Eigen::Index>(keep.size()));
				for (std::size_t i = 0; i < keep.size(); ++i) K.col(static_cast<Eigen::Index>(i)) = X.col(keep[i]);
				return K;
			};
			auto rmsOn = [&](const Eigen::MatrixXd& X1, const Eigen::MatrixXd& XJ) {
				const Eigen::VectorXd coef = coefficientsOnRows(X1, sig1, rep.selection.fit_rows);
				const Eigen::VectorXd res = residualWithCoefficients(XJ, sigJ, coef);
				const double m = static_cast<double>(std::max<std::size_t>(sigJ.usableCount(), 1));
				return std::sqrt(res.squaredNorm() / m);
			};
			auto& g = rep.rate_estimator_gap;
			g.tested = true;
			g.run_label = rep.run_labels[sig2 ? 1 : 0];
			g.rms_causal_dph = rmsOn(columns(base1.X), columns(baseJ.X));
			g.rms_centred_dph = rmsOn(base1.X, baseJ.X);
			const double c2 = g.rms_causal_dph * g.rms_causal_dph, e2 = g.rms_centred_dph * g.rms_centred_dph;
			g.ratio = e2 > 0 && c2 > e2 ? std::sqrt((c2 - e2) / e2) : 0.0;
			g.material = g.ratio >= opt.min_held_out_effect_ratio;
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
		const auto segs2 = segmentRun(*sig2, opt.segmentation);
		rep.gap_confirm = makeRunGap(rep.run_labels[1], *sig2, segs2, rb, ra, rows2, opt);
		if (rep.cannot_tell.empty())
			rep.unexplained = unexplainedStructure(rep, segmentRun(sig1, opt.segmentation), sig1, segs2, ra, rows2, opt);
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

}  // namespace mrpt_fog::discrepancy
