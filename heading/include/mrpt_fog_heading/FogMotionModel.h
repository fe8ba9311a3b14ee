/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file FogMotionModel.h
 * The motion model of an odometry step whose heading is a FOG's, for MRPT's particle filters
 * (CActionRobotMovement2D, Gaussian model; docs/guide/localization.md "The filter"):
 *  - heading std per step = minStdPHI + a4 |turn|, a3 = 0 (no heading noise per metre: the
 *    heading is not the wheels'). minStdPHI = b sqrt(dt T): a random walk whose spread after T
 *    equals the drift of a constant bias b; a4 = the scale-factor uncertainty [rad/rad];
 *  - position std per step = minStdXY + a1 x distance.
 * MRPT's default model (wheelMotionModel) is what pf-localization applies to wheel odometry:
 * heading std 0.2 deg + 1 deg per metre driven + 5 % of the turn. */

#include <mrpt/obs/CActionRobotMovement2D.h>

namespace mrpt_fog::heading
{
struct FogMotionModel
{
	double heading_bias_dph = 0.5;  //!< FOG bias uncertainty the filter allows [deg/h]
	double horizon_s = 60.0;  //!< time over which the heading random walk matches a constant bias of that size [s]
	double scale_factor_ppm = 2000.0;  //!< heading error per turned angle [ppm]
	double distance_frac = 0.003;  //!< distance std per metre driven [-]
	double min_std_xy_m = 0.05;  //!< position std per step [m]

	/** MRPT's Gaussian model for a step of dt_s [s]. */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions toMrpt(double dt_s) const;
};

/** MRPT's default Gaussian model (wheel odometry without a gyro). */
mrpt::obs::CActionRobotMovement2D::TMotionModelOptions wheelMotionModel();

}  // namespace mrpt_fog::heading
