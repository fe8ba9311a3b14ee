/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RunSegmenter.h
 * Where a model fails: every sample of a run is labelled, from the data itself, by segment
 * type, temperature band and heating vs cooling, and the segments are ranked by the energy of
 * a residual, with a sentence such as "largest during cooling ramps below -20 C".
 *
 * Labels, by priority: power-off (power < 0.5), power-on transient (the first
 * `power_on_transient_s` after a power-on; only when the run has a power column), rate-table
 * (|table rate| > threshold), field (|field| > threshold), then from the mean thermistor
 * temperature rate: soak (|dT/dt| < `moving_rate_Cpm`), or a moving stretch of one sign that is
 * a ramp when it holds its rate (|rate| >= 0.8 x its peak without a break for at least `ramp_plateau_s`
 * and 30 % of the stretch, the coil's settling tail included) and a
 * step otherwise (the rate decays right after the peak; half-cycles of a sine sweep come out
 * as steps or ramps by the same rule). Segments are also cut where the mean temperature
 * crosses a band edge (bands: below -20, -20..0, 0..20, 20..40, above 40 C). Stretches shorter
 * than `min_segment_s` are merged into the previous segment.
 */

#include <mrpt_fog/discrepancy/DiscrepancyOptions.h>
#include <mrpt_fog/discrepancy/RunSignals.h>
#include <mrpt_fog/discrepancy/Segments.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Segments in time order covering every sample. */
std::vector<Segment> segmentRun(const RunSignals& sig, const SegmentationOptions& opt = {});

/** Ranks segments by the energy of `residual_dph` over the samples where rows is 1. Groups
 * holding less than 2 % of the time are listed but never named in the sentence. */
SegmentRanking rankSegments(const std::vector<Segment>& segments, const Eigen::VectorXd& residual_dph,
							const std::vector<unsigned char>& rows);

}  // namespace mrpt_fog::discrepancy
