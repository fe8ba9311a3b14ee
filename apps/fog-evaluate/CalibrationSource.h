/* fog-evaluate: the compensated rate of a series, from a calibration file. */
#pragma once

#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>

namespace mrpt_fog::evaluate
{
struct CompensationResult
{
	CompensationCounters counters;
	GyroAxis axis = GyroAxis::Z;  //!< the calibrated axis
	/** The evaluated log is one of the calibration's runs: the figures are in-sample. */
	bool in_sample = false;
	ExtrapolationPolicy extrapolation = ExtrapolationPolicy::Linear;  //!< the calibration's policy
	Calibration calibration;  //!< as loaded (its magnetic section, if any, for the field warning)
	bool log_has_field = false;  //!< the run has a field column (fed to the magnetic term)
};

/** Runs the causal compensator (model/Compensator.h) of one axis' calibration (read from
 * cal_path) over the run read from log_path, chunk by chunk, passing its outputs to `sink`
 * (memory independent of the log's length). Throws std::invalid_argument naming cal_path on a
 * layout mismatch (from the compensator). */
CompensationResult compensateWithCalibration(const Calibration& cal, const std::string& cal_path,
											 const std::string& log_path, const FogRun& run, const CompensationSink& sink);

}  // namespace mrpt_fog::evaluate
