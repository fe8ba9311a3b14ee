/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RangeWarning.h
 * The out-of-calibrated-range report every program that compensates prints: the
 * share of samples with a temperature (or inner-outer difference) and with a rate outside the
 * calibrated range, how far beyond, and the extrapolation policy used; and the same as JSON. */

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/model/Compensator.h>

#include <string>

namespace mrpt_fog::app
{
/** "warning: ..." line(s) (with trailing newline), or "" when every sample was in range. */
std::string outOfRangeWarning(const CompensationCounters& c, ExtrapolationPolicy policy);
/** {"policy", "samples", "temperature": {"outside_samples", "outside_share", "max_beyond_C"},
 *  "rate": {"outside_samples", "outside_share", "max_beyond_C_per_min"}} */
JsonValue outOfRangeJson(const CompensationCounters& c, ExtrapolationPolicy policy);
}  // namespace mrpt_fog::app
