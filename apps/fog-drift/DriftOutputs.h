/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file DriftOutputs.h
 * fog-drift's outputs: the JSON report (stable keys, see docs/nav.md), the two PNGs
 * (trajectories over the truth; heading error vs time) and the odometry rawlog for MRPT's
 * localization apps. Every file is written atomically. */

#include "DriveEvaluation.h"

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog_nav/DriftReport.h>

#include <map>
#include <string>
#include <vector>

namespace mrpt_fog::drift
{
/** Extra figures recorded in the JSON next to the report. */
struct DriftContext
{
	std::string input;
	std::string calibration;  //!< "" when none
	double latitude_deg = 0.0;
	double earth_rate_removed_dph = 0.0;
	bool transport_rate = false;
	std::string rate_sampling;
	double calibration_earth_rate_dph = 0.0;  //!< vertical Earth rate the calibration's bias held
	std::string calibration_latitude_source;  //!< "option", "calibration", "drive" ("" without calibration)
	JsonValue input_notices;  //!< the reading's notes and unit warnings (LogInput::json)
};

/** The text lines on the drive's gyro-off stretches ("" without any; GyroOff.h). */
std::string gyroOffText(const DriveEvaluation& e);

/** One drive: the report's tables at the top level (as before) plus the navigation figures.
 * Several drives: {"drives": [one object per drive], "over_drives": {figure: spread}}. */
void writeDriftJson(const std::string& path, const std::vector<DriveEvaluation>& drives,
					const std::vector<DriftContext>& ctxs, const std::map<std::string, Spread>& over);

/** Per-sample CSV at the truth times: time_s (from the start), truth_yaw_deg, and per gyro
 * heading_error_<name>_deg and position_error_<name>_m. */
void writeDriftCsv(const std::string& path, const nav::Trajectory& truth, const nav::DriftReport& report);
/** The same CSV from a streamed evaluation's spilled series (DriveEvaluation::spilled). */
void writeDriftCsv(const std::string& path, const SpilledSeries& spilled, const nav::DriftReport& report);

/** trajectories.png and heading_error.png in dir (created if missing). */
void writeDriftPlots(const std::string& dir, const nav::Trajectory& truth, const std::vector<nav::NamedTrajectory>& variants,
					 const nav::DriftReport& report);

/** Observations-only rawlog: CObservationOdometry + CObservationIMU per pose (see
 * mrpt_fog_nav/OdometryRawlog.h), gz-compressed, atomic. */
void writeOdometryRawlog(const std::string& path, const nav::Trajectory& traj, const std::vector<double>& imu_rate_z_rad_s);
/** The same from a streamed evaluation's spilled poses and rates (DriveEvaluation::spilled), the
 * rates interpolated at the poses' times as the in-memory path does; returns the first pose. */
nav::TrajectoryPoint writeOdometryRawlog(const std::string& path, const SpilledSeries& spilled);

}  // namespace mrpt_fog::drift
