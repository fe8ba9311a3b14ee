/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file DiscrepancyOutput.h
 * How fog-discrepancy shows a model-gap analysis (discrepancy/DiscrepancyAnalysis.h, which
 * returns data only): the JSON document, the readable text and the residual plot.
 */

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/discrepancy/DiscrepancyAnalysis.h>

#include <string>

namespace mrpt_fog::discrepancy
{
/** JSON document (stable keys: named_effects, segments, gap.before.rms_dph, gap.after.rms_dph,
 * gap_confirm..., see docs/guide/model-gap.md). */
JsonValue discrepancyJson(const DiscrepancyReport& report);

/** Readable report (several lines). */
std::string discrepancyText(const DiscrepancyReport& report);

/** PNG: residual vs time before and after (two panels), flagged segments shaded. Atomic. */
void saveGapPlot(const RunGap& gap, const std::string& path_png, const std::string& title);

}  // namespace mrpt_fog::discrepancy
