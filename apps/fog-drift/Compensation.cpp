/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "Compensation.h"

#include <mrpt_fog/model/Compensator.h>

#include <stdexcept>

namespace mrpt_fog::drift
{
std::vector<double> compensatedRate_dph(const FogSeries& fog, const std::string& cal_path)
{
	// The calibration YAML reader (model/CalibrationYaml.h) is not in the tree yet: the
	// compensated path is wired up to Compensator::compensate and waits for the loader.
	(void)fog;
	throw std::runtime_error(cal_path + ": cannot load: the calibration YAML reader is not available in this build");
}

}  // namespace mrpt_fog::drift
