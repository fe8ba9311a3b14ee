/* fog-evaluate: the compensated rate of a series, from a calibration file. */
#include "CalibrationSource.h"

#include <mrpt_fog/model/CalibrationYaml.h>

#include <stdexcept>

namespace mrpt_fog::evaluate
{
CompensatedSeries compensateWithCalibration(const std::string& cal_path, const FogSeries& series)
{
	const Calibration cal = loadCalibrationYaml(cal_path);
	CompensatedSeries out;
	try
	{
		out = compensate(cal, series);
	}
	catch (const std::exception& e)
	{
		throw std::invalid_argument(cal_path + ": cannot compensate this log: " + e.what());
	}
	if (out.compensated_dph.size() != series.size())
		throw std::runtime_error(cal_path + ": the compensator returned " + std::to_string(out.compensated_dph.size()) +
								 " samples for " + std::to_string(series.size()));
	return out;
}

}  // namespace mrpt_fog::evaluate
