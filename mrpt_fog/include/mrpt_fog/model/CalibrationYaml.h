/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CalibrationYaml.h
 * Calibration files (YAML, read with mrpt::containers::yaml). Human-readable: the sensor layout
 * the calibration is for, the preset and selection, the rate-estimator settings, and for the
 * main model and each fallback model: the signals with their normalisation (centre, scale) and
 * calibrated range [min, max] with units, the terms by name with coefficient [deg/h] and its
 * standard deviation, the coefficient covariance, and the fit statistics; then the in-sample,
 * held-out and validation figures, each labelled. Numbers are written with 17 significant
 * digits so a file round-trips exactly.
 *
 * Loading validates everything and throws std::invalid_argument "<file>: <field>: <reason>"
 * (unknown format/version, missing or non-numeric field, unknown term, a term whose signal has
 * no normalisation, scale <= 0, min > max, coefficient count != term count, a model using a
 * thermistor outside the layout, a fallback that uses its own dropped thermistor). Saving is
 * atomic (common/AtomicFile.h).
 */

#include <mrpt_fog/model/Calibration.h>

#include <string>

namespace mrpt_fog
{
/** YAML text of a calibration. */
std::string calibrationToYaml(const Calibration& cal);
/** Parses and validates YAML text; `source` names the file in error messages. */
Calibration calibrationFromYaml(const std::string& text, const std::string& source = "calibration");

/** Writes atomically (throws std::runtime_error naming the path on failure). */
void saveCalibrationYaml(const Calibration& cal, const std::string& path);
/** Reads and validates (throws std::invalid_argument naming the file and field). */
Calibration loadCalibrationYaml(const std::string& path);

}  // namespace mrpt_fog
