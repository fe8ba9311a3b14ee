/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file HeadingFigures.h
 * Navigation figures of a heading-error series that mean something on a drive with turns
 * (a final value alone can land anywhere: a drive that ends inside a turn reads the gyro's
 * lag, and a calibration error can cancel a turn error by luck).
 *
 * Turns and straights are found on the TRUTH: the truth yaw rate (central differences of the
 * unwrapped truth yaw, smoothed over `smooth_s`) above `turn_rate_dps` is a turn; a stretch
 * below `straight_rate_dps` lasting at least `min_straight_s` (after trimming `margin_s` at each
 * end) is a straight.
 *  - heading_error_rms_deg: RMS of the signed heading error over the whole run;
 *  - heading_drift_between_turns_dph: the common slope of the heading error on the straights
 *    (pooled within-segment least squares: each straight keeps its own offset, so what the
 *    turns did is not counted) [deg/h];
 *  - turn_scale_factor_ppm: the heading error each turn adds, against the turn angle, after
 *    removing the between-turn drift over the turn's duration: pooled least squares through
 *    the origin of (error change) on (truth heading change), x 1e6 [ppm]. A scale-factor
 *    error s gives s; a pure bias gives 0. NaN when the drive has no turn.
 * Returns NaN figures (never a throw) when the drive has no straight or no turn; throws
 * std::invalid_argument when the series and the truth do not overlap.
 */

#include <mrpt_fog_nav/Trajectory.h>

#include <cstddef>
#include <vector>

namespace mrpt_fog::nav
{
struct HeadingFigureOptions
{
	double turn_rate_dps = 1.0;  //!< truth |yaw rate| above this is a turn [deg/s]
	double straight_rate_dps = 0.2;  //!< below this (and long enough) a straight [deg/s]
	double min_straight_s = 30.0;  //!< shortest straight kept [s]
	double margin_s = 3.0;  //!< trimmed at both ends of a straight [s]
	double smooth_s = 2.0;  //!< truth yaw-rate smoothing window [s]
};

struct HeadingFigures
{
	double heading_error_rms_deg = 0.0;
	double heading_error_max_deg = 0.0;  //!< max |error|
	double heading_error_final_deg = 0.0;  //!< |error| at the end
	double heading_drift_between_turns_dph = 0.0;  //!< NaN without straights
	double turn_scale_factor_ppm = 0.0;  //!< NaN without turns
	std::size_t straights = 0;  //!< straights used
	double straight_time_s = 0.0;  //!< their total duration [s]
	std::size_t turns = 0;  //!< turns used
	double turned_deg = 0.0;  //!< sum of |heading change| over the turns [deg]
};

/** The truth segmentation, shared by every variant of one drive. */
struct DriveSegments
{
	struct Span
	{
		double t0_s = 0, t1_s = 0;
	};
	std::vector<Span> straights, turns;
};

/** Finds turns and straights on the truth (see the file comment). */
DriveSegments segmentDrive(const Trajectory& truth, const HeadingFigureOptions& options = {});

/** Figures of one signed heading-error series [deg] at times t_s [s] (e.g. DriftSeries). */
HeadingFigures computeHeadingFigures(const std::vector<double>& t_s, const std::vector<double>& heading_error_deg,
									 const Trajectory& truth, const DriveSegments& segments);

}  // namespace mrpt_fog::nav
