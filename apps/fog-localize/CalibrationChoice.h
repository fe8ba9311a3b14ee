/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file CalibrationChoice.h
 * Which calibration compensates the drive's FOG, and what it models.
 *
 * A drive turns: the gyro's scale-factor error (its temperature dependence, ScaleFactorModel.h)
 * adds a heading error at every turn, which a bias-only calibration leaves in the compensated
 * gyro. So when no calibration is given, fog-localize fits one the way fog-calibrate does on a
 * chamber run plus a rate-table run of the same gyro (thermistor readings screened; bias from
 * the static samples, scale factor vs temperature from the table segments; the same file as
 * `fog-calibrate -i CHAMBER -i RATETABLE --model multipoint`), and falls back to a bias-only fit on the
 * chamber run when no rate-table run is available, saying so. A given calibration is used as
 * it is. What was used goes into the text output and the JSON (`calibration`). */

#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/model/Calibration.h>

#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog::localize
{
enum class CalibrationSource
{
	Given,  //!< --cal: the file as given
	FittedBiasAndScaleFactor,  //!< fitted here on a chamber run + a rate-table run
	FittedBiasOnly  //!< fitted here on a chamber run alone (no rate-table run)
};
/** "given", "fitted_bias_and_scale_factor", "fitted_bias_only". */
const char* toString(CalibrationSource s);

struct CalibrationChoice
{
	CalibrationSource source = CalibrationSource::Given;
	std::string path;  //!< the file the compensation read (given, or written by the fit)
	std::vector<std::string> fitted_on;  //!< runs of the fit (empty when given)
	Calibration cal;  //!< its z-axis calibration
	bool hasScaleFactor() const { return cal.scale_factor.has_value(); }
};

struct CalibrationRequest
{
	std::string given_path;  //!< --cal (empty: fit)
	std::string chamber_path;  //!< chamber run for the fit
	std::optional<std::string> ratetable_path;  //!< rate-table run for the fit (none: bias only)
	std::string write_path;  //!< where a fitted calibration is written
	std::string preset = "multipoint";
	LogReadOptions read_options;  //!< how the runs are read (format file, notices)
};

/** Loads the given calibration, or fits one (see the file comment) and writes it. Throws
 * std::runtime_error naming the file on unreadable input, and when a rate-table run is given
 * but cannot support a scale-factor fit (the reason from fitScaleFactor). */
CalibrationChoice chooseCalibration(const CalibrationRequest& request);

/** One line: the file, how it was obtained, its bias model and its scale-factor model (or that
 * it has none and what that leaves in the compensated gyro). */
std::string describeCalibration(const CalibrationChoice& choice);

}  // namespace mrpt_fog::localize
