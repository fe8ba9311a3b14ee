/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file GyroOff.h
 * Stretches of a drive with the gyro off (the FOG's `power` column 0).
 *
 * While the gyro is off there is no rate to integrate: what the vehicle turned then cannot be
 * known from the gyro (a log may hold an empty rate there, or, as fog-sim's drive wrote before commit 20c65b6,
 * a 0 deg/h that is no measurement). fog-drift therefore navigates each powered span as a
 * drive of its own: at its start (the first powered sample, i.e. the turn-on) heading and
 * position are re-aligned from the truth, as at the start of the drive, and the error
 * figures are computed on the powered spans only (the truth poses inside a gyro-off stretch
 * are not compared; straights are cut there and turns that overlap one are left out). The
 * truth's heading change over each stretch is reported: the heading the gyro could not see.
 *
 * Both of fog-drift's paths (in memory and streamed) build these from the FOG samples in
 * order (PowerSpanBuilder) and feed the truth poses to TruthYawAt in order, so the figures
 * are the same. */

#include "StreamingFigures.h"

#include <mrpt_fog_nav/HeadingFigures.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace mrpt_fog::drift
{
/** A stretch with the gyro off [absolute s]: from the last powered sample before it (or the
 * log's first sample when the log starts off) to the turn-on sample (or the log's last
 * sample when it ends off). */
struct GyroOffStretch
{
	double off_s = 0, on_s = 0;
	bool from_start = false;  //!< the log starts with the gyro off
	bool to_end = false;  //!< the log ends with the gyro off (no turn-on)
	std::size_t samples = 0;  //!< FOG samples with power 0 in it
	/** unwrapped truth heading change from off_s to on_s [deg]; NaN when the truth does not
	 * cover both ends */
	double truth_heading_change_deg = std::numeric_limits<double>::quiet_NaN();
	double duration_s() const { return on_s - off_s; }
};

/** A run of consecutive powered FOG samples [absolute s]. */
struct PoweredSpan
{
	double t0_s = 0, t1_s = 0;
	std::size_t samples = 0;
};

/** The gyro-off stretches and powered spans of a FOG stream, sample by sample, by the rule of
 * apps/common/PowerCycles.h: a sample is off when its power is 0, and the first powered sample
 * after off ones is the turn-on (power 1 right after power 0). */
class PowerSpanBuilder
{
   public:
	/** power: the sample's power value (0 or 1; NaN when the log has no power column). */
	void add(double t_s, double power);
	/** Closes the last span or stretch. */
	void finish();
	const std::vector<PoweredSpan>& powered() const { return powered_; }
	std::vector<GyroOffStretch>& stretches() { return off_; }
	const std::vector<GyroOffStretch>& stretches() const { return off_; }

   private:
	std::vector<PoweredSpan> powered_;
	std::vector<GyroOffStretch> off_;
	bool any_ = false, on_ = false, finished_ = false;
	double last_t_ = 0;
};

/** The unwrapped truth yaw [deg] (HeadingFigures' unwrapping, linear between poses) at sorted
 * query times, from the truth poses in time order; NaN for a query outside the truth. */
class TruthYawAt
{
   public:
	explicit TruthYawAt(std::vector<double> sorted_queries_s);
	void add(double t_s, double yaw_rad);
	/** Call once after the last pose; then value(i) is final. */
	void finish();
	double value(std::size_t i) const { return values_[i]; }

   private:
	std::vector<double> q_, values_;
	std::size_t next_ = 0, n_ = 0;
	double front_yaw_rad_ = 0, prev_yaw_rad_ = 0, acc_rad_ = 0, prev_t_ = 0, prev_y_deg_ = 0;
};

/** The truth heading change over every stretch (from a TruthYawAt fed with the truth). */
std::vector<double> stretchQueryTimes(const std::vector<GyroOffStretch>& off);
void setTruthHeadingChanges(std::vector<GyroOffStretch>& off, const TruthYawAt& yaw);

/** The time window a gyro variant is navigated over within a powered span: the span clipped
 * to the variant's, the odometry's and the truth's time ranges; nullopt when empty. */
std::optional<std::pair<double, double>> navigationWindow(const PoweredSpan& span, double gyro_first_s,
														  double gyro_last_s, double odo_first_s, double odo_last_s,
														  double truth_first_s, double truth_last_s);

/** The truth segmentation without what a gyro-off stretch touches: straights are cut at the
 * stretches (a piece shorter than min_straight_s is dropped), turns overlapping a stretch
 * are dropped (with their TurnSpan, when `turns` is given: the same order). */
void cutSegmentsAtGyroOff(nav::DriveSegments& seg, std::vector<TurnSpan>* turns, const std::vector<GyroOffStretch>& off,
						  const nav::HeadingFigureOptions& options);

}  // namespace mrpt_fog::drift
