/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file DriftReport.h
 * How far a dead-reckoned trajectory drifts from the truth, for any number of named gyro
 * variants on the same drive (e.g. "raw", "compensated", "ideal").
 *
 * Each variant is interpolated at the truth's timestamps inside the variant's time span.
 * Heading error = wrap(yaw_variant - yaw_truth) [deg]; position error = Euclidean distance
 * [m]. "final" is the magnitude at the last common time, "max" the largest magnitude over
 * the run; the position error is also given in % of the distance travelled (truth path
 * length). Throws std::invalid_argument when the truth has fewer than 2 points or a variant
 * does not overlap it in time. */

#include <mrpt_fog_nav/Trajectory.h>

#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog::nav
{
struct DriftSeries
{
	std::string name;
	std::vector<double> t_s;  //!< evaluation times (truth timestamps)
	std::vector<double> heading_error_deg;  //!< signed
	std::vector<double> position_error_m;

	double heading_error_final_deg = 0.0;  //!< |error| at the last time
	double heading_error_max_deg = 0.0;  //!< max |error|
	double heading_error_final_signed_deg = 0.0;
	double position_error_final_m = 0.0;
	double position_error_max_m = 0.0;
	double position_error_final_pct = 0.0;  //!< final / distance travelled * 100
	double position_error_max_pct = 0.0;
};

struct DriftReport
{
	double distance_m = 0.0;  //!< truth path length
	double duration_s = 0.0;  //!< truth time span
	std::vector<DriftSeries> variants;

	/** Variant by name; throws std::out_of_range when absent. */
	const DriftSeries& variant(const std::string& name) const;
};

using NamedTrajectory = std::pair<std::string, Trajectory>;

DriftReport computeDriftReport(const Trajectory& truth, const std::vector<NamedTrajectory>& variants);

}  // namespace mrpt_fog::nav
