/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogSeriesConversion.h
 * FogSeries (columns) <-> CObservationFOG (one MRPT observation per sample).
 * Timestamps: observation timestamp = series.epoch_s + time_s (UNIX seconds). */

#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <vector>

namespace mrpt_fog
{
/** Observation for sample k of the series (dropouts become tempValid = false). */
CObservationFOG::Ptr observationFromSeries(const FogSeries& series, std::size_t k);

/** All samples as observations (validates the series first; throws std::invalid_argument). */
std::vector<CObservationFOG::Ptr> observationsFromSeries(const FogSeries& series);

/** Builds a series from observations of one sensor. The layout (thermistors, axes, optional
 * fields) is taken from the first observation; an observation with another layout throws
 * std::invalid_argument naming its index. epoch_s is the first timestamp (whole seconds).
 * An empty input gives an empty series. */
FogSeries seriesFromObservations(const std::vector<CObservationFOG::Ptr>& obs);

}  // namespace mrpt_fog
