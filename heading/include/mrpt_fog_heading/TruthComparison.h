/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file TruthComparison.h
 * A dead-reckoned track against a truth (e.g. CObservationRobotPose GROUND_TRUTH), streamed:
 * both come in time order, each estimate is compared with the truth interpolated at its time
 * (position linear, heading along the shortest arc) and dropped; memory holds only the truth
 * poses not yet passed. Estimates outside the truth's span, or beyond max_duration_s after the
 * first compared one, are not compared (counted).
 *
 * Frames: with align_at_first_estimate the estimate's frame is moved rigidly onto the truth's at
 * the first compared time (an odometry frame against a map frame); otherwise both are in the
 * same frame. Heading error = wrap(estimate - truth) [deg], position error = distance [m]. */

#include <cstddef>
#include <deque>
#include <limits>

namespace mrpt_fog::heading
{
struct TrackErrors
{
	std::size_t compared = 0, not_compared = 0;
	double t_first_s = std::numeric_limits<double>::quiet_NaN(), t_last_s = std::numeric_limits<double>::quiet_NaN();
	double heading_rms_deg = std::numeric_limits<double>::quiet_NaN();
	double heading_max_deg = std::numeric_limits<double>::quiet_NaN();  //!< max |error|
	double heading_final_deg = std::numeric_limits<double>::quiet_NaN();  //!< signed, at the last compared time
	double position_rms_m = std::numeric_limits<double>::quiet_NaN();
	double position_max_m = std::numeric_limits<double>::quiet_NaN();
	double position_final_m = std::numeric_limits<double>::quiet_NaN();
};

class TruthComparison
{
   public:
	explicit TruthComparison(bool align_at_first_estimate = true,
							 double max_duration_s = std::numeric_limits<double>::infinity());
	/** Truth pose at absolute time t_s [s]; times must increase (a repeat is skipped). */
	void addTruth(double t_s, double x_m, double y_m, double yaw_rad);
	/** Estimated pose; times must increase (a repeat is skipped). */
	void addEstimate(double t_s, double x_m, double y_m, double yaw_rad);
	/** The end of both streams: the figures. */
	TrackErrors finish();

   private:
	struct Pose
	{
		double t, x, y, yaw;
	};
	void pump(bool done);
	void compare(const Pose& e, const Pose& truth);

	bool align_;
	double max_duration_s_;
	std::deque<Pose> truth_, est_;
	bool aligned_ = false;
	double dyaw_ = 0, c_ = 1, s_ = 0, tx_ = 0, ty_ = 0;  // estimate frame -> truth frame
	double sum_h2_ = 0, sum_p2_ = 0, max_h_ = 0, max_p_ = 0;
	TrackErrors out_;
};

}  // namespace mrpt_fog::heading
