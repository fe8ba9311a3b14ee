/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file LocalizationErrors.h
 * Position and heading error of a filter run against the truth, and their RMS per stretch and
 * per stretch kind, pooled over filter seeds. A run "diverged" when its position error is
 * above divergence_m anywhere in an urban stretch later than recover_s after its start (a
 * map-matched stretch must bring the filter back). */

#include "Localization.h"

#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace mrpt_fog::localize
{
struct RunErrors
{
	std::vector<double> t_s, position_m, heading_deg;  //!< per scan
	std::vector<double> heading_spread_deg;  //!< the particles' heading standard deviation per scan
	/** per scan: reached by a wheel-only step (gyro off): left out of the stretch figures and of
	 * the divergence test (as fog-drift computes its figures on the powered spans), in
	 * WheelOnlyFigures instead */
	std::vector<bool> wheel_only;
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

/** The errors at the scans reached by a wheel-only step (a gyro-off stretch, GyroOffOdometry.h),
 * pooled over the seeds. */
struct WheelOnlyFigures
{
	std::size_t steps = 0;  //!< wheel-only steps of one run
	double position_rms_m = NAN, position_max_m = NAN, heading_rms_deg = NAN;
};
WheelOnlyFigures wheelOnlyFigures(const std::vector<RunErrors>& seeds);

/** Seconds of [t0_s, t1_s] inside stretches of each kind. */
std::map<StretchKind, double> overlapByKind(const std::vector<Stretch>& stretches, double t0_s, double t1_s);

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

/** Whether the open fields can judge a gyro's heading at all ("say plainly when the map makes
 * heading irrelevant"). A heading error's share of an open field's position error is what any
 * gyro improvement can remove; the rest is the map-matching's (the heading and position the
 * filter enters the field with, the same for every gyro). Two measures, both from the run:
 * - per field, the raw gyro's own heading drift over the field against the ideal gyro's entry
 *   heading error (RMS over seeds): below it, the field's heading error at its end is mostly
 *   the map-matching's, whatever the gyro;
 * - over the open fields, the ideal gyro's position RMS over the raw gyro's: the best ratio a
 *   perfect compensation could reach. Above kMaxReachableRatio the "compensated <= 0.5x raw"
 *   target cannot be judged on these fields: "cannot tell", never "missed by the gyro". */
struct FieldRelevance
{
	std::size_t index = 0;  //!< into World::stretches
	double raw_gyro_drift_deg = 0;  //!< raw odometry heading error change over the field
	double ideal_entry_heading_rms_deg = 0;  //!< the map-matching's heading error at entry
	double ideal_to_raw_position_rms = NAN;  //!< this field's ideal / raw position RMS
	bool gyro_dominates = false;  //!< |raw drift| > ideal entry heading RMS
};

struct HeadingRelevance
{
	static constexpr double kMaxReachableRatio = 0.5;  //!< the target ratio compensated / raw (docs/guide/localization.md)
	double ideal_to_raw_position_rms = NAN;  //!< pooled over the open fields and seeds
	bool heading_matters = false;  //!< ideal_to_raw_position_rms <= kMaxReachableRatio
	std::vector<FieldRelevance> fields;
};

/** From the raw and ideal gyros' summaries and heading budgets of the same world and seeds. */
HeadingRelevance headingRelevance(const GyroSummary& raw, const std::vector<HeadingBudget>& raw_budget,
								  const GyroSummary& ideal, const std::vector<HeadingBudget>& ideal_budget);

}  // namespace mrpt_fog::localize
