/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CalibrationAugmentOutput.h
 * How fog-discrepancy --write-cal shows the augmented calibration
 * (discrepancy/CalibrationAugment.h, which returns data only): readable lines and JSON.
 */

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/discrepancy/CalibrationAugment.h>

#include <string>

namespace mrpt_fog::discrepancy
{
/** The rate-window choice in words: "rate estimator CHOSEN instead of BASE (analysed-run RMS a
 * vs b deg/h with the added terms)" (for a RateWindowChoice that changed the window). */
std::string rateWindowNote(const AugmentedCalibration& aug);
/** Readable lines (what was written, what not and why, the gap before/after). */
std::string augmentedCalibrationText(const AugmentedCalibration& aug, const std::string& path);
/** JSON: path, added_terms, not_written [{id, reason}], confirm {before, after} figures. */
JsonValue augmentedCalibrationJson(const AugmentedCalibration& aug, const std::string& path);

}  // namespace mrpt_fog::discrepancy
