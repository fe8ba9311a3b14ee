/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AllanNoiseTerms.h
 * The IEEE Std 952-1997 (Annex C) noise terms read off an Allan deviation curve of a rate in
 * deg/h, each by a straight line of the term's fixed log-log slope through the part of the curve
 * that has that slope:
 *
 *   term                      AVAR          slope   read at            reported as
 *   quantisation Q            3 Q^2/tau^2   -1      tau = sqrt(3) s    Q [arcsec]
 *   angle random walk N       N^2/tau       -1/2    tau = 1 (s or h)   N [deg/sqrt(h)]
 *   bias instability B        (0.664 B)^2   0       flat part          B = sigma_flat/0.664 [deg/h]
 *   rate random walk K        K^2 tau/3     +1/2    tau = 3 (s or h)   K [deg/h/sqrt(h)]
 *
 * B is the flat level divided by 0.664 = sqrt(2 ln2 / pi), not the minimum of the curve.
 *
 * Bias instability (the flat region): the usable points (at least min_clusters clusters) are
 * fitted jointly by AVAR = c_-2/tau^2 + c_-1/tau + c_0 + c_1 tau with c_k >= 0 (weighted by the
 * clusters, residuals relative to the model: IEEE 952 Annex C's sum-of-terms fit). A flat region
 * exists where c_0 holds at least flat_share (half) of the fitted variance, on at least two curve
 * points; only then is B = sqrt(c_0) / 0.664 reported. The minimum between a -1/2 and a +1/2
 * slope (white noise plus rate random walk, no flicker) is not a flat region: B is NaN there.
 * Subtracting the neighbouring terms, B is not biased high by them as a line through the flat
 * points would be.
 *
 * The other terms, each by a straight line of the term's fixed log-log slope through the part of
 * the curve that has that slope: a point belongs to the term when the mean of the log-log slopes
 * of its neighbouring segments is within slope_tolerance of the term's slope; of the contiguous
 * runs of such points the one with the largest statistical weight (sum of clusters) is fitted,
 * the intercept by weighted least squares in log space with weights equal to the clusters
 * (var(log adev) ~ 1/clusters). Q is looked for only in a run that starts at the shortest usable
 * tau (a -1 slope at long tau, e.g. a slow signal removed by a fit, is not quantisation) and
 * before the flat region; N after Q and before the flat region (a noisy falling tail of a flicker
 * curve is not ARW); K after N and the flat region. A term with no such run is NaN (not
 * identified): e.g. no flat part in a record too short to reach it.
 */

#include <mrpt_fog/metrics/AllanDeviation.h>

#include <cmath>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** One fitted term: a line adev = level_at_1s * tau^slope on [tau_min_s, tau_max_s]. */
struct AllanLineFit
{
	double slope = 0;  //!< fixed log-log slope of the term
	double adev_at_1s_dph = NAN;  //!< the line's value at tau = 1 s [deg/h]; NaN = not identified
	double tau_min_s = NAN, tau_max_s = NAN;  //!< part of the curve used [s]
	std::size_t points = 0;  //!< curve points used

	bool identified() const { return points > 0; }
	/** The line at tau [deg/h] (NaN when not identified). */
	double at(double tau_s) const;
};

/** The IEEE 952 terms of a rate Allan curve in deg/h (see the file comment). NaN = not identified. */
struct AllanNoiseTerms
{
	double quantization_arcsec = NAN;  //!< Q [arcsec] (= line at tau = sqrt(3) s, in deg/h * s)
	double arw_dpsh = NAN;  //!< N [deg/sqrt(h)] (= line at tau = 1 s, in deg/h, / 60)
	double bias_instability_dph = NAN;  //!< B [deg/h] = flat level / 0.664
	double rrw_dphsh = NAN;  //!< K [deg/h/sqrt(h)] (= line at tau = 3 s, in deg/h, * 60)
	AllanLineFit quantization, arw, flat, rrw;  //!< the fitted lines (for plots and reports)
};

struct AllanTermOptions
{
	double slope_tolerance = 0.15;  //!< a point belongs to a term when |slope - term slope| <= this
	std::size_t min_clusters = 8;  //!< points with fewer clusters are not used
	double flat_share = 0.5;  //!< the flat region: where the flat term holds at least this share of the AVAR
};

/** Reads the noise terms from an Allan deviation curve of a rate in deg/h (tau ascending).
 * Never throws; an empty or too short curve gives all terms NaN. */
AllanNoiseTerms allanNoiseTerms(const std::vector<AllanPoint>& curve_dph, const AllanTermOptions& options = {});

/** 0.664 = sqrt(2 ln 2 / pi): flat-region Allan deviation over bias instability B. */
constexpr double kBiasInstabilityFactor = 0.6642824702679332;

}  // namespace mrpt_fog
