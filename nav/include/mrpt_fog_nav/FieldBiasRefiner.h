/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file FieldBiasRefiner.h
 * The in-field stage after the thermal compensation: while the vehicle stands still
 * (StandstillDetector) the compensated rate should read the Earth rate's vertical component;
 * what it reads beyond that updates the bias offset (BiasOffsetFilter), which is subtracted from
 * every later sample. Causal: the correction of a sample at t uses only samples up to
 * t - guard_s, and it is the same whatever order a log interleaves gyro and odometry in.
 *
 * Which samples of a standstill count:
 *  - none of the first guard_s after the vehicle stopped (the end of the deceleration) and none
 *    of the last guard_s before it moved (so a motion the odometry reports a sample late is not
 *    taken for bias);
 *  - none until the standstill has lasted min_still_s AND is long enough to beat the prior:
 *    its white-noise variance over its length, (60 N)^2 / T + B^2 (N: angle random walk,
 *    B: bias instability), must be below the prior's variance. A standstill that cannot beat
 *    the prior changes nothing (counted in shortStandstills()); one that can is weighed by the
 *    filter against what earlier standstills learned.
 * The estimate replaces the prior only once it differs from it by more than significance_sigma
 * (3) of its own 1-sigma: a calibration the standstills do not contradict is left alone, and
 * noise of a few thousandths of a deg/h is not added to a good thermal model. The test looks
 * twice per standstill (when its first min_still_s are in, and at its end), not at every
 * sample: every look is a chance of a false alarm (tests/nav: the rate on 400 runs).
 * A drive without a standstill is passed through unchanged (the prior offset, 0 unless a
 * refined calibration gives one, is what is subtracted: x - 0.0 is x). At a turn-on within the
 * log the gyro picks a new offset: the filter restarts from the prior there. */

#include <mrpt_fog_nav/BiasOffsetFilter.h>
#include <mrpt_fog_nav/StandstillDetector.h>

#include <cstddef>
#include <deque>
#include <limits>
#include <optional>
#include <vector>

namespace mrpt_fog::nav
{
struct FieldRefinementOptions
{
	StandstillOptions standstill;
	GyroNoiseModel noise;
	/** What the gyro reads while still: the Earth rate's component on its axis [deg/h]
	 * (15.041 deg/h x sin(latitude) for a vertical gyro). */
	double expected_rate_dph = 0.0;
	double prior_offset_dph = 0.0;  //!< offset before any standstill [deg/h]
	double prior_sigma_dph = 1.0;  //!< its 1-sigma [deg/h]: thermal model uncertainty and turn-on repeatability
	double min_still_s = 10.0;  //!< shortest standstill used [s]
	double guard_s = 1.0;  //!< left out at both ends of a standstill [s]
	/** The estimate replaces the prior only once the standstills show the prior wrong:
	 * |offset - prior offset| > significance_sigma x its 1-sigma (then for the rest of the turn-on).
	 * 0: always (the plain filter). */
	double significance_sigma = 3.0;
};

/** What one standstill did to the offset. */
struct StandstillUpdate
{
	double start_s = 0, end_s = 0;  //!< the standstill (first and last still sample)
	double first_used_s = 0, last_used_s = 0;  //!< the samples the filter took
	std::size_t samples = 0;
	double offset_before_dph = 0, sigma_before_dph = 0;
	double offset_after_dph = 0, sigma_after_dph = 0;
	/** Mean of (rate - expected rate) over the samples used [deg/h]: what the standstill read. */
	double mean_reading_dph = 0;
	/** After this standstill the estimate is applied (it differs significantly from the prior,
	 * now or at an earlier standstill of the same turn-on). */
	bool applied = false;
};

/** A corrected sample. */
struct RefinedRate
{
	double t_s = 0;
	double rate_dph = 0;  //!< input minus correction_dph
	double correction_dph = 0;  //!< offset + bias instability estimate subtracted [deg/h]
};

class FieldBiasRefiner
{
   public:
	/** t0_s: the time of the prior (the first sample's). Throws std::invalid_argument on bad
	 * options (see StandstillDetector and BiasOffsetFilter). */
	FieldBiasRefiner(const FieldRefinementOptions& options, double t0_s);

	void addOdometry(double t_s, double x_m, double y_m, double yaw_rad) { detector_.addOdometry(t_s, x_m, y_m, yaw_rad), drain(); }
	/** A gyro sample (times must increase: a repeated or earlier time is dropped and gives no
	 * output). turn_on: the gyro was powered on at this sample: a new turn-on offset, so the
	 * filter restarts from the prior. */
	void addRate(double t_s, double rate_dph, bool turn_on = false) { detector_.addRate(t_s, rate_dph, turn_on), drain(); }
	void finish();
	/** The next corrected sample, in the input's order; false when none is ready (waiting for
	 * the odometry that covers it). */
	bool next(RefinedRate& out);

	const std::vector<StandstillUpdate>& updates() const { return updates_; }
	/** Standstills that ended before they could change anything (shorter than min_still_s plus
	 * the guards, or too short to beat the prior). */
	std::size_t shortStandstills() const { return short_; }
	/** Turn-ons after the first sample (each restarted the filter from the prior). */
	std::size_t restarts() const { return restarts_; }
	const BiasOffsetFilter& filter() const { return kf_; }
	/** Whether the estimate is applied (see FieldRefinementOptions::significance_sigma), and
	 * since when (NaN: not yet in this turn-on). */
	bool applied() const { return applied_; }
	double appliedSince_s() const { return applied_since_s_; }
	/** The correction at t_s [deg/h] from what is decided so far, for a caller that cannot wait
	 * for the odometry covering t_s (a per-sample pipeline): causal, but unlike next() it depends
	 * on how the caller interleaves gyro and odometry. */
	double currentCorrection_dph(double t_s) const { return applied_ ? kf_.correctionAt_dph(t_s) : opt_.prior_offset_dph; }
	const FieldRefinementOptions& options() const { return opt_; }

   private:
	void drain();
	void take(const ClassifiedRate& c);
	void endRun();
	bool beatsPrior(double length_s) const;
	void testSignificance(double t_s);

	FieldRefinementOptions opt_;
	StandstillDetector detector_;
	BiasOffsetFilter kf_;
	std::deque<ClassifiedRate> run_;  //!< still samples of the current standstill not yet used
	bool in_run_ = false;
	double run_start_s_ = 0, run_last_s_ = 0;
	std::optional<StandstillUpdate> current_;
	double reading_sum_ = 0;
	std::vector<StandstillUpdate> updates_;
	std::size_t short_ = 0, restarts_ = 0;
	bool applied_ = false;
	bool look_ = false;  //!< test the significance at this sample (twice per standstill)
	double applied_since_s_ = std::numeric_limits<double>::quiet_NaN();
	double t0_s_;
	std::deque<RefinedRate> out_;
};

}  // namespace mrpt_fog::nav
