/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file DriveRun.h
 * The vehicle scenario: a ground vehicle drives a DriveTrajectory (exact truth) while its cabin
 * follows a ChamberProfile (default preset `drive_cabin`: winter cold start, the gyro powered at
 * t = 0 from an unpowered cold soak, so ambient change and self-heating give a coil transient of
 * more than 20 C). A level z-axis FOG measures yaw rate + the vertical Earth rate
 * (15.041 deg/h x sin(latitude)); wheel odometry integrates distance and heading with scale
 * errors and noise.
 *
 * Outputs (all timestamps epoch_s + t):
 *  - fog: label "FOG", the gyro with every enabled thermal error;
 *  - fog_ideal: label "FOG_IDEAL", the same noise realisation without thermal error;
 *  - others: CObservationFOG "FOG_IDEAL" samples, CObservationOdometry "ODOMETRY" (cumulative
 *    pose2D + local velocities) and CObservationRobotPose "GROUND_TRUTH" (true 3D pose, zero
 *    covariance), in time order.
 * Metadata: latitude_deg, sim.* (as chamber runs) and drive.* (odometry errors, coil transient). */

#include <mrpt/obs/CObservation.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/DriveTrajectory.h>
#include <mrpt_fog/sim/FogDevice.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <functional>
#include <vector>

namespace mrpt_fog::sim
{
/** Wheel-odometry errors (estimates for a car's wheel-speed odometry). */
struct OdometryErrors
{
	double scale_error = 0.004;  //!< distance scale error (tyre radius, 0.4 %)
	double yaw_scale_error = 0.01;  //!< heading-increment scale error (track width, 1 %)
	double distance_noise_m_rt_m = 0.002;  //!< white noise on distance [m per sqrt(m)]
	double yaw_noise_rad_rt_m = 2e-4;  //!< white noise on heading [rad per sqrt(m)]
};

struct DriveOutput
{
	FogSeries fog;
	FogSeries fog_ideal;
	std::vector<mrpt::obs::CObservation::Ptr> others;  //!< FOG_IDEAL, ODOMETRY, GROUND_TRUTH
	double coil_transient_C = 0;  //!< max - min of the coil mean temperature [degC]
	double duration_s = 0;
};

/** One step of a drive as simulateDrive() records it: the FOG sample (with the ideal twin's
 * rate), the applied table rate, the wheel odometry (cumulative pose and local velocities) and
 * the planar truth (yaw wrapped to (-pi, pi]). */
struct DriveRecord
{
	double t_s = 0;
	FogSample sample;
	double table_rate_dph = 0;
	double odo_x_m = 0, odo_y_m = 0, odo_yaw_rad = 0, odo_v_mps = 0, odo_w_rad_s = 0;
	double truth_x_m = 0, truth_y_m = 0, truth_yaw_rad = 0;
	double epoch_s = kSimEpoch_s;  //!< absolute time of t = 0 (FogDevice::epoch_s)
};
/** Called per step, in order; return false to be called no more (the simulation still runs to
 * the end, for the coil transient). */
using DriveStepSink = std::function<bool(const DriveRecord&)>;

/** simulateDrive()'s steps one at a time (a long drive need not be held); returns the
 * coil's thermal transient over the whole drive (max - min of the coil mean temperature). */
double simulateDriveSteps(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
						  const OdometryErrors& odo, const DriveStepSink& f);
/** Samples of a drive: floor(duration * rate + 1e-9) + 1. */
std::size_t driveSampleCount(const ChamberProfile& cabin, const SimSettings& settings);
/** The FOG series of simulateDrive() without samples: layout and metadata (which holds the
 * coil transient, known after the whole drive). */
FogSeries driveRunHeader(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
						 const OdometryErrors& odo, double coil_transient_C);
/** The ODOMETRY and GROUND_TRUTH observations of a step, as simulateDrive() makes them. */
mrpt::obs::CObservation::Ptr odometryObservation(const DriveRecord& r);
mrpt::obs::CObservation::Ptr truthObservation(const DriveRecord& r);

/** Simulates the drive over the cabin profile's duration (> 130 s). */
DriveOutput simulateDrive(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
						  const OdometryErrors& odo = {});

/** One step of simulateDrive()'s loop (also what tools replaying a drive with the simulator's
 * state call): t = k / rate_hz, the vehicle's planar truth there, the cabin state the FOG sees
 * (the mean applied yaw rate over (t - 1/rate_hz, t] from the heading truth, no field) and the
 * FOG sample (the simulator started at k = 0, else advanced one step). `prev` is the previous
 * step's planar state (unused at k = 0). */
struct DriveStep
{
	double t_s = 0;
	PlanarState now;
	ChamberState chamber;
	FogSample sample;
};
DriveStep driveStep(std::size_t k, double rate_hz, const DriveTrajectory& traj, const ChamberProfile& cabin,
					FogSimulator& sim, const PlanarState& prev);

}  // namespace mrpt_fog::sim
