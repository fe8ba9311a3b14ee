/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file DiscrepancyOptions.h
 * Options of the model-gap workflow (analyseDiscrepancy, DiscrepancyAnalysis.h): how the run's
 * signals are derived, how it is segmented, how missing effects are selected, and the
 * information needed before anything is named. Public API.
 */

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct RunSignalsOptions
{
	/** Width of the local linear fit used for temperature derivatives [s]. */
	double derivative_window_s = 120.0;
	/** Longest thermistor dropout bridged by interpolation [s]. */
	double max_dropout_bridge_s = 300.0;
};


struct SegmentationOptions
{
	double moving_rate_Cpm = 0.05;
	double ramp_plateau_s = 600.0;  //!< a ramp holds >= 0.8 x its peak rate this long
	double power_on_transient_s = 1800.0;
	double table_threshold_dph = 1.0;
	double field_threshold_uT = 1.0;
	double min_segment_s = 180.0;
};


struct SelectionOptions
{
	/** Family-wise significance level (Holm over candidates). 0.005, not 0.01: with the noise
	 * model estimated from the same run the null chi-squares come out ~1.1-1.2x nominal, and at
	 * 0.01 the false-naming rate on 200 null trials was 2.5 % (target <= 2 %). */
	double alpha = 0.005;
	double alias_alpha = 0.01;  //!< conditional-test level for "distinguishable"
	/** Shape reproduction (whitened, model projected out; see step 5) at or above which a
	 * candidate is an alias of the named one whatever the significance. */
	double alias_collinearity = 0.95;
	int max_effects = 3;
	int max_ar_order = 3;
	double span_tolerance = 1e-3;  //!< relative projection residual below which "spanned"
	double outlier_sigma = 6.0;
	int lrv_max_lag = 30;  //!< Bartlett window of the long-run variance factor [samples]
	/** Candidate ids to consider (empty = every bias-channel candidate). */
	std::vector<std::string> candidates;
	/** Candidate ids left out of the selection (the analysis leaves out a candidate whose fit
	 * was implausible, so that it does not hide the others). */
	std::vector<std::string> left_out;
};


/** Whether a preset's calibration fits the scale factor versus temperature from the run's
 * table segments (fog-calibrate --scale-factor auto|off). */
enum class ScaleFactorFitting : unsigned char
{
	Auto = 0,  //!< as fog-calibrate by default: table samples serve the scale-factor fit
	Off = 1  //!< fog-calibrate --scale-factor off: a bias-only calibration (table rate subtracted)
};


struct DiscrepancyOptions
{
	SelectionOptions selection;
	SegmentationOptions segmentation;
	RunSignalsOptions signals;
	double tau_s = 100.0;  //!< averaging time of the stability / range figures [s]
	/** Length of the block means the runs are analysed at [s]. 0: chosen from the analysed
	 * run's noise (a quarter of the tau where the Allan deviation of the base model's residual
	 * stops falling as white noise), within what the model can serve; > 0: at least this long
	 * (shorter rows are merged into blocks; a block longer than the model can serve is refused
	 * with the limit stated, std::invalid_argument); < 0: the rows as given. The longest block
	 * the model can serve: its causal rate window (or, without rate terms, the derivative
	 * window) / 4. */
	double analysis_block_s = 0.0;
	/** A preset's calibration: scale factor versus temperature fitted from table segments (as
	 * fog-calibrate) or not (--scale-factor off). Ignored for a calibration YAML. */
	ScaleFactorFitting scale_factor = ScaleFactorFitting::Auto;
	// Information needed before anything is named ("cannot tell" otherwise):
	double min_usable_s = 3600.0;  //!< usable (powered, thermistors known) time on the analysed run [s]
	double min_temp_span_C = 3.0;  //!< span (1st..99th percentile) of the mean temperature [degC]
	double min_span_quanta = 30.0;  //!< that span in thermistor quanta (coarse quantisation)
	/** > 0: the thermistors' quantum from the raw readings [degC], used instead of the steps
	 * between the analysed run's rows; set when the run was reduced to block means
	 * (io/BlockMeanReader.h: BlockMeanInfo::thermistor_step_p05_C), whose steps are fractions
	 * of it. */
	double thermistor_quantum_C = 0.0;
	double min_wander_spans = 5.0;  //!< run length in correlation times of the residual's AR(1) part
	double flag_rms_ratio = 1.5;  //!< a segment is flagged when its RMS >= this x the run's
	/** With a confirmation run, an effect is named only when, with its coefficient from the
	 * analysed run, it explains on the other run at least this x the RMS left there (the drop of
	 * the residual's mean square >= this^2 x what remains): the smallest effect worth naming,
	 * half the weakest effect-to-noise ratio the workflow is specified for, which is 1.
	 * Smaller held-out parts may be real, but they are what slow bias wander, or the part of a
	 * term a noisy rate estimate misses, leave behind. */
	double min_held_out_effect_ratio = 0.5;
};


}  // namespace mrpt_fog::discrepancy
