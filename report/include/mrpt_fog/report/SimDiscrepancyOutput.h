/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimDiscrepancyOutput.h
 * How fog-discrepancy --sim shows a simulator-gap analysis (discrepancy/SimulatorGap.h, which
 * returns data only): the JSON document and the readable text.
 */

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/discrepancy/SimulatorGap.h>

#include <string>

namespace mrpt_fog::discrepancy
{
/** discrepancyJson plus the simulator keys (docs/guide/model-gap-simulator.md). */
JsonValue simDiscrepancyJson(const SimDiscrepancyReport& r);

/** Readable report. */
std::string simDiscrepancyText(const SimDiscrepancyReport& r);

}  // namespace mrpt_fog::discrepancy
