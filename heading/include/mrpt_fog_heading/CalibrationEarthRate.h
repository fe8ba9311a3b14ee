/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file CalibrationEarthRate.h
 * The Earth-rate rule, written once. A FOG fixed to the Earth senses the vertical Earth rate
 * Omega sin(latitude) (15.041 deg/h x sin(lat)). A bias model fitted on static chamber runs
 * (EarthRateHandling::InBias) has absorbed that rate at the calibration site, so the
 * compensated rate lacks it; the strapdown update (nav::StrapdownAttitude) removes the Earth
 * rate at the drive's latitude. The rule: add Omega sin(calibration latitude) back to the
 * compensated rate once, before the strapdown, or the Earth rate is removed twice.
 * The scale factor divides (raw - bias), so the Earth rate goes back unscaled.
 *
 * The calibration latitude: an explicit override, else the one the calibration file records,
 * else the drive's (and the result says which). A calibration whose runs carried the Earth
 * rate in the table rate (EarthRateHandling::InTableRate) needs nothing added. */

#include <mrpt_fog/model/Calibration.h>

#include <optional>

namespace mrpt_fog::heading
{
/** Where the calibration latitude came from. */
enum class LatitudeSource
{
	Drive,  //!< the file records none: the drive's latitude is assumed
	Calibration,  //!< the calibration file's latitude_deg
	Option  //!< given by the caller (e.g. --cal-latitude-deg)
};
const char* latitudeSourceName(LatitudeSource s);  //!< "drive", "calibration", "option"

struct CalibrationEarthRateOptions
{
	std::optional<double> calibration_latitude_deg;  //!< overrides the file's [deg]
	bool bias_without_earth_rate = false;  //!< the caller states the bias holds no Earth rate
};

struct CalibrationEarthRate
{
	double add_back_dph = 0.0;  //!< added to the compensated rate [deg/h] (0 when none is held)
	double calibration_latitude_deg = 0.0;  //!< the latitude used [deg]
	LatitudeSource source = LatitudeSource::Drive;
	bool bias_holds_earth_rate = false;  //!< whether anything is added back
};

/** The rule for calibration `cal` on a drive at drive_latitude_deg. Throws
 * std::invalid_argument when a latitude is outside [-90, 90] or not finite. */
CalibrationEarthRate calibrationEarthRate(const Calibration& cal, double drive_latitude_deg,
										  const CalibrationEarthRateOptions& options = {});

/** The vertical Earth rate Omega sin(latitude) [deg/h] (what a level, still FOG reads). */
double verticalEarthRate_dph(double latitude_deg);

}  // namespace mrpt_fog::heading
