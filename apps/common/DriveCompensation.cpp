/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "DriveCompensation.h"

#include "FieldWarning.h"
#include "RangeWarning.h"
#include "ThermistorScreeningReport.h"

#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <cstdio>
#include <stdexcept>

namespace mrpt_fog::app
{
std::vector<double> compensatedDriveRate_dph(const FogSeries& fog, const Calibration& cal, const std::string& cal_path,
										bool screen_thermistors, std::string* field_warning)
{
	if (!fog.has_axis[static_cast<std::size_t>(cal.axis)])
		throw std::runtime_error(cal_path + ": calibration is for axis " + std::string(1, axisLetter(cal.axis)) +
								 ", which the drive's FOG does not have");
	// The compensated column alone (compensate() returns five: memory).
	std::vector<double> rate;
	CompensationCounters c;
	ThermistorScreening screening;
	try
	{
		rate = mrpt_fog::compensatedRate_dph(cal, screenedForCompensation(fog, screen_thermistors, screening), &c);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error(cal_path + ": cannot compensate the drive's FOG: " + e.what());
	}
	if (rate.size() != fog.size())
		throw std::runtime_error(cal_path + ": the compensator returned a different number of samples");
	if (!screen_thermistors || screening.rejected_readings) std::fputs(app::screeningText(screening, screen_thermistors).c_str(), stdout);
	if (c.fallback_samples || c.no_model_samples || c.clamped_samples)
		std::printf("  compensation: %zu samples, %zu on a fallback model, %zu without model, %zu clamped to the "
					"calibrated range\n",
					c.samples, c.fallback_samples, c.no_model_samples, c.clamped_samples);
	std::fputs(app::outOfRangeWarning(c, cal.extrapolation).c_str(), stdout);
	const std::string w = app::fieldWarning(cal, c, !fog.field_uT.empty());
	std::fputs(w.c_str(), stderr);
	if (field_warning) *field_warning += w;
	return rate;
}

std::vector<double> compensatedDriveRate_dph(const FogSeries& fog, const std::string& cal_path, bool screen_thermistors,
										std::string* field_warning)
{
	return compensatedDriveRate_dph(fog, loadCalibrationYaml(cal_path, GyroAxis::Z), cal_path, screen_thermistors,
							   field_warning);
}

}  // namespace mrpt_fog::app
