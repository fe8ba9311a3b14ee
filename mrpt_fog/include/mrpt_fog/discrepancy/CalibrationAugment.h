/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CalibrationAugment.h
 * Closing the loop (fog-discrepancy --write-cal): the calibration under test, plus the named
 * and confirmed effects that the compensator can run, refitted on the analysed run by the
 * calibration code (fitCalibration), and the gap before/after measured on the confirmation run
 * through the compensator (evaluateCalibration: exactly what fog-compensate computes, the
 * run's applied field fed to a magnetic section).
 *
 * Effect -> compensator terms (thermal terms as extra bias terms, model/ThermalFeatureSet.h;
 * IN = first inner thermistor, OUT = first outer one, S = the thermistor of the base's
 * temperature polynomial of order p):
 *   radial_gradient  dT(IN-OUT)^1, and dT(OUT-OTHER)^1 when a thermistor is on neither side
 *                    (OTHER = the first such; the candidate's second column)
 *   gradient_rate    d/dt dT(IN-OUT)^1; named through a lag tau: dTlag/dt(IN,tau)^1 and dTlag/dt(OUT,tau)^1
 *   shupe_rate       dT/dt(IN)^1 and d/dt dT(IN-OUT)^1 (without an OUT: dT/dt(S)^1)
 *   temp_poly_order  T(S)^(p+1), T(S)^(p+2) (at most 5)
 *   hysteresis       hyst(S,play,wC)^1 or hyst(S,branch,wC)^1: the named shape and width
 *                    (CandidateEffect.h hysteresisShapeOf) as the compensator's operator on S's
 *                    reading (model/HysteresisFilter.h; the branch behind its 0.05 C dead band);
 *                    the calibration file is then version 3; a rate shape (tanh or sign of
 *                    the rate) is not written (no compensator operator): listed in not_written
 *   warmup           the calibration's (v2) warm-up term: amplitude and tau as named, when the
 *                    analysed run starts with the gyro off; when it starts powered (its first
 *                    turn-on unknown) but holds turn-ons, amplitude and tau fitted on those
 *                    turn-ons by the calibration's own fit (WarmupFit.h) after the bias
 *   scale_factor_temp the scale factor versus temperature refitted by the calibration's own
 *                    fit (ScaleFactorFit.h: table segments of the analysed run,
 *                    thermistor and order >= 1 chosen by leave-one-temperature-out error:
 *                    the naming has established a dependence) after the bias; when that fit
 *                    refuses (e.g. fewer than 3 soaks), it is listed as not written
 *   magnetic         the calibration's (v3) magnetic section, bias += dph_per_uT x field_uT:
 *                    refitted on the analysed run (MagneticFit.h), not taken from the analysis
 *                    or the confirmation run: the residual of the augmented calibration (thermal
 *                    terms above refitted) through the compensator, over the powered samples
 *                    with a field and no table rate, regressed by generalised least squares
 *                    on field_uT and a slow piecewise-linear drift (knots every shortest
 *                    constant-field stretch; ARMA(1,1) noise by REML, whitened; standard error
 *                    times the Bartlett long-run variance factor); not written when the run's
 *                    field does not vary (or it has no field column)
 * Effects without a compensator term (thermistor_lag) are listed in `not_written`
 * with the reason.
 * The base calibration: the YAML given, or fitCalibration(run, preset) with default options
 * (what fog-calibrate writes). The augmented one: the base's selected terms plus the added
 * ones, fitted by plain least squares on the same run (selection "none": the named terms are
 * kept), same rate estimator and extrapolation, table samples left out when the run has table
 * rates (as fog-calibrate does). Exception: when an added term reads a rate (gradient_rate,
 * shupe_rate), the causal rate window is chosen among 1, 2 and 4 x the base's by the refit's
 * residual RMS on the analysed run: the added rate term multiplies the estimate's noise (at 5 s
 * sampling a 60 s order-2 window left a d(Ca - Cb)/dt term noisier than the gap it closes).
 */

#include <mrpt_fog/discrepancy/DiscrepancyOptions.h>
#include <mrpt_fog/discrepancy/SelectionResult.h>
#include <mrpt_fog/model/Calibration.h>

#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** When an added term reads a rate: the causal rate window chosen among 1, 2 and 4 x the
 * base's by the refit's residual RMS on the analysed run (with the added terms). */
struct RateWindowChoice
{
	bool changed = false;  //!< a longer window than the base's was chosen (AugmentedCalibration::augmented's)
	double rms_dph = 0.0;  //!< analysed-run RMS on the chosen window
	double base_window_rms_dph = 0.0;  //!< analysed-run RMS on the base's window
};

struct AugmentedCalibration
{
	Calibration base;  //!< the calibration under test
	Calibration augmented;  //!< base + added terms (== base when nothing could be added)
	/** Names of the terms added (feature-set term names), and "warmup(amplitude_dph, tau_s)" for
	 * the warm-up term. */
	std::vector<std::string> added_terms;
	/** The scale factor versus temperature was refitted and added (augmented.scale_factor, of
	 * order >= 1). */
	bool scale_factor_added = false;
	/** The magnetic sensitivity was refitted and added (augmented.magnetic). */
	bool magnetic_added = false;
	std::vector<std::pair<std::string, std::string>> not_written;  //!< effect id, why
	RateWindowChoice rate_window;
	bool has_confirm = false;
	FitFigures before, after;  //!< confirmation run through the compensator (base / augmented)
};

/** Builds the augmented calibration for the named effects (see file comment). confirm may be
 * null (no before/after figures). Throws std::invalid_argument when the refit fails. */
AugmentedCalibration augmentCalibration(const std::string& preset_or_yaml, const std::vector<NamedEffect>& named,
										const FogSeries& run, const FogSeries* confirm, const std::string& confirm_label,
										ScaleFactorFitting sf = ScaleFactorFitting::Auto);

}  // namespace mrpt_fog::discrepancy
