/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file WarmupFit.h
 * Fits the turn-on (warm-up) term of WarmupModel.h from static runs that hold a turn-on, on top
 * of a calibration fitted without them (bias, optionally scale factor):
 *
 *  1. Turn-ons: the run's metadata `power_on_time_s` (a turn-on at or before its first sample,
 *     e.g. fog-sim runs that start cold and unpowered) and every 0 -> 1 step of `power`. Each
 *     turn-on's span runs to the next power-off or the end of the run.
 *  2. Residual: the calibration's causal compensated rate (what the real-time compensator
 *     would output without the warm-up term), table-rate samples left out, averaged over
 *     `bin_s` bins.
 *  3. Model per span j: e(t) = c_j + A exp(-(t - t_on,j) / tau), with an offset c_j per turn-on
 *     (the bias model's static error at that run's conditions: not applied by the compensator)
 *     and one (A, tau) for all turn-ons. For each tau the problem is linear; tau is searched on a
 *     log grid from max(min_tau_s, 3 bin_s) to max_tau_fraction x the shortest span and refined
 *     by golden section; a minimum at the edge of the grid, or an amplitude under 3 standard
 *     errors, is refused (no decay resolved).
 *  4. Standard errors of A and tau from the Gauss-Newton covariance, with the residual variance
 *     inflated by (1 + r1) / (1 - r1) (r1: lag-1 autocorrelation of the binned residuals; the
 *     gyro's bias instability makes neighbouring bins correlated).
 *
 * Only the compensated residual is modelled, so what the thermal bias model already explains at
 * a turn-on (the coil warming from the electronics) is not fitted twice; rms_before_dph /
 * rms_after_dph (offsets only / offsets + warm-up, over the fitted spans) show what the term
 * adds beyond it. Throws WarmupFitError (a std::invalid_argument) with the reason when the runs
 * cannot support the fit.
 */

#include <mrpt_fog/model/Calibration.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_fog
{
struct WarmupFitOptions
{
	double bin_s = 10.0;  //!< residual averaging bin [s]
	double min_tau_s = 30.0;  //!< shortest time constant searched [s]
	double max_tau_fraction = 0.5;  //!< longest time constant searched, as a fraction of the shortest span
	double min_span_s = 600.0;  //!< shortest usable span after a turn-on [s]
	/** Exponential terms, 1 or 2 (two time constants: searched on a grid of pairs, refined in
	 * turn; each amplitude must exceed 3 standard errors). selectWarmupTerms() chooses by
	 * held-out error. */
	std::size_t exponentials = 1;
};

/** What the fit saw (for reports and tests). */
struct WarmupFitReport
{
	struct Span
	{
		std::size_t run = 0;
		double t_on_s = 0, t_end_s = 0;  //!< turn-on and end of the span used [s]
		double offset_dph = 0;  //!< fitted c_j (not applied) [deg/h]
		std::size_t bins = 0;
	};
	std::vector<Span> spans;
	double tau_min_s = 0, tau_max_s = 0;  //!< time-constant search range [s]
	double lag1_autocorrelation = 0;  //!< of the binned residuals after the fit
};

class WarmupFitError : public std::invalid_argument
{
   public:
	using std::invalid_argument::invalid_argument;
};

/** Fits the warm-up term of `cal`'s axis from the turn-ons in `runs` (see the file comment).
 * `cal` must have no warm-up term. run_labels name runs in messages. */
WarmupModel fitWarmup(const std::vector<FogSeries>& runs, const Calibration& cal, const WarmupFitOptions& options = {},
					  WarmupFitReport* report = nullptr, const std::vector<std::string>& run_labels = {});

/** How many exponential terms the warm-up runs support, judged held out: each run in turn is
 * left out, the term fitted on the others (1 and 2 exponentials), and the left-out run's binned
 * residual (bin_s bins, each turn-on span about its own mean) scored; the count with the lower
 * pooled RMS wins (ties and a count that cannot be fitted: fewer terms). One run: 1, not judged. */
struct WarmupTermsChoice
{
	std::size_t exponentials = 1;
	bool judged = false;
	double held_out_rms_dph[2] = {0, 0};  //!< for 1 and 2 terms [deg/h] (infinity: not fittable)
	std::string why;  //!< one line for reports
};
WarmupTermsChoice selectWarmupTerms(const std::vector<FogSeries>& runs, const Calibration& cal,
									const WarmupFitOptions& options = {}, const std::vector<std::string>& run_labels = {});

}  // namespace mrpt_fog
