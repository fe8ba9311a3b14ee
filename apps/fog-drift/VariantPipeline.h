/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file VariantPipeline.h
 * fog-drift's gyro variants on the library's heading pipeline (mrpt_fog_heading/HeadingPipeline.h):
 * thermistor screening, the causal compensator, the calibration's field offset, the standstill
 * updates (FieldRefinement.h), the calibration's Earth rate (the Earth-rate rule,
 * CalibrationEarthRate.h) and the strapdown with the drive's Earth rate removed. Both of
 * fog-drift's paths give it the odometry before the FOG samples at or after its time:
 *  - the streamed one (StreamingDrive.cpp) integrates with it, one pipeline per variant, aligned
 *    from the truth at the start of each powered span;
 *  - the in-memory one (DriveEvaluation.cpp) takes the compensated variant's rate from it
 *    (PipelineRate.h: pipelineRate_dph) into the truth-aligned dead reckoning (TruthAlignedDeadReckoning.h),
 *    which also runs a triad's 3-D strapdown and the transport rate.
 * The pipeline's own dead-reckoned poses are not used: fog-drift dead-reckons from the truth. */

#include "DriveEvaluation.h"
#include "PipelineRate.h"

#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/model/FieldOffset.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog_heading/HeadingPipeline.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog::drift
{
/** A variant's pipeline options without a calibration (raw, ideal): the drive's latitude and the
 * rate sampling from `hopt`, aligned by the caller. */
heading::PipelineOptions pipelineOptionsFor(const HeadingOptions& hopt);

/** The compensated variant's pipeline options (latitude and sampling as pipelineOptionsFor):
 * the screening, the calibration's latitude options, the standstill updates (when `refine`:
 * settings.refinement) and the calibration's field offset. Also those of the comparison without
 * a truth (HeadingWithoutTruth.h). */
heading::PipelineOptions compensatedOptionsFor(const DriveSettings& settings, const HeadingOptions& hopt, bool refine,
											   const std::optional<FieldOffset>& field_offset);

/** The compensated variant's pipeline for the vertical calibration `zcal` on a drive whose FOG
 * has `header`'s layout and metadata: the screening, the calibration's latitude options, the
 * standstill updates (when `refine`: settings.refinement) and the calibration's field offset,
 * which it loads into e.refinement (its value at t0_unix_s, the drive's first FOG sample).
 * Throws std::runtime_error naming settings.cal_path. */
std::unique_ptr<heading::HeadingPipeline> compensatedPipeline(const FogSeries& header, const Calibration& zcal,
															  const DriveSettings& settings, const HeadingOptions& hopt,
															  double t0_unix_s, bool refine, DriveEvaluation& e);

using app::addFogSample;  // PipelineRate.h
using app::pipelineRate_dph;

/** A FOG observation as a sample, its time relative to epoch_s (the pipeline header's). */
FogSample fogSampleOf(const CObservationFOG& o, double epoch_s);

/** After the drive's last sample: the screening and compensation lines (stdout), the field
 * warning (stderr, appended to e.field_warning), the magnetic term, and the standstill updates
 * into e.refinement. */
void reportCompensation(heading::HeadingPipeline& pipe, const Calibration& zcal, bool log_has_field,
						const DriveSettings& settings, DriveEvaluation& e);

}  // namespace mrpt_fog::drift
