/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AnalysisTimescale.h
 * The timescale the model-gap workflow analyses a run at, from the run's own noise.
 *
 * Thermal effects vary over minutes; per-sample (or per-second) rows of a gyro are mostly white
 * noise. The rows are therefore block means of a length chosen from the data: the Allan deviation
 * of the base model's residual falls as 1/sqrt(tau) while white noise dominates; the
 * "white corner" is the shortest tau where its Allan variance reaches twice the white line's
 * (white noise no longer holds most of it). Blocks of a quarter of that corner average the white
 * part away and keep whatever varies at the corner and slower. The block never exceeds what the
 * model's slowest short-window estimate can serve: the calibration's causal rate estimator (or,
 * without rate terms, the analysis' derivative window) needs at least kBlocksPerWindow block
 * means per window. A requested block beyond that limit is refused with the limit stated.
 * Internal to the discrepancy room.
 */

#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Block means needed inside the shortest window the analysis estimates a slope over. */
constexpr double kBlocksPerWindow = 4.0;

/** Median time step of the run's rows [s] (0 with fewer than two rows). */
double medianRowPeriod_s(const FogSeries& run);

/** The shortest tau [s] where the Allan variance of `residual` (rows of period `period_s`,
 * gaps ignored) reaches 2x the white line drawn through its first point, searched over octaves
 * while at least 8 clusters remain; NaN when it never does (white to the longest tau measured). */
double whiteNoiseCorner_s(const std::vector<double>& residual, double period_s);

/** The run's rows merged into block means of K = floor(block_s / row period) consecutive rows
 * (K <= 1: returned unchanged). A block ends early where power, table rate or field change, or
 * before a gap (a step longer than 3 row periods): it never mixes them. Each row is the mean of
 * its block's rows (time, rates, table rate, field, power; each thermistor over its finite
 * readings, NaN when none). Metadata and layout are kept. */
FogSeries blockMeansOfRows(const FogSeries& run, double block_s);

}  // namespace mrpt_fog::discrepancy
