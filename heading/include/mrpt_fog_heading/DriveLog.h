/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file DriveLog.h
 * A vehicle drive's rawlog read whole into memory, for the evaluations against a truth
 * (fog-drift's in-memory path, fog-localize): the FOG series (label "FOG", with thermal
 * error), the ideal FOG series ("FOG_IDEAL", optional), wheel odometry (CObservationOdometry
 * "ODOMETRY") and the truth (CObservationRobotPose "GROUND_TRUTH"), plus the latitude
 * (metadata latitude_deg or device.latitude_deg). Missing required parts throw
 * std::runtime_error naming the file and what is missing. */

#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <cstdint>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_fog::heading
{
struct DriveLabels
{
	std::string fog = "FOG";
	std::string fog_ideal = "FOG_IDEAL";
	std::string odometry = "ODOMETRY";
	std::string truth = "GROUND_TRUTH";
};

/** The drive has no truth (fewer than 2 poses with the truth label): what can be known without
 * one is heading::compareHeadingsWithoutTruth's. */
class NoTruthError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

struct OdometryPoses
{
	std::vector<double> t_s, x_m, y_m, phi_rad;  //!< cumulative wheel odometry (UNIX time)
};

struct DriveData
{
	FogSeries fog;  //!< with thermal error
	std::optional<FogSeries> fog_ideal;  //!< same noise, no thermal error
	OdometryPoses odometry;
	nav::Trajectory truth;  //!< UNIX-time poses
	std::optional<double> latitude_deg;  //!< from the metadata, when present
};

/** `progress` (optional): called per object read with the FOG samples read, the file bytes consumed
 * and the file's size (0 when unknown). */
DriveData readDrive(const std::string& path, const DriveLabels& labels = {},
					const std::function<void(std::uint64_t samples, std::uint64_t bytes_done, std::uint64_t bytes_total)>&
						progress = {},
					const LogReadOptions& options = {});

/** The latitude [deg] in a series' metadata (latitude_deg, else device.latitude_deg), if any;
 * throws std::runtime_error when the value is not a latitude (latitudeOf in HeadingPipeline.h
 * gives nullopt instead). */
std::optional<double> driveLatitude(const FogSeries& s);

/** Absolute times [s] (epoch_s + time_s) of a series. */
std::vector<double> absoluteTimes(const FogSeries& s);

}  // namespace mrpt_fog::heading
