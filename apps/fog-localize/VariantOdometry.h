/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file VariantOdometry.h
 * A gyro variant's odometry for the filter: the drive's FOG samples through the variant's heading
 * pipeline (mrpt_fog_heading/HeadingPipeline.h, Alignment::ByCaller), aligned from the truth's
 * heading at the start of each powered span (realign()), its attitude after each integrated
 * sample (attitude()) kept, and the wheel odometry's distances dead-reckoned with it from the
 * truth's position at the span's first odometry sample (nav::deadReckon2D), as fog-drift's
 * streamed path does. */

#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog_heading/DriveLog.h>
#include <mrpt_fog_heading/HeadingPipeline.h>
#include <mrpt_fog_heading/PowerSpans.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <string>
#include <vector>

namespace mrpt_fog::localize
{
/** The trajectories of `fog` (the drive's FOG or its ideal stream) through `pipe` (not yet fed):
 * the drive as one when `power` has no gyro-off stretch, else one per powered span that overlaps
 * the odometry and the truth (navigationWindow) with at least 2 odometry samples. An error of the
 * compensator names `cal_path` ("" for none); throws std::runtime_error naming `drive_path` when no
 * powered span can be navigated. */
std::vector<nav::Trajectory> deadReckonPoweredSpans(heading::HeadingPipeline& pipe, const FogSeries& fog,
													const heading::PowerSpanBuilder& power,
													const heading::DriveData& drive, const std::string& cal_path,
													const std::string& drive_path);

}  // namespace mrpt_fog::localize
