/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file LongRunVariance.h
 * The long-run variance of a serially correlated residual (the sum of all its autocovariances:
 * what the variance of a mean of n samples is, times n), the one place it is estimated. Two
 * forms, for two uses:
 *  - batchMeansLongRunVariance: b x the variance of means over non-overlapping blocks of b
 *    samples, b = round(sqrt(length)); for intervals of parameters fitted on a residual that
 *    holds autocorrelated noise and unmodelled structure alike (the simulator calibration, the
 *    reconstructed chamber air);
 *  - longRunVarianceFactor: the Bartlett-window estimate of the long-run variance over the
 *    variance, for a residual already whitened by a fitted noise model (what autocorrelation the
 *    whitening left; the missing-effect tests).
 */

#include <Eigen/Core>
#include <vector>

namespace mrpt_fog
{
/** How batch means are combined over several series (e.g. one per thermistor). */
enum class BatchPooling
{
	/** One block length b = round(sqrt(m / series)), m = all entries; the block means of every
	 * series around their common mean: b x var(block means). NaN with fewer than 8 entries or
	 * fewer than 2 blocks in all. */
	PooledBlocks,
	/** Per series b = round(sqrt(its length)) and b x var(its block means) when it holds at
	 * least 2 blocks; the mean of those. NaN when no series holds 2 blocks. */
	MeanOfSeries
};

/** Long-run variance by batch means (see the file comment). Entries must be finite (leave the
 * others out); a trailing partial block is dropped. */
double batchMeansLongRunVariance(const std::vector<std::vector<double>>& series, BatchPooling pooling);

/** Long-run variance factor 1 + 2 sum_{l=1..L} (1 - l/(L+1)) rho_l of a (whitened) residual
 * (Bartlett window of L = max_lag lags), clamped to >= 1; 1 for fewer than 3 samples or a
 * constant residual. */
double longRunVarianceFactor(const Eigen::VectorXd& e, int max_lag);

}  // namespace mrpt_fog
