/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file StreamingDrive.h
 * evaluateDrive() without holding the drive: the figures of a single-axis drive in
 * memory that does not grow with the drive, from two reads of the file.
 *  - Pass 1: the ends of every series (FOG, FOG_IDEAL, odometry, truth), the truth's path length
 *    and its turns and straights (nav::segmentDrive's rules, with a window of +-smooth_s / 2).
 *  - Pass 2: each gyro variant (raw, compensated, ideal) runs through its own library heading
 *    pipeline (VariantPipeline.h: compensation, standstill updates, Earth rate, strapdown),
 *    given the odometry before the FOG samples at or after its time and re-aligned from the
 *    truth at the start of each powered span; its attitudes are dead-reckoned with the odometry
 *    from the truth's position and compared with the truth as the samples come, keeping only the
 *    attitudes, poses and truth points not yet bracketed by a later one; the heading figures are
 *    summed as they go (nav::HeadingFigures: the samples of the current straight are kept for its
 *    centred least squares: memory bounded by the longest straight, not the drive).
 * The in-memory evaluation takes the same pipeline's rate into the library's truth-aligned dead
 * reckoning; the arithmetic is the same step for step (same interpolation brackets, same
 * summation order), so the figures are the same (ctest io_drift_streaming_equals_in_memory:
 * JSON and text equal to --in-memory's).
 * The per-sample series (DriftSeries::t_s ..., trajectories, truth) are left empty; with
 * DriveSettings::keep_series (--csv) the truth and each variant's errors, with
 * KeptTrajectories::ForOdometry (--odometry-out) the odometry variant's poses and rates, are
 * spilled to temporary files instead (DriveEvaluation::spilled). --plots (every trajectory)
 * and --transport-rate use evaluateDrive(), as does a triad FOG. */

#include "DriveEvaluation.h"

#include <optional>
#include <string>

namespace mrpt_fog::drift
{
/** Whether a drive with these settings can be evaluated by streaming (the outputs asked for
 * need no per-sample series). */
bool canStream(const DriveSettings& settings);

/** The evaluation of a single-axis drive by streaming; std::nullopt when the drive's FOG is a
 * triad (then evaluateDrive()). Throws as evaluateDrive() does. */
std::optional<DriveEvaluation> evaluateDriveStreaming(const std::string& path, const DriveSettings& settings);

}  // namespace mrpt_fog::drift
