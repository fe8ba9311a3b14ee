/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file TruthAlignedDeadReckoning.h
 * A whole drive in memory (DriveLog.h) dead-reckoned against its truth, for the evaluations
 * (fog-drift's in-memory path); HeadingPipeline.h is the streaming form without a
 * truth. One gyro variant through the navigation chain: vertical FOG rate [deg/h] ->
 * StrapdownAttitude (VerticalOnly, Earth rate at the drive's latitude removed) -> heading ->
 * DeadReckoning2D with the wheel odometry distances. Starts from the truth pose (position and
 * heading) at the first common time, as an aligned vehicle would.
 * With a triad (x, y and z rates): StrapdownAttitude ThreeAxis (the full Earth rate removed),
 * started from the truth attitude; the heading for dead reckoning is the 3-D attitude's yaw,
 * and roll and pitch are kept for the attitude figures. */

#include <mrpt_fog_heading/DriveLog.h>

#include <mrpt_fog_nav/StrapdownAttitude.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <limits>
#include <vector>

namespace mrpt_fog::heading
{
struct HeadingOptions
{
	double latitude_deg = 0.0;
	bool transport_rate = false;  //!< the simulator's drive is flat-Earth: off by default
	nav::RateSampling sampling = nav::RateSampling::IntervalAverage;  //!< fog-sim: mean over (t - dt, t]
	/** false: VariantResult::t_s and yaw_rate_rad_s are left empty (not needed: memory) */
	bool keep_rates = true;
	/** Navigate only within [window_t0_s, window_t1_s] (absolute s): one powered span of a drive
	 * with the gyro off in places (GyroOff.h), aligned from the truth at its start. */
	double window_t0_s = -std::numeric_limits<double>::infinity();
	double window_t1_s = std::numeric_limits<double>::infinity();
	/** true: fewer than 2 odometry samples inside the gyro's span give an empty trajectory
	 * (a powered span too short to navigate) instead of an error */
	bool empty_if_no_odometry = false;
};

struct VariantResult
{
	nav::Trajectory trajectory;  //!< dead-reckoned, at odometry times (fog-drift's evaluation moves it on)
	std::vector<double> t_s;  //!< gyro sample times used
	std::vector<double> yaw_rate_rad_s;  //!< gyro rate with the Earth rate removed (for the rawlog)
	std::vector<double> roll_rad, pitch_rad;  //!< triad only: the attitude at t_s
};

/** t_s: absolute sample times [s]; rate_dph: vertical gyro output [deg/h] (same size).
 * Throws std::runtime_error when the gyro, odometry and truth do not overlap in time. */
VariantResult deadReckonVariant(const std::vector<double>& t_s, const std::vector<double>& rate_dph,
								const DriveData& drive, const HeadingOptions& options);

/** The same for a triad: rate_x/y/z_dph [deg/h] (body x forward, y left, z up). */
VariantResult deadReckonVariant(const std::vector<double>& t_s, const std::vector<double>& rate_x_dph,
								const std::vector<double>& rate_y_dph, const std::vector<double>& rate_z_dph,
								const DriveData& drive, const HeadingOptions& options);

/** Roll and pitch [rad] of q_nb (yaw-pitch-roll convention of nav::quatFromYawPitchRoll). */
double rollOf(const Eigen::Quaterniond& q_nb);
double pitchOf(const Eigen::Quaterniond& q_nb);

}  // namespace mrpt_fog::heading
