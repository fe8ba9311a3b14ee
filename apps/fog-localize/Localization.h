/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file Localization.h
 * MRPT's Monte Carlo localization (mrpt::slam::CMonteCarloLocalization2D + CParticleFilter,
 * standard proposal: the same code path as the pf-localization app) over the world's grid,
 * with one laser scan and one odometry increment per step.
 *
 * Motion model (why not pf-localization's): the odometry's heading comes from the FOG, its
 * distance from the wheels. pf-localization, given an observations-only rawlog, builds
 * CActionRobotMovement2D with MRPT's Gaussian model of which it reads only minStdXY/minStdPHI:
 * the model's a3 = 1 deg of heading noise per metre stays, i.e. 11 deg per 1 s step at 40 km/h,
 * a wheel-odometry heading. Here every action carries its own Gaussian model (an
 * actions-observations rawlog stores it, so pf-localization uses it too on the rawlog written):
 *   heading std per step = minStdPHI (FOG bias uncertainty, see FogMotionModel)
 *                          + a4 * |turn| (scale-factor uncertainty), a3 = 0 (no per-metre term);
 *   position std per step = minStdXY + a1 * distance (wheel distance noise and residual scale).
 *
 * Odometry scale: wheel odometry carries a tyre-radius scale error (0.4 % on the bundled drive)
 * that would dominate every open stretch whatever the gyro. As a vehicle does, the scale is
 * calibrated online from the map-matched stretches: at the end of each urban stretch the
 * filter's own estimated displacements over it (30 s chords from 60 s after its start) are
 * compared with the odometry's, and the accumulated ratio scales the following increments. No
 * truth is used. (One chord over a winding stretch would let the gyro's heading error bias the
 * ratio: 0.056 % on the bundled drive for the raw and compensated gyros, 3 m along the road at
 * the end of a 6 km open field.) */

#include <mrpt_fog_heading/FogMotionModel.h>
#include "GyroOffOdometry.h"
#include "Sensors.h"
#include "World.h"

#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/poses/CPose2D.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mrpt_fog::localize
{
/** A FOG's heading noise and a wheel's distance noise per step (heading/FogMotionModel.h; defaults
 * documented in docs/guide/localization.md). */
using FogMotionModel = heading::FogMotionModel;

/** The motion model of a step without the gyro (GyroOffOdometry.h): MRPT's default Gaussian model,
 * what pf-localization applies to wheel odometry (heading std 0.2 deg + 1 deg per metre driven +
 * 5 % of the turn). */
inline mrpt::obs::CActionRobotMovement2D::TMotionModelOptions wheelOnlyMotionModel() { return heading::wheelMotionModel(); }

/** What the filter does at a turn-on after a gyro-off stretch (GyroOffOdometry.h). */
enum class GyroOffRecovery
{
	Refix,  //!< particles re-drawn around a position and heading fix, as at the start (default)
	None  //!< the particles go on from where the wheel-only steps left them
};
/** "refix" / "none"; throws std::invalid_argument naming the allowed values. */
GyroOffRecovery gyroOffRecoveryFromString(const std::string& text);

struct MclOptions
{
	std::size_t particles = 300;
	FogMotionModel motion;
	/** the steps that touch a gyro-off stretch (StepSource::WheelOnly) */
	mrpt::obs::CActionRobotMovement2D::TMotionModelOptions wheel_only_motion = wheelOnlyMotionModel();
	double init_xy_m = 2.0;  //!< initial particles uniform within +- this of the true start [m]
	double init_yaw_deg = 0.5;  //!< and within +- this of the true heading
	double lf_std_hit_m = 1.0;  //!< likelihood-field hit std (grid 2 m)
	unsigned lf_decimation = 1;  //!< every ray in the likelihood
	double pow_factor = 1.0;  //!< likelihood exponent (< 1 flattens it: rays are not independent)
	/** Roughening after each resampling (Gordon, Salmond & Smith 1993, IEE Proc. F 140(2)): every
	 * particle gets Gaussian jitter of std K * E * N^(-1/d) per dimension, E the particles' range
	 * (max - min) in that dimension, N the particle count, d = 3 (x, y, heading). 0 = off. */
	double roughening_k = 0.0;
	bool calibrate_odometry_scale = true;
	double settle_s = 60.0;  //!< scale calibration ignores the first seconds of an urban stretch
	double chord_s = 30.0;  //!< scale calibration compares displacements over windows of this length
};

struct MclRun
{
	std::vector<double> t_s, x_m, y_m, yaw_rad;  //!< weighted-mean estimate at each scan
	std::vector<double> yaw_std_rad;  //!< the particles' weighted heading standard deviation at each scan
	std::vector<double> odometry_scale;  //!< scale applied at each step
	std::vector<bool> wheel_only;  //!< per scan: reached by a wheel-only step (gyro off)
	std::size_t resamplings = 0;
	std::size_t roughenings = 0;  //!< resamplings followed by roughening
};

/** A fix the particles are re-drawn around (uniformly within init_xy_m / init_yaw_deg, as at
 * the start) right after the scan of index `scan` has been processed. */
struct Refix
{
	std::size_t scan = 0;
	mrpt::poses::CPose2D pose;
};

/** odo: the odometry pose at each scan time (GyroOffOdometry.h): FOG heading + wheel distance,
 * and on the steps marked StepSource::WheelOnly (empty: none) the wheel odometry alone, moved
 * with options.wheel_only_motion instead of the FOG model.
 * The filter starts around start (the true pose at scan_t_s[0], as after a GNSS fix), and is
 * re-drawn around each of `refixes` (in scan order; empty: none).
 * seed seeds MRPT's global random generator (the filter is the only user during the run). */
MclRun runMcl(const World& world, const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans,
			  const std::vector<double>& scan_t_s, const std::vector<mrpt::poses::CPose2D>& odo,
			  const std::vector<StepSource>& step_source, const std::vector<Refix>& refixes,
			  const mrpt::poses::CPose2D& start, const MclOptions& options, std::uint32_t seed);

/** The grid's likelihood options used by runMcl (also written to the .ini). */
void applyLikelihoodOptions(mrpt::maps::COccupancyGridMap2D& grid, const MclOptions& options, double laser_range_m);

}  // namespace mrpt_fog::localize
