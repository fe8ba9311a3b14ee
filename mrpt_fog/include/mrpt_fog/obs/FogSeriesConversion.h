/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogSeriesConversion.h
 * FogSeries (columns) <-> CObservationFOG (one MRPT observation per sample).
 * Timestamps: observation timestamp = series.epoch_s + time_s (UNIX seconds). */

#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <cstddef>
#include <utility>
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

/** seriesFromObservations() one observation at a time (the same series and the same layout
 * error), so that a reader need not keep a log's observations as MRPT objects. */
class FogSeriesBuilder
{
   public:
	/** expected_samples: columns reserved on the first add() (0: grown as needed).
	 * keep_temperatures false: the series has no thermistors (when only the rates are used; the
	 * layout is still checked against the first observation's). */
	explicit FogSeriesBuilder(std::size_t expected_samples = 0, bool keep_temperatures = true)
		: expected_(expected_samples), keep_temps_(keep_temperatures)
	{
	}
	/** Appends one sample; throws std::invalid_argument when its layout is not the first one's. */
	void add(const CObservationFOG& o);
	bool empty() const { return n_ == 0; }
	/** The series built so far (the builder is left empty). */
	FogSeries take() { return std::move(s_); }

   private:
	FogSeries s_;
	std::vector<ThermistorInfo> first_thermistors_;
	std::size_t expected_ = 0, n_ = 0;
	bool keep_temps_ = true;
	bool table_ = false, field_ = false, power_ = false;
};

}  // namespace mrpt_fog
