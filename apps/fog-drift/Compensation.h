/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file Compensation.h
 * The compensated FOG rate of a drive: the calibration file loaded and run through the causal
 * Compensator (mrpt_fog/model/Compensator.h), sample by sample as in real time. */

#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::drift
{
/** Compensated z-axis rate [deg/h], one value per sample of fog. Throws on an unreadable
 * calibration, a calibration for another axis or a layout mismatch (message names the file). */
std::vector<double> compensatedRate_dph(const FogSeries& fog, const std::string& cal_path);

}  // namespace mrpt_fog::drift
