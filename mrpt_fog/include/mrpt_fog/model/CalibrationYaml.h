/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CalibrationYaml.h
 * Calibration files (YAML, read with mrpt::containers::yaml), version 2 (layout: docs/reference/model.md;
 * version 1 files, single axis and bias only, are still read). Version 3 is version 2 plus what a
 * version-2 reader cannot apply: lag signals (dTlag/dt) in a bias model, or an axis' magnetic
 * section; it is written only when a calibration holds one of them (else version 2), and a
 * file that says 1 or 2 but holds one of them is refused. Human-readable: the sensor
 * layout the calibration is for, the latitude of the calibration runs and how the Earth rate
 * entered the bias; then per gyro axis the preset and selection, the rate-estimator settings,
 * the bias model (main model and fallbacks), the optional scale_factor, warmup and magnetic
 * (bias per applied axial field, MagneticModel.h) sections, and the statistics. For the main bias model and each fallback model: the signals with their normalisation (centre, scale) and
 * calibrated range [min, max] with units, the terms by name with coefficient [deg/h] and its
 * standard deviation, the coefficient covariance, and the fit statistics; then the in-sample,
 * held-out and validation figures, each labelled. Numbers are written with 17 significant
 * digits so a file round-trips exactly.
 *
 * Loading validates everything and throws std::invalid_argument "<file>: <field>: <reason>"
 * (unknown format/version, missing or non-numeric field, unknown term, a term whose signal has
 * no normalisation, scale <= 0, min > max, coefficient count != term count, a model using a
 * thermistor outside the layout, a fallback that uses its own dropped thermistor, a magnetic
 * section with a non-finite number, a negative standard deviation or min > max). Saving is
 * atomic (common/AtomicFile.h).
 */

#include <mrpt_fog/model/Calibration.h>

#include <string>

namespace mrpt_fog
{
/** YAML text (version 2, or 3: see above) of a one-axis calibration / of a set of axes (validated first). */
std::string calibrationToYaml(const Calibration& cal);
std::string calibrationSetToYaml(const CalibrationSet& set);
/** Parses and validates YAML text (version 1, 2 or 3); `source` names the file in error messages. */
CalibrationSet calibrationSetFromYaml(const std::string& text, const std::string& source = "calibration");
/** The file's only axis (throws std::invalid_argument when it holds several, naming them). */
Calibration calibrationFromYaml(const std::string& text, const std::string& source = "calibration");
/** The calibration of `axis` (throws std::invalid_argument when the file has none for it). */
Calibration calibrationFromYaml(const std::string& text, const std::string& source, GyroAxis axis);

/** Write atomically (throw std::runtime_error naming the path on failure). */
void saveCalibrationYaml(const Calibration& cal, const std::string& path);
void saveCalibrationSet(const CalibrationSet& set, const std::string& path);
/** Read and validate (throw std::invalid_argument naming the file and field): the file's only
 * axis, a given axis, or all axes. */
Calibration loadCalibrationYaml(const std::string& path);
Calibration loadCalibrationYaml(const std::string& path, GyroAxis axis);
CalibrationSet loadCalibrationSet(const std::string& path);

}  // namespace mrpt_fog
