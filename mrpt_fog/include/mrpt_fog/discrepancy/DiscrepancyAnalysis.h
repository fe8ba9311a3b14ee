/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file DiscrepancyAnalysis.h
 * The model-gap workflow end to end (what fog-discrepancy runs): refit the base model on the
 * measured run, locate where the residual is largest (RunSegmenter), name the missing effect(s)
 * (EffectSelector), add them and refit, and show the gap before/after: residual RMS, 100 s
 * stability and range of the residual, per segment, and on the confirmation run (second run,
 * coefficients from the first, only the constant offset re-estimated).
 * Returns data only; fog-discrepancy shows it (report/DiscrepancyOutput.h).
 */

#include <mrpt_fog/discrepancy/DiscrepancyOptions.h>
#include <mrpt_fog/discrepancy/Segments.h>
#include <mrpt_fog/discrepancy/SelectionResult.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <limits>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Residual figures of one run [deg/h]. Stability/range are NaN when the run holds fewer than
 * two tau-s windows. */
struct GapFigures
{
	double rms_dph = 0, stability_dph = 0, range_dph = 0;
	std::size_t samples = 0;
};

struct SegmentGap
{
	Segment segment;  //!< with the BEFORE ranking fields
	double rms_after_dph = 0;
	/** Residual figures over the segment's samples (stability/range NaN below two windows). */
	GapFigures before, after;
	bool flagged = false;
};

struct RunGap
{
	std::string label;
	/** Samples left out of the gap figures because a thermistor was outside the temperature
	 * range the model was fitted on (the model is not valid there; it is never extrapolated). */
	std::size_t outside_model_range = 0;
	std::string validity_note;  //!< "" or which range and how much of the run left it
	GapFigures before, after;
	std::vector<SegmentGap> segments;  //!< ranked by residual energy before
	SegmentRanking ranking_before;
	std::vector<double> time_s;
	std::vector<double> residual_before_dph, residual_after_dph;  //!< NaN where not used
};

struct DiscrepancyReport
{
	std::string model_source;
	std::vector<std::string> base_terms;
	std::vector<std::string> run_labels;
	SelectionResult selection;
	RunGap gap;
	bool has_confirm = false;
	RunGap gap_confirm;
	double tau_s = 100.0;
	/** The timescale the runs were analysed at (DiscrepancyOptions::analysis_block_s). */
	struct Timescale
	{
		double row_period_s = 0;  //!< median step of the rows given [s]
		double block_s = 0;  //!< rows analysed: block means of about this [s] (= row_period_s: as given)
		double limit_s = 0;  //!< longest block the model can serve [s]
		std::string limit_reason;  //!< which window sets limit_s
		/** Where the Allan deviation of the base model's residual stops falling as white noise
		 * [s]; NaN when it does not within the run (or when not measured: block requested). */
		double white_corner_s = std::numeric_limits<double>::quiet_NaN();
		bool from_data = false;  //!< chosen from the white corner (not requested)
	} timescale;
	/** Significant effects NOT named, with the reason: fitted contribution larger than the raw
	 * bias range (implausible), a 95 % interval that includes zero, or too small a held-out part
	 * on the confirmation run (DiscrepancyOptions::min_held_out_effect_ratio). */
	struct Rejected
	{
		std::string id, reason;
	};
	std::vector<Rejected> rejected;
	/** Residual structure that no candidate explained and that reproduces on the confirmation
	 * run: after the named effects, a segment group (type, direction = rate sign, temperature
	 * band) whose residual RMS is at least flag_rms_ratio x its run's on both runs. Reported so
	 * that a shape no candidate has is not met with silence. */
	struct Unexplained
	{
		std::string where;  //!< the segment group, e.g. "cooling ramps between 0 and 20 C"
		double temp_low_C = 0, temp_high_C = 0;  //!< mean thermistor temperature over it (analysed run)
		double rms_dph = 0, ratio = 0;  //!< its residual RMS on the analysed run, and / the run's
		double rms_confirm_dph = 0, ratio_confirm = 0;  //!< the same on the confirmation run
		double time_share = 0;  //!< of the analysed run's usable time
		std::string closest_candidate;  //!< the last round's largest chi-square per dof ("" if none)
		double closest_chi2_per_dof = 0, closest_p_adjusted = 1;
	};
	std::vector<Unexplained> unexplained;
	/** The compensator's rate estimate as a gap of its own (not a physical effect): the model's
	 * rate terms on the calibration's causal rate vs on the analysis' centred rate (the
	 * "centred minus causal" nuisance columns, BaseModelDesign.h), both fitted on the analysed
	 * run, RMS on the confirmation run (on the analysed run without one) [deg/h]. `material`
	 * when the centred rate explains at least min_held_out_effect_ratio x the RMS left (the rail
	 * an effect must pass to be named). Absent (tested false) when the model has no rate term. */
	struct RateEstimatorGap
	{
		bool tested = false, material = false;
		std::string run_label;
		double rms_causal_dph = 0, rms_centred_dph = 0;
		double ratio = 0;  //!< sqrt((causal^2 - centred^2) / centred^2), 0 when not smaller
	} rate_estimator_gap;
	/** Non-empty when the data cannot answer (too short, too narrow a temperature span, too
	 * coarse a quantisation, bias wander too slow for the run): nothing is named, this says why. */
	std::string cannot_tell;
	/** What the reader should know about the verdict (e.g. a slow wander the confirmation run
	 * answered). */
	std::vector<std::string> notes;
	/** "cannot tell: ...", "no missing effect found" or "missing: a, b (strongest first)". */
	std::string verdict() const;
};

/** Runs the workflow. runs[0] is analysed, runs[1] (optional) confirms; more than two runs,
 * an empty list, runs of different layouts, the same samples given as both runs, a block
 * longer than the model can serve, or too few usable samples throw std::invalid_argument (a
 * message about one run starts with that run's label). `model` is a preset or a calibration YAML (BaseModelDesign.h). */
DiscrepancyReport analyseDiscrepancy(const std::vector<FogSeries>& runs, const std::vector<std::string>& run_labels,
									 const std::string& model, const DiscrepancyOptions& opt = {});

}  // namespace mrpt_fog::discrepancy
