/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file LocalizationErrors.h
 * Position and heading error of a filter run against the truth, and their RMS per stretch and
 * per stretch kind, pooled over filter seeds. A run "diverged" when its position error is
 * above divergence_m anywhere in an urban stretch later than recover_s after its start (a
 * map-matched stretch must bring the filter back). */

#include "Localization.h"

#include <map>
#include <string>
#include <vector>

namespace mrpt_fog::localize
{
struct RunErrors
{
	std::vector<double> t_s, position_m, heading_deg;  //!< per scan
	std::vector<double> heading_spread_deg;  //!< the particles' heading standard deviation per scan
	bool diverged = false;
	double max_urban_error_m = 0;  //!< after the recovery time
};

RunErrors computeErrors(const MclRun& run, const nav::Trajectory& truth, const std::vector<Stretch>& stretches,
						double divergence_m = 10.0, double recover_s = 60.0);

/** RMS over all seeds' samples inside one stretch. */
struct StretchFigure
{
	std::size_t index = 0;  //!< into World::stretches
	double position_rms_m = 0, heading_rms_deg = 0, position_max_m = 0;
};

struct GyroSummary
{
	std::map<StretchKind, double> position_rms_m;  //!< pooled over seeds and stretches of the kind
	std::map<StretchKind, double> heading_rms_deg;
	std::vector<StretchFigure> stretches;  //!< every stretch
	std::size_t worst_open = 0;  //!< index of the open stretch with the largest position RMS
	std::vector<double> open_rms_per_seed_m;  //!< open-stretch position RMS of each seed
	std::size_t diverged_runs = 0;
	double position_rms_all_m = 0;
};

GyroSummary summarize(const std::vector<RunErrors>& seeds, const std::vector<Stretch>& stretches);

/** Where an open stretch's heading error comes from. With no observation the filter's mean
 * heading error at time t in the stretch is
 *   e(t) = e(entry)                      what the map-matching left at the stretch's start
 *        + [o(t) - o(entry)]             the gyro's own heading error accrued since (o: the
 *                                        odometry's heading error against the truth)
 *        + w(t)                          the rest: the motion model's heading noise as the
 *                                        particle mean carries it (zero-mean, ~ spread/sqrt(N)),
 * so at the stretch's end: entry, gyro drift and residual walk. Per stretch, over the seeds. */
struct HeadingBudget
{
	std::size_t index = 0;  //!< into World::stretches
	double duration_s = 0, length_m = 0;
	double entry_heading_rms_deg = 0;  //!< RMS over seeds of e(entry)
	double entry_heading_mean_deg = 0;  //!< mean over seeds of e(entry)
	/** RMS over seeds of the particles' heading standard deviation at entry: what the filter
	 * believes its heading error is (well below entry_heading_rms_deg: overconfident). */
	double entry_heading_spread_rms_deg = 0;
	double entry_position_rms_m = 0;  //!< RMS over seeds of the position error at entry
	double gyro_drift_deg = 0;  //!< o(end) - o(entry): the same for every seed
	double walk_rms_deg = 0;  //!< RMS over seeds of e(end) - e(entry) - gyro drift
	double end_heading_rms_deg = 0;  //!< RMS over seeds of e(end)
};

/** odometry_heading_error_deg: the odometry's heading error against the truth at each scan
 * time (the same times as every run's). */
std::vector<HeadingBudget> headingBudget(const std::vector<RunErrors>& seeds, const std::vector<Stretch>& stretches,
										 const std::vector<double>& odometry_heading_error_deg);

}  // namespace mrpt_fog::localize
