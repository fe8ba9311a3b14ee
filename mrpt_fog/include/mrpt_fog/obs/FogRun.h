/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogRun.h
 * A FOG run read in sequential passes, chunk by chunk, so that analyses that need several passes
 * over a log (the calibration fit, the figures) keep memory that does not grow with its length.
 * Two forms, the same numbers:
 *  - a view of a FogSeries in memory (one chunk: the series itself, no copy);
 *  - a run spilled row by row to an unlinked temporary file (common/RowSpill.h), read back in
 *    chunks of kChunkSamples (io/FogLogIO.h: readFogRun() reads a log file this way).
 *
 *   FogRun run(series);                                     // or readFogRun("big.rawlog")
 *   run.forEachChunk([&](const FogSeries& chunk, std::size_t k0) {
 *       for (std::size_t j = 0; j < chunk.size(); j++) use(k0 + j, chunk.time_s[j]);
 *   });
 *
 * A chunk is a FogSeries with the run's layout and metadata and consecutive samples k0 ..
 * k0 + chunk.size() - 1; it is valid only inside the callback. */

#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <functional>
#include <memory>

namespace mrpt_fog
{
class FogRun
{
   public:
	static constexpr std::size_t kChunkSamples = RowSpill::kBlockRows;

	/** A view of a series in memory (which must outlive the FogRun). */
	explicit FogRun(const FogSeries& series);
	/** An empty run with the layout and metadata of `header` (its columns are ignored; which
	 * optional columns are present is given here), filled with append(). */
	FogRun(const FogSeries& header, bool has_table_rate, bool has_field, bool has_power);
	FogRun(FogRun&&) noexcept;
	FogRun& operator=(FogRun&&) noexcept;
	~FogRun();

	/** Appends sample j of `chunk` (the run's layout); spilled runs only. */
	void append(const FogSeries& chunk, std::size_t j);

	/** Layout, metadata and which optional columns are present (present ones hold one NaN, as
	 * FogLogReader::header()); no samples. */
	const FogSeries& header() const;
	std::size_t size() const;
	bool empty() const { return size() == 0; }
	double frontTime_s() const;  //!< time of the first sample (NaN when empty)
	double backTime_s() const;  //!< time of the last sample (NaN when empty)
	bool hasTableRate() const;
	bool hasField() const;
	bool hasPower() const;
	/** The series in memory, or nullptr for a spilled run. */
	const FogSeries* inMemory() const;

	/** Calls f(chunk, k0) for consecutive chunks covering every sample, in order. */
	void forEachChunk(const std::function<void(const FogSeries& chunk, std::size_t k0)>& f) const;

	/** The whole run as a series in memory (for the few analyses that need random access; its
	 * memory grows with the run). */
	FogSeries load() const;

	/** FogSeries::validate() of a view (a spilled run is validated as it is written). */
	void validate() const;

	/** The same samples (shared, not copied) seen as a single-axis run: only `axis` is present,
	 * and where the gyro is on and the rate finite, `subtract_dph` is taken from its rate (what
	 * model/AxisRuns.h runsForAxis() does to a series). */
	FogRun axisView(GyroAxis axis, double subtract_dph) const;

   private:
	FogRun(const FogRun& other, int);  // a copy sharing the samples (axisView)
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrpt_fog
