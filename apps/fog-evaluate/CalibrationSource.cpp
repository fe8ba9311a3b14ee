/* fog-evaluate: the compensated rate of a series, from a calibration file. */
#include "CalibrationSource.h"

#include <stdexcept>

namespace mrpt_fog::evaluate
{
CompensatedSeries compensateWithCalibration(const std::string& cal_path, const FogSeries& series)
{
	// The calibration YAML reader (model/CalibrationYaml.h) is not in the tree yet; once it is,
	// this loads the file and returns compensate(cal, series).
	(void)series;
	throw std::runtime_error(cal_path + ": --cal is not available in this build: the calibration YAML reader "
										"(model/CalibrationYaml.h) is missing");
}

}  // namespace mrpt_fog::evaluate
