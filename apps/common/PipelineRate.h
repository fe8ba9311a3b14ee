/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file PipelineRate.h
 * A drive held in memory through the library's heading pipeline (mrpt_fog_heading/HeadingPipeline.h),
 * for the programs that dead-reckon it against its truth (fog-drift, fog-localize): a sample
 * through a pipeline, the rate the strapdown integrates at each FOG sample (fog-drift's
 * in-memory path), and the compensation's reports printed after the drive's last sample. */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog_heading/DriveLog.h>
#include <mrpt_fog_heading/HeadingPipeline.h>

#include <string>
#include <vector>

namespace mrpt_fog::app
{
/** One FOG sample through a pipeline; an error of the compensator names `cal_path` ("" for
 * none: as it comes). */
const heading::RateStep& addFogSample(heading::HeadingPipeline& pipe, const FogSample& x, const std::string& cal_path);

/** The rate the strapdown integrates [deg/h] at each sample of a drive held in memory (NaN while
 * the gyro is off): the FOG samples through `pipe` (not aligned: no heading) with the odometry
 * given before the samples at or after its time. */
std::vector<double> pipelineRate_dph(heading::HeadingPipeline& pipe, const FogSeries& fog,
									 const heading::OdometryPoses& odometry, const std::string& cal_path);

/** After the drive's last sample, the compensated pipeline's reports: the thermistor screening
 * (stdout, when off or when it rejected readings), the compensator's fallback / clamp counts and
 * the out-of-range warning (stdout), and the field warning (stderr), which it returns. */
std::string reportPipelineCompensation(const heading::HeadingPipeline& pipe, const Calibration& zcal,
									   bool screen_thermistors, bool log_has_field);

}  // namespace mrpt_fog::app
