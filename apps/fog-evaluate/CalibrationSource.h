/* fog-evaluate: the compensated rate of a series, from a calibration file. */
#pragma once

#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>

namespace mrpt_fog::evaluate
{
/** Loads the calibration YAML at cal_path and runs the causal compensator (model/Compensator.h)
 * over the series. Throws std::runtime_error naming the file when it cannot be loaded, and
 * std::invalid_argument on a layout mismatch (from the compensator). */
CompensatedSeries compensateWithCalibration(const std::string& cal_path, const FogSeries& series);

}  // namespace mrpt_fog::evaluate
