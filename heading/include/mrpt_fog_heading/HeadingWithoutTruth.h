/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file HeadingWithoutTruth.h
 * What a vehicle rawlog without a truth can tell about the compensation (fog-drift on a real
 * vehicle's log). Two heading pipelines run on the same FOG samples, raw and compensated, both
 * started at 0 at the first FOG sample; their difference d(t) = compensated - raw heading is what
 * the compensation changed. Turns and straights are found on the compensated rate (1 s blocks:
 * |rate| > turn_rate_dps a turn; < straight_rate_dps for >= min_straight_s a straight):
 *  - per turn: the turned angle and the change of d over it;
 *  - per straight: the slope of d [deg/h] (the bias the compensation removed there), and the
 *    pooled slope over all straights;
 * which heading is right cannot be told without a reference. With GPS (CObservationGPS with an
 * RMC message, or GGA positions) the course over ground above gps_min_speed_mps is one: each
 * heading is compared with it after removing the constant offset between the heading's frame
 * (started at 0) and North (the mean difference), and the RMS about that offset and its slope
 * [deg/h] are given for both. The course is the direction of travel, not the vehicle's heading
 * (side slip, reversing): a reference good to about a degree, not to the compensation's
 * thousandths.
 *
 * Any rawlog, either format (RawlogObjectReader). Streaming: memory does not grow with the log.
 * Throws FogIoError / std::runtime_error with a one-line message. */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog_heading/HeadingPipeline.h>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog::heading
{
struct NoTruthOptions
{
	std::string fog_label = "FOG";
	PipelineOptions pipeline;  //!< latitude_deg NaN: from the FOG's metadata
	double turn_rate_dps = 1.0;
	double straight_rate_dps = 0.2;
	double min_straight_s = 30.0;
	double gps_min_speed_mps = 5.0;  //!< course over ground used above this speed [m/s]
};

struct TurnDifference
{
	double t0_s = 0, t1_s = 0;
	double turned_deg = 0;  //!< compensated heading change over the turn
	double difference_change_deg = 0;  //!< change of (compensated - raw) over the turn
};

struct StraightDifference
{
	double t0_s = 0, t1_s = 0;
	double difference_slope_dph = 0;  //!< slope of (compensated - raw) [deg/h]
};

struct CourseFigures
{
	std::size_t fixes = 0;  //!< GPS courses used
	double raw_rms_deg = std::numeric_limits<double>::quiet_NaN();  //!< about the mean offset
	double compensated_rms_deg = std::numeric_limits<double>::quiet_NaN();
	double raw_slope_dph = std::numeric_limits<double>::quiet_NaN();  //!< slope of heading - course
	double compensated_slope_dph = std::numeric_limits<double>::quiet_NaN();
	bool from_rmc = false;  //!< RMC course (else from consecutive GGA positions)
};

struct NoTruthReport
{
	double latitude_deg = 0;
	CalibrationEarthRate earth;
	std::size_t fog_samples = 0;
	double start_s = 0;  //!< the first FOG sample's time [s] (times below are absolute)
	double duration_s = 0;
	double final_difference_deg = 0;  //!< compensated - raw heading at the end
	std::vector<TurnDifference> turns;
	std::vector<StraightDifference> straights;
	double pooled_slope_dph = std::numeric_limits<double>::quiet_NaN();  //!< over the straights
	std::optional<CourseFigures> gps;  //!< when the log has usable GPS courses
};

NoTruthReport compareHeadingsWithoutTruth(const std::string& path, const Calibration& cal, const NoTruthOptions& options);

}  // namespace mrpt_fog::heading
