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
 * order (PowerSpanBuilder, heading/PowerSpans.h) and feed the truth poses to TruthYawAt in order, so the figures
 * are the same. */

#include "StreamingFigures.h"

#include <mrpt_fog_heading/PowerSpans.h>
#include <mrpt_fog_nav/HeadingFigures.h>

#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace mrpt_fog::drift
{
/** The gyro-off stretches and powered spans (the library's, heading/PowerSpans.h). */
using heading::GyroOffStretch;
using heading::navigationWindow;
using heading::PowerSpanBuilder;
using heading::PoweredSpan;

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

/** The truth segmentation without what a gyro-off stretch touches: straights are cut at the
 * stretches (a piece shorter than min_straight_s is dropped), turns overlapping a stretch
 * are dropped (with their TurnSpan, when `turns` is given: the same order). */
void cutSegmentsAtGyroOff(nav::DriveSegments& seg, std::vector<TurnSpan>* turns, const std::vector<GyroOffStretch>& off,
						  const nav::HeadingFigureOptions& options);

}  // namespace mrpt_fog::drift
