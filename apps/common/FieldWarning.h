/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FieldWarning.h
 * What every program that compensates says about the magnetic term of a calibration with a
 * magnetic section (MagneticModel.h): whether the log gives the applied field, and on how many
 * samples it was unknown (compensated without the term). Never silently without the field. */

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/model/Compensator.h>

#include <string>

namespace mrpt_fog::app
{
/** "  warning: ..." line (with trailing newline) when `cal` has a magnetic section and the field
 * was unknown on some samples (the log has no field column, or NaN cells), else "". */
std::string fieldWarning(const Calibration& cal, const CompensationCounters& c, bool log_has_field);
/** fieldWarning()'s lines (one or several axes) as one message for a JSON value: without the
 * "  warning: " prefixes and newlines, joined by "; ". */
std::string fieldWarningMessage(const std::string& warning_lines);
/** {"dph_per_uT", "field_column", "field_unknown_samples", "field_range_uT", "field_outside_samples",
 * "field_max_beyond_uT", "warning"} for a calibration with a
 * magnetic section (null otherwise). */
JsonValue fieldJson(const Calibration& cal, const CompensationCounters& c, bool log_has_field);
}  // namespace mrpt_fog::app
