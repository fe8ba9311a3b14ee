/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AllanDeviation.h
 * Allan deviation of a uniformly sampled rate record (IEEE Std 952-1997, Annex C), both the
 * non-overlapping and the fully overlapping estimator, on a list of cluster sizes m
 * (tau = m tau0). Rates are in whatever unit the caller uses (deg/h here); the deviation comes
 * out in the same unit.
 *
 *   non-overlapping:  M = floor(N/m) cluster averages ybar_j,
 *                     AVAR = 1 / (2 (M-1)) sum_j (ybar_{j+1} - ybar_j)^2
 *   overlapping:      x_i = tau0 sum_{k<i} y_k (i = 0..N),
 *                     AVAR = 1 / (2 m^2 tau0^2 (N - 2m + 1)) sum_i (x_{i+2m} - 2 x_{i+m} + x_i)^2
 *
 * Checked against the NBS-14 reference values (tests/metrics/test_AllanDeviation.cpp).
 * The input must be uniformly sampled and free of NaN: use resampleUniform() first for a
 * record with irregular timestamps or dropouts.
 */

#include <mrpt_fog/common/RowSpill.h>

#include <cstddef>
#include <vector>

namespace mrpt_fog
{
/** One point of an Allan deviation curve. */
struct AllanPoint
{
	double tau_s = 0;  //!< averaging time m tau0 [s]
	std::size_t m = 0;  //!< cluster size [samples]
	double adev = 0;  //!< Allan deviation [unit of the input rate]
	/** Number of non-overlapping clusters N/m: the statistical weight of the point (the
	 * relative 1-sigma error of the deviation is roughly 1/sqrt(clusters) or better). */
	std::size_t clusters = 0;
};

enum class AllanKind
{
	NonOverlapping,
	Overlapping
};

/** Octave cluster sizes 1, 2, 4, ... with at least `min_clusters` (>= 2) clusters of m samples
 * in n samples (m <= n / min_clusters). Empty when n < min_clusters; never throws. */
std::vector<std::size_t> octaveClusterSizes(std::size_t n, std::size_t min_clusters = 2);

/** Allan deviation of y (uniform sample period tau0_s, no NaN) at the given cluster sizes.
 * Sizes that do not fit (non-overlapping: fewer than 2 clusters; overlapping: 2m > N) are
 * skipped. Throws std::invalid_argument for tau0_s <= 0, a non-finite sample (names the index),
 * fewer than 2 samples or m == 0. */
std::vector<AllanPoint> allanDeviation(const std::vector<double>& y, double tau0_s,
									   const std::vector<std::size_t>& cluster_sizes, AllanKind kind);

/** Same, on octave cluster sizes (octaveClusterSizes(y.size())). */
std::vector<AllanPoint> allanDeviation(const std::vector<double>& y, double tau0_s,
									   AllanKind kind = AllanKind::Overlapping);

/** A uniformly sampled copy of an irregular record, for the Allan deviation: period
 * period_s (<= 0: the median sample interval), values by linear interpolation between the
 * neighbouring finite samples; NaN samples are skipped. Each gap longer than max_gap_s
 * (<= 0: 5 periods) splits the record, and only the longest gap-free segment is returned
 * (an Allan deviation across a gap would be wrong). Throws std::invalid_argument on size
 * mismatch, non-increasing time, fewer than 2 finite samples, or when the resample would hold
 * more than 4x (+16) the samples of the segment (timestamps far too irregular for the period). */
struct UniformRecord
{
	double t0_s = 0;  //!< time of the first sample [s]
	double period_s = 0;  //!< sample period [s]
	std::vector<double> value;  //!< resampled values
	std::size_t segments = 1;  //!< gap-free segments found (only the longest is kept)
};
UniformRecord resampleUniform(const std::vector<double>& time_s, const std::vector<double>& value,
							  double period_s = 0, double max_gap_s = 0);


// ---- The same for records longer than memory: read from a RowSpill in passes. ----

/** resampleUniform() of columns time_col / value_col of `rows`: the same numbers, the resampled
 * values appended to `out` (width 1; UniformRecord::value stays empty). Memory independent of
 * the record's length. */
UniformRecord resampleUniform(const RowSpill& rows, std::size_t time_col, std::size_t value_col, RowSpill& out,
							  double period_s = 0, double max_gap_s = 0);

/** Which offsets the overlapping estimator of a spilled record sums over. */
enum class AllanOffsets : unsigned char
{
	/** Every offset i = 0 .. N - 2m (fully overlapping): one pass for m <= 65 536, then one pass
	 * of three readers per larger octave, so O(N log N) in all. */
	All = 0,
	/** Every offset for m <= 65 536 (the same numbers, bit for bit); for larger m the offsets
	 * that are multiples of a stride s = max(256, 2^ceil(log2(N / 2^18))) (at least 512 offsets
	 * per cluster length, N / s + 1 terms), from phases kept during the one pass: O(N) in all,
	 * memory at most 2^18 + 1 phases (4 MB). The estimate sums the same second differences at
	 * fewer offsets: at m >= 512 s neighbouring offsets are nearly the same difference, so its
	 * spread is that of full overlap within a few percent (docs/reference/metrics.md, "Allan deviation of
	 * long records"). */
	Linear = 1
};

/** allanDeviation(y, tau0_s, cluster_sizes, AllanKind::Overlapping) of a record held in a RowSpill
 * of width 1: with AllanOffsets::All the same numbers, bit for bit; with Linear (default) the
 * same for m <= 65 536 and the strided estimate above. Memory: a ring of the phase for cluster
 * sizes up to 65 536 (2 MB) and the strided phases; All reads the spill again with three readers
 * per larger cluster size. */
std::vector<AllanPoint> allanDeviationOverlapping(const RowSpill& y, double tau0_s,
												  const std::vector<std::size_t>& cluster_sizes,
												  AllanOffsets offsets = AllanOffsets::Linear);

}  // namespace mrpt_fog
