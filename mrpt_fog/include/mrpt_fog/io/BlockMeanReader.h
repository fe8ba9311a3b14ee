/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file BlockMeanReader.h
 * A FOG log read as a stream and reduced to block means with a bounded number of rows, for the
 * analyses of slow (thermal) effects that otherwise hold dense per-sample matrices of the whole
 * run (fog-discrepancy). Memory is bounded by `max_rows`, not by the log.
 *
 * Rule (BlockMeanOptions):
 *  - the native sample period P is the median of the first (up to 64) time steps;
 *  - a block holds K = max(1, floor(min_block_s / P)) consecutive samples, so a log sampled at
 *    1 / min_block_s or slower is passed through unchanged (K = 1: every row is one sample, bit
 *    for bit), and a faster one is reduced to blocks of about min_block_s;
 *  - a block also ends early where the power state, the table rate or the applied field changes,
 *    or before a time step longer than 3 P (a gap): a block never mixes a powered and an
 *    unpowered sample, two table rates or two fields, nor bridges a gap;
 *  - when the rows exceed max_rows, adjacent blocks of the same power, table rate and field
 *    with no gap between them are merged in pairs (the block length doubles: 2 K, 4 K, ...),
 *    so the rows stay at most max_rows (unless the log changes power, table rate or field more
 *    often than that, or the blocks would exceed max_block_s: then the rows grow).
 * A row is the mean over its block's samples: time, gyro rates, table rate, field, power; each
 * thermistor over its finite readings (NaN when the whole block is a dropout). The mean of a
 * quantity linear in the samples (bias = rate - table rate, a temperature rate) is the quantity
 * of the means; thermal effects vary over minutes, so a block of seconds leaves them intact and
 * averages only the white part of the gyro noise (its RMS falls as 1 / sqrt(samples per block);
 * stability and range over windows much longer than a block are unchanged).
 *
 * The per-sample hook `each` (e.g. the thermistor screening) sees every raw sample before it
 * enters a block, as readFogRun()'s. Errors are readFogLog()'s (FogIoError naming the file and
 * the line / object), plus a powered sample without a finite rate (named by sample index). */

#include <mrpt_fog/io/FogLogReader.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>

namespace mrpt_fog
{
struct BlockMeanOptions
{
	/** Shortest block [s]; <= 0 disables the reduction (every sample is a row, max_rows ignored). */
	double min_block_s = 1.0;
	/** Rows kept at most (blocks double beyond it); at least 2. */
	std::size_t max_rows = 65536;
	/** Blocks never grow beyond this [s] (<= 0: no limit): past it the rows grow instead. A block
	 * must stay well inside the slowest-varying estimate the analysis makes from the rows (the
	 * compensator's rate window, 60 s by default: with 32 s blocks it has too few points). */
	double max_block_s = 16.0;
	/** The row's time: the mean of its block's times (default: the time of the means of signals
	 * linear in time), or the time of its first sample (on the log's own time grid, for analyses
	 * that need rows on a simulator profile's grid; the means then lag it by half a block). */
	enum class RowTime : unsigned char
	{
		Mean = 0,
		FirstSample = 1
	} row_time = RowTime::Mean;
};

/** What the reduction did. */
struct BlockMeanInfo
{
	std::size_t samples = 0;  //!< raw samples read
	std::size_t rows = 0;  //!< rows returned
	double native_period_s = 0;  //!< median of the first time steps (0 with fewer than 2 samples)
	std::size_t samples_per_block = 1;  //!< K x 2^doublings: the nominal block
	double block_s = 0;  //!< samples_per_block x native_period_s
	int doublings = 0;  //!< times the blocks were merged in pairs to stay within max_rows
	/** The thermistors' quantum as the raw readings show it: 5th percentile of the non-zero
	 * steps between consecutive readings of each thermistor (all pooled; a reservoir of 65 536
	 * of them, fixed seed), 0 with fewer than 20. Block means step by fractions of it, so an
	 * analysis of the rows that judges the quantisation needs this figure. */
	double thermistor_step_p05_C = 0;
	bool reduced() const { return rows < samples; }
};

/** Reads `path` (.rawlog, .csv, .csv.gz; the FOG sensor `fog_label`, or the only one) into block
 * means (see the file comment). `progress` and `options` (format file, notices) are readFogRun()'s. */
FogSeries readFogLogBlockMeans(
	const std::string& path, const std::string& fog_label, const BlockMeanOptions& opt, BlockMeanInfo& info,
	const std::function<void(double time_s, double* temp_C, std::size_t thermistor_count)>& each = {},
	const std::function<void(std::uint64_t samples, std::uint64_t bytes_done, std::uint64_t bytes_total)>& progress =
		{},
	const LogReadOptions& options = {});

/** The same reduction of samples given one by one (what readFogLogBlockMeans runs; tests feed it
 * directly). `layout` is the reader's header (FogLogReader::header(): present optional columns
 * hold one NaN). */
class BlockMeanAccumulator
{
   public:
	BlockMeanAccumulator(const FogSeries& layout, const BlockMeanOptions& opt);
	~BlockMeanAccumulator();
	BlockMeanAccumulator(const BlockMeanAccumulator&) = delete;
	BlockMeanAccumulator& operator=(const BlockMeanAccumulator&) = delete;
	/** One sample, times strictly increasing (checked by the reader). Throws
	 * std::invalid_argument for a powered sample without a finite rate. */
	void add(const FogSample& x);
	/** The rows (the reader's layout and metadata) and what was done; call once, at the end. */
	FogSeries finish(BlockMeanInfo& info);

   private:
	struct Impl;
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrpt_fog
