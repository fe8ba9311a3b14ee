/* fog-evaluate: the compensated rate of a series, from a calibration file. */
#include "CalibrationSource.h"

#include <mrpt_fog/model/CalibrationYaml.h>

#include <filesystem>
#include <stdexcept>

namespace mrpt_fog::evaluate
{
namespace
{
bool sameFile(const std::string& a, const std::string& b)
{
	std::error_code ec;
	const bool eq = std::filesystem::equivalent(a, b, ec);
	return !ec && eq;
}
}  // namespace

CompensationResult compensateWithCalibration(const Calibration& cal, const std::string& cal_path,
											 const std::string& log_path, const FogRun& run, const CompensationSink& sink)
{
	CompensationResult r;
	r.axis = cal.axis;
	r.extrapolation = cal.extrapolation;
	r.calibration = cal;
	r.log_has_field = run.hasField();
	try
	{
		r.counters = compensateRun(cal, run, sink);
	}
	catch (const std::exception& e)
	{
		throw std::invalid_argument(cal_path + ": cannot compensate this log: " + e.what());
	}
	for (const auto& run : cal.runs)
		if (run == log_path || sameFile(run, log_path)) r.in_sample = true;
	return r;
}

}  // namespace mrpt_fog::evaluate
