/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file DriveCompensation.h
 * The compensated FOG rate of a drive held in memory (fog-drift's triad horizontal axes; the
 * vertical gyro goes through the heading pipeline, PipelineRate.h), with the
 * programs' reports printed: the calibration file loaded and run through the causal
 * Compensator (mrpt_fog/model/Compensator.h), sample by sample as in real time, after the
 * thermistor screening that a real-time implementation would run. */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::app
{
/** Compensated rate of the calibration's axis [deg/h], one value per sample of fog, with the
 * calibration `cal` read from `cal_path` (named in messages). With `screen_thermistors` the
 * thermistor readings are screened first (stuck / spike / out of range -> dropout, see
 * ThermistorHealth.h; a summary is printed). The log's field column feeds a magnetic term; when
 * it is unknown a warning goes to stderr and is appended to `field_warning`. Throws on a log
 * without that axis or a layout mismatch (message names the file). */
std::vector<double> compensatedDriveRate_dph(const FogSeries& fog, const Calibration& cal, const std::string& cal_path,
										bool screen_thermistors, std::string* field_warning = nullptr);
/** The same with the file's z-axis calibration loaded from cal_path. */
std::vector<double> compensatedDriveRate_dph(const FogSeries& fog, const std::string& cal_path, bool screen_thermistors,
										std::string* field_warning = nullptr);

}  // namespace mrpt_fog::app
