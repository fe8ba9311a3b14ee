/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/CalibrationEarthRate.h>

#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_fog::heading
{
const char* latitudeSourceName(LatitudeSource s)
{
	switch (s)
	{
		case LatitudeSource::Drive: return "drive";
		case LatitudeSource::Calibration: return "calibration";
		case LatitudeSource::Option: return "option";
	}
	return "drive";
}

double verticalEarthRate_dph(double latitude_deg) { return units::kEarthRate_dph * std::sin(latitude_deg * units::kDegToRad); }

CalibrationEarthRate calibrationEarthRate(const Calibration& cal, double drive_latitude_deg,
										  const CalibrationEarthRateOptions& options)
{
	CalibrationEarthRate r;
	r.calibration_latitude_deg = drive_latitude_deg;
	r.source = LatitudeSource::Drive;
	if (options.calibration_latitude_deg)
	{
		r.calibration_latitude_deg = *options.calibration_latitude_deg;
		r.source = LatitudeSource::Option;
	}
	else if (std::isfinite(cal.latitude_deg))
	{
		r.calibration_latitude_deg = cal.latitude_deg;
		r.source = LatitudeSource::Calibration;
	}
	if (!(std::abs(r.calibration_latitude_deg) <= 90))
		throw std::invalid_argument("calibration latitude " + std::to_string(r.calibration_latitude_deg) +
									" deg: must be within [-90, 90]");
	r.bias_holds_earth_rate = !options.bias_without_earth_rate && cal.earth_rate == EarthRateHandling::InBias;
	if (r.bias_holds_earth_rate) r.add_back_dph = verticalEarthRate_dph(r.calibration_latitude_deg);
	return r;
}

}  // namespace mrpt_fog::heading
