/* fog-evaluate: the figures of one gyro axis of a log, raw and (with a calibration) compensated. */
#pragma once

#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/obs/FogRun.h>

#include <memory>
#include <string>

#include "CalibrationSource.h"
#include "PowerCycles.h"
#include "RateEvaluation.h"

namespace mrpt_fog::evaluate
{
struct AxisReport
{
	GyroAxis axis = GyroAxis::Z;
	/** Rows (time, raw bias [, compensated bias]) [s, deg/h]: bias = rate minus table rate, NaN
	 * while the gyro is off. */
	RowSpill rows{2};
	RateEvaluation raw;
	std::unique_ptr<RateEvaluation> comp;  //!< with a calibration
	std::unique_ptr<CompensationResult> compensation;  //!< with a calibration
	app::PowerCycles power_cycles;  //!< gyro-off rows and turn-ons
};

/** The figures of `axis` of the run (read from `path`), compensated by `cal` when given (its
 * axis must be `axis`). Throws std::invalid_argument naming the file when tau_s does not fit. */
AxisReport evaluateAxis(const FogRun& run, const std::string& path, GyroAxis axis, const Calibration* cal,
						const std::string& cal_path, double tau_s);
}  // namespace mrpt_fog::evaluate
