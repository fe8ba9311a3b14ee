/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file FieldRefinement.h
 * fog-drift's use of the in-field bias refinement (mrpt_fog_nav/FieldBiasRefiner.h) on the
 * compensated vertical gyro: its settings from the command line and what it reports. It runs
 * inside the library's heading pipeline (mrpt_fog_heading/StandstillCorrection.h; fog-drift's
 * pipelines: VariantPipeline.h), which corrects each sample with what the standstills decided
 * by its time (causal), in both of fog-drift's paths alike. */

#include "DriveData.h"

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/FieldOffset.h>
#include <mrpt_fog_nav/FieldBiasRefiner.h>

#include <string>
#include <vector>

namespace mrpt_fog::drift
{
struct FieldRefinementSettings
{
	bool enabled = true;  //!< --no-field-refinement turns it off
	/** 1-sigma turn-on to turn-on repeatability of the offset [deg/h]: with the thermal model's
	 * uncertainty (the calibration's held-out 100 s stability) it makes the prior's sigma. */
	double turn_on_repeatability_dph = 1.0;
	nav::GyroNoiseModel noise;
	nav::StandstillOptions standstill;
	double min_still_s = 10.0, guard_s = 1.0;
	double significance_sigma = 3.0;  //!< the estimate is applied once it differs from the prior by this many sigma
};

/** What the refinement did on one drive (fog-drift's text and JSON "field_refinement"). */
struct FieldRefinementResult
{
	bool ran = false;  //!< enabled, with a compensated single-axis variant
	std::string note;  //!< why it did not run, or what it did in one line
	double prior_offset_dph = 0, prior_sigma_dph = 0;
	double thermal_sigma_dph = 0;  //!< the thermal model's share of the prior sigma
	double expected_rate_dph = 0;  //!< what the gyro reads while still (Earth rate up)
	std::vector<nav::StandstillUpdate> updates;  //!< absolute times
	std::size_t short_standstills = 0, restarts = 0;
	double offset_dph = 0, offset_sigma_dph = 0;  //!< at the end of the drive
	bool applied = false;  //!< the estimate was applied (significant) by the end of the drive
	double applied_since_s = 0;  //!< absolute time it was first applied in the last turn-on
	double significance_sigma = 3.0;
	/** The calibration file's field offset (fog-refine), applied to the compensated rate at the
	 * drive's date whether or not the standstill updates run; their prior is then the turn-on's
	 * own draw around it. */
	std::optional<FieldOffset> calibration_offset;
	double calibration_offset_at_drive_dph = 0;
};

/** Copies the refiner's updates and final state into `result` (ran = true) and writes its note. */
void noteRefinement(const nav::FieldBiasRefiner& refiner, FieldRefinementResult& result);

/** The text lines fog-drift prints ("" when the refinement did not run and has nothing to say). */
std::string refinementText(const FieldRefinementResult& result, double epoch_s);

}  // namespace mrpt_fog::drift
