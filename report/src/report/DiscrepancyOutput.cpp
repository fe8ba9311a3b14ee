/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/plot/PlotCanvas.h>
#include <mrpt_fog/report/DiscrepancyOutput.h>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mrpt_fog::discrepancy
{
namespace
{
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
	e["direction"] = toString(s.segment.direction);
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
}  // namespace

JsonValue discrepancyJson(const DiscrepancyReport& rep)
{
	const auto& sel = rep.selection;
	JsonValue j = JsonValue::object();
	j["model"] = rep.model_source;
	j["base_terms"] = JsonValue::arrayOf(rep.base_terms);
	j["runs"] = JsonValue::arrayOf(rep.run_labels);
	j["verdict"] = rep.verdict();
	JsonValue named = JsonValue::array();
	for (const auto& ne : sel.named)
	{
		JsonValue e = JsonValue::object();
		e["id"] = ne.id;
		e["alias_group"] = JsonValue::arrayOf(ne.alias_group);
		e["confidence"] = ne.confidence;
		e["group_confidence"] = ne.group_confidence;
		e["coefficient"] = ne.coefficient;
		e["coefficient_unit"] = ne.coefficient_unit;
		e["ci"] = JsonValue::array({ne.ci_low, ne.ci_high});
		if (!ne.theta_name.empty()) e[ne.theta_name] = ne.theta;
		if (!ne.theta_name.empty() && !ne.theta_meaning.empty()) e[ne.theta_name + "_meaning"] = ne.theta_meaning;
		e["chi2"] = ne.chi2;
		e["p_adjusted"] = ne.p_adjusted;
		e["delta_bic"] = ne.delta_bic;
		e["separating_profiles"] = JsonValue::arrayOf(ne.separating_profiles);
		if (ne.confirm_tested)
		{
			e["confirmed"] = ne.confirmed;
			e["confirm_p"] = ne.confirm_p;
			if (ne.confirmed) e["confirmed_by"] = ne.confirmed_by;
		}
		else if (!ne.confirm_cannot_tell.empty())
			e["confirm_cannot_tell"] = ne.confirm_cannot_tell;  // the confirmation run cannot show it
		named.push_back(e);
	}
	j["named_effects"] = named;
	// named on the analysed run, not confirmed on the second run: reported, not added
	j["not_confirmed"] = JsonValue::arrayOf(sel.not_confirmed, [](const auto& ne) {
		return JsonValue::object({{"id", ne.id}, {"p_adjusted", ne.p_adjusted}, {"coefficient", ne.coefficient},
								  {"coefficient_unit", ne.coefficient_unit}, {"confirm_p", ne.confirm_p}});
	});
	j["not_named"] = JsonValue::arrayOf(
		rep.rejected, [](const auto& r) { return JsonValue::object({{"id", r.id}, {"reason", r.reason}}); });
	j["cannot_tell"] = rep.cannot_tell;
	j["notes"] = JsonValue::arrayOf(rep.notes);
	j["unexplained"] = JsonValue::arrayOf(rep.unexplained, [](const auto& u) {
		return JsonValue::object({{"where", u.where},
								  {"temp_low_C", u.temp_low_C},
								  {"temp_high_C", u.temp_high_C},
								  {"rms_dph", u.rms_dph},
								  {"ratio_to_run", u.ratio},
								  {"rms_confirm_dph", u.rms_confirm_dph},
								  {"ratio_to_run_confirm", u.ratio_confirm},
								  {"time_share", u.time_share},
								  {"closest_candidate", u.closest_candidate},
								  {"closest_chi2_per_dof", u.closest_chi2_per_dof},
								  {"closest_p_adjusted", u.closest_p_adjusted}});
	});
	{
		const auto& t = rep.timescale;
		JsonValue ts = JsonValue::object();
		ts["row_period_s"] = t.row_period_s;
		ts["block_s"] = t.block_s;
		ts["limit_s"] = t.limit_s;
		ts["limit_reason"] = t.limit_reason;
		ts["white_corner_s"] = t.white_corner_s;  // null when not reached / not measured
		ts["from_data"] = t.from_data;
		j["analysis_timescale"] = ts;
	}
	if (rep.rate_estimator_gap.tested)
	{
		const auto& g = rep.rate_estimator_gap;
		j["rate_estimator_gap"] = JsonValue::object({{"run", g.run_label},
													  {"rms_causal_dph", g.rms_causal_dph},
													  {"rms_centred_dph", g.rms_centred_dph},
													  {"ratio", g.ratio},
													  {"material", g.material}});
	}
	j["where"] = rep.gap.ranking_before.sentence;
	JsonValue segs = JsonValue::array();
	int rank = 1;
	for (const auto& s : rep.gap.segments) segs.push_back(segmentJson(s, rank++));
	j["segments"] = segs;
	j["segment_groups"] = JsonValue::arrayOf(rep.gap.ranking_before.groups, [](const auto& g) {
		return JsonValue::object({{"description", g.description}, {"rms_dph", g.rms_dph},
								  {"energy_share", g.energy_share}, {"time_share", g.time_share},
								  {"segments", static_cast<unsigned long>(g.segments)}});
	});
	JsonValue cands = JsonValue::array();
	if (!sel.rounds.empty())
		for (const auto& t : sel.rounds.front())
		{
			JsonValue e = JsonValue::object();
			e["id"] = t.id;
			e["status"] = toString(t.status);
			e["note"] = t.note;
			if (t.status == CandidateStatus::Tested)
			{
				e["chi2"] = t.chi2;
				e["dof"] = t.dof;
				e["p_adjusted"] = t.p_adjusted;
				e["delta_bic"] = t.delta_bic;
				e["significant"] = t.significant;
				// how well its columns reproduce the shape of the effect named in this round (alias
				// test; 0 for that effect itself and when nothing was named)
				e["shape_reproduction_of_named"] = t.collinearity_with_best;
			}
			cands.push_back(e);
		}
	j["candidates_first_round"] = cands;
	JsonValue noise = JsonValue::object();
	noise["ar_phi"] = JsonValue::arrayOf(sel.ar.phi);
	noise["ma_theta"] = sel.ar.theta;
	noise["long_run_variance_factor"] = sel.lrv_factor;
	noise["outliers_excluded"] = static_cast<unsigned long>(sel.outliers);
	// the noise model left after the named effects (judges the slow-wander guard rail)
	noise["ar_phi_after_named"] = JsonValue::arrayOf(sel.ar_after.phi);
	noise["ma_theta_after_named"] = sel.ar_after.theta;
	j["noise_model"] = noise;
	if (!sel.rounds.empty())
	{
		JsonValue d = JsonValue::object();
		for (const auto& t : sel.rounds.back())
			if (std::isfinite(t.detectable_rms_dph)) d[t.id] = t.detectable_rms_dph;
		j["detectable_rms_dph"] = d;
	}
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
		os << "  " << i + 1 << ". " << s.segment.describe() << " [" << formatValue("%.0f", s.segment.t_start_s) << ".."
		   << formatValue("%.0f", s.segment.t_end_s) << " s] RMS " << formatValue("%.3g", s.segment.rms_dph) << " -> "
		   << formatValue("%.3g", s.rms_after_dph) << " deg/h, " << formatValue("%.0f", 100 * s.segment.energy_share)
		   << " % of the energy" << (s.flagged ? "  (flagged)" : "") << "\n";
	}
	os << "Verdict: " << rep.verdict() << "\n";
	for (const auto& note : rep.notes) os << "  note: " << note << "\n";
	for (const auto& ne : sel.named)
	{
		os << "  " << ne.id << ": " << candidateDescription(ne.id) << "\n";
		os << "    coefficient " << formatValue("%.4g", ne.coefficient) << " " << ne.coefficient_unit << " (95 % CI "
		   << formatValue("%.4g", ne.ci_low) << " .. " << formatValue("%.4g", ne.ci_high) << ")";
		if (!ne.theta_name.empty())
		{
			os << ", " << ne.theta_name << " = " << formatValue("%g", ne.theta);
			if (!ne.theta_meaning.empty()) os << " (" << ne.theta_meaning << ")";
		}
		os << "; confidence " << formatValue("%.2f", ne.confidence) << ", chi2 " << formatValue("%.1f", ne.chi2) << ", Holm p "
		   << formatValue("%.2g", ne.p_adjusted) << "\n";
		for (std::size_t a = 1; a < ne.alias_group.size(); ++a)
			os << "    alias: " << ne.alias_group[a] << " cannot be told apart on this run; to separate them use "
			   << ne.separating_profiles[a - 1] << "\n";
		if (ne.alias_group.size() > 1)
			os << "    confidence of the alias group: " << formatValue("%.2f", ne.group_confidence) << "\n";
		if (ne.confirm_tested)
			os << "    confirmation run: " << (ne.confirmed ? "confirmed" : "NOT confirmed") << " (p "
			   << formatValue("%.2g", ne.confirm_p)
			   << (ne.confirmed && !ne.confirmed_by.empty() && ne.confirmed_by != ne.id
					   ? ", by its alias " + ne.confirmed_by + ": the group is confirmed, not which member"
					   : std::string())
			   << ")\n";
		else if (!ne.confirm_cannot_tell.empty())
			os << "    confirmation run: cannot tell (" << ne.confirm_cannot_tell << ")\n";
	}
	for (const auto& ne : sel.not_confirmed)
		os << "  not confirmed (named on " << rep.run_labels[0] << ", not added): " << ne.id << ", coefficient "
		   << formatValue("%.4g", ne.coefficient) << " " << ne.coefficient_unit << ", Holm p " << formatValue("%.2g", ne.p_adjusted)
		   << "; on the confirmation run p " << formatValue("%.2g", ne.confirm_p)
		   << (ne.confirm_p < 0.01 ? " with the opposite sign" : "") << "\n";
	for (const auto& r : rep.rejected) os << "  not named: " << r.id << " (" << r.reason << ")\n";
	for (const auto& u : rep.unexplained)
		os << "Unexplained (no candidate explains it; it reproduces on the confirmation run): " << u.where << " ("
		   << formatValue("%.3g", u.temp_low_C) << " .. " << formatValue("%.3g", u.temp_high_C) << " C, "
		   << formatValue("%.0f", 100 * u.time_share) << " % of the time): residual RMS " << formatValue("%.3g", u.rms_dph)
		   << " deg/h, " << formatValue("%.2g", u.ratio) << " x the run's; on the confirmation run "
		   << formatValue("%.3g", u.rms_confirm_dph) << " deg/h, " << formatValue("%.2g", u.ratio_confirm) << " x"
		   << (u.closest_candidate.empty()
				   ? std::string()
				   : "; closest candidate " + u.closest_candidate + " (chi2 per dof " +
						 formatValue("%.3g", u.closest_chi2_per_dof) + ", Holm p " +
						 formatValue("%.2g", u.closest_p_adjusted) + ")")
		   << "\n";
	if (!sel.rounds.empty())
	{
		std::string list;
		for (const auto& t : sel.rounds.back())
			if (std::isfinite(t.detectable_rms_dph))
				list += (list.empty() ? "" : ", ") + t.id + " " + formatValue("%.3g", t.detectable_rms_dph);
		if (!list.empty())
			os << "  cannot tell below (the smallest contribution this run could name, deg/h RMS beyond the model, at its "
				  "noise): "
			   << list << "\n";
	}
	if (rep.rate_estimator_gap.tested && rep.rate_estimator_gap.material)
	{
		const auto& g = rep.rate_estimator_gap;
		os << "Rate estimator (not a physical effect): the model's rate terms on the calibration's causal rate leave RMS "
		   << formatValue("%.4g", g.rms_causal_dph) << " deg/h on " << g.run_label << ", on a centred rate "
		   << formatValue("%.4g", g.rms_centred_dph) << " deg/h (" << formatValue("%.2g", g.ratio)
		   << " x the RMS left): the compensator's rate estimate is a gap of its own, "
			  "not named as an effect\n";
	}
	if (!sel.rounds.empty())
	{
		std::string skipped;
		for (const auto& t : sel.rounds.front())
			if (t.status != CandidateStatus::Tested)
				skipped += "  " + t.id + ": " + toString(t.status) + " (" + t.note + ")\n";
		if (!skipped.empty()) os << "Not tested:\n" << skipped;
	}
	auto gapLine = [&](const RunGap& g)
	{
		os << "Gap on " << g.label << ": RMS " << formatValue("%.4g", g.before.rms_dph) << " -> " << formatValue("%.4g", g.after.rms_dph)
		   << " deg/h; ";
		if (std::isfinite(g.before.stability_dph) && std::isfinite(g.after.stability_dph))
			os << formatValue("%g", rep.tau_s) << " s stability " << formatValue("%.4g", g.before.stability_dph) << " -> "
			   << formatValue("%.4g", g.after.stability_dph) << " deg/h; range " << formatValue("%.4g", g.before.range_dph)
			   << " -> " << formatValue("%.4g", g.after.range_dph) << " deg/h\n";
		else
			os << formatValue("%g", rep.tau_s) << " s stability and range n/a (the run holds fewer than two "
			   << formatValue("%g", rep.tau_s) << " s windows)\n";
	};
	gapLine(rep.gap);
	if (rep.has_confirm) gapLine(rep.gap_confirm);
	if (rep.has_confirm && !rep.gap_confirm.validity_note.empty()) os << "  (" << rep.gap_confirm.validity_note << ")\n";
	{
		const auto& t = rep.timescale;
		if (t.block_s > 0)
		{
			os << "Timescale: block means of " << formatValue("%.3g", t.block_s) << " s (rows given every "
			   << formatValue("%.3g", t.row_period_s) << " s; ";
			if (t.from_data)
				os << (std::isfinite(t.white_corner_s)
						   ? "the base residual's Allan deviation stops falling as white noise at " +
								 formatValue("%.3g", t.white_corner_s) + " s; blocks of a quarter of that"
						   : std::string("white noise to the longest tau measured"))
				   << ", at most " << formatValue("%.3g", t.limit_s) << " s: " << t.limit_reason << ")\n";
			else
				os << "as requested; at most " << formatValue("%.3g", t.limit_s) << " s: " << t.limit_reason << ")\n";
		}
	}
	os << "Noise model: ARMA(" << sel.ar.order() << ",1) theta " << formatValue("%.2f", sel.ar.theta) << ", long-run factor "
	   << formatValue("%.2f", sel.lrv_factor) << ", " << sel.outliers << " outlier(s) excluded\n";
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
