/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogSeriesLayout.h
 * A series' layout without its samples: what readers report as their header and what writers
 * and converters start a chunk from. */

#include <mrpt_fog/obs/FogSeries.h>

namespace mrpt_fog
{
/** A series with the layout of `header` (label, epoch, thermistors, axes, metadata) and no
 * samples (optional columns empty). */
FogSeries emptySeriesLike(const FogSeries& header);

/** The layout header a reader reports: emptySeriesLike(s), and each optional column the log
 * has (table rate, field, power) present as one NaN. */
FogSeries layoutHeaderOf(const FogSeries& s, bool has_table_rate, bool has_field, bool has_power);
}  // namespace mrpt_fog
