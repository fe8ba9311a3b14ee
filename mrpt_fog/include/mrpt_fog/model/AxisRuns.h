/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AxisRuns.h
 * What the runs of a multi-axis FOG (a triad) give the calibration of one axis.
 *
 * A run serves axis a when it has that axis and either applies no table rate or its table
 * turns about a (metadata `table_axis`, default: the run's first axis): while the table turns
 * about another axis, a's output holds a rotating projection of the Earth rate, neither a bias
 * sample nor a scale-factor sample, so such a run is left out for a (and said so).
 *
 * Earth rate: a run whose metadata states the Earth-rate projection its axis a saw
 * (`earth_rate_dph.<a>`, constant over the run: fog-sim --triad writes it, a lab records it from
 * the mount) has it subtracted from a's output, so that the bias holds no Earth rate (the
 * calibration's earth_rate handling is then in_table_rate). Either every run serving a states it
 * or none does (then the bias holds the Earth rate as before: in_bias); a mix is refused.
 *
 * Each returned series holds axis a alone (the other rate columns dropped), so every single-axis
 * fit (fitCalibration, fitScaleFactor, fitWarmup, evaluateCalibration) applies unchanged. */

#include <mrpt_fog/obs/FogRun.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog
{
struct AxisRunSet
{
	GyroAxis axis = GyroAxis::Z;
	std::vector<FogSeries> runs;  //!< single-axis series for this axis
	std::vector<std::string> labels;  //!< their labels
	std::vector<std::string> skipped;  //!< "<label>: <why>" for each run left out
	bool earth_rate_removed = false;  //!< the runs' stated Earth-rate projections were subtracted
};

/** The axis the run's table turns about: metadata table_axis (x, y or z), else the run's first
 * axis. Throws std::invalid_argument naming the value when it is not an axis letter. */
GyroAxis tableAxis(const FogSeries& run);

/** The axes present in every run, in x, y, z order. */
std::vector<GyroAxis> commonAxes(const std::vector<FogSeries>& runs);

/** The runs' data for calibrating `axis` (see the file comment). With consume, the runs are
 * moved from (cheaper when this is the last axis to calibrate). Throws std::invalid_argument
 * "<label>: <reason>" for a mix of runs with and without earth_rate_dph.<axis>, or a stated
 * value that is not a finite number. */
AxisRunSet runsForAxis(std::vector<FogSeries>& runs, const std::vector<std::string>& labels, GyroAxis axis,
					   bool consume = false);

/** runsForAxis() of runs read in passes (obs/FogRun.h): the same choice and messages,
 * each kept run a FogRun::axisView() sharing the samples (nothing copied). */
struct AxisRunViews
{
	GyroAxis axis = GyroAxis::Z;
	std::vector<FogRun> runs;
	std::vector<std::string> labels;
	std::vector<std::string> skipped;
	bool earth_rate_removed = false;
};
AxisRunViews runsForAxis(const std::vector<FogRun>& runs, const std::vector<std::string>& labels, GyroAxis axis);

/** commonAxes() of runs read in passes. */
std::vector<GyroAxis> commonAxes(const std::vector<FogRun>& runs);

}  // namespace mrpt_fog
