/* fog-refine: a calibration that learns its bias offset and aging from field logs. */
#pragma once

/** \file FieldLog.h
 * One field log through the thermal compensation and the standstill updates
 * (mrpt_fog_nav/FieldBiasRefiner.h): what the log says the offset was at its turn-on, relative
 * to the calibration it was compensated with, and how well. */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/FieldOffset.h>
#include <mrpt_fog_nav/FieldBiasRefiner.h>

#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog::refine
{
struct FieldLogSettings
{
	double turn_on_repeatability_dph = 1.0;  //!< prior 1-sigma of a turn-on's offset [deg/h]
	nav::GyroNoiseModel noise;
	nav::StandstillOptions standstill;
	double min_still_s = 10.0, guard_s = 1.0;
	std::optional<double> latitude_deg;  //!< else the log's metadata
	std::string fog_label = "FOG", odometry_label = "ODOMETRY";
};

struct FieldLogOffset
{
	std::string path;
	double t_unix_s = 0;  //!< the log's first FOG sample
	bool measured = false;  //!< at least one standstill update
	/** The offset the log measured, the calibration's field offset at its date included [deg/h],
	 * and its 1-sigma (the filter's, without the turn-on scatter). */
	double offset_dph = 0, sigma_dph = 0;
	double applied_dph = 0;  //!< the calibration's field offset at the log's date (0 without one)
	std::vector<nav::StandstillUpdate> updates;
	std::size_t short_standstills = 0, samples = 0, odometry = 0;
	std::string note;  //!< why nothing was measured
};

/** Compensates the log's vertical FOG with `zcal` (and `previous`, the calibration's field
 * offset, if any) and runs the standstill updates over it (odometry: CObservationOdometry with
 * the settings' label). Throws std::runtime_error naming the file on unreadable input, no z axis
 * or no latitude. */
FieldLogOffset measureFieldLog(const std::string& path, const Calibration& zcal, const std::optional<FieldOffset>& previous,
							   const FieldLogSettings& settings);

/** The calibration's new field offset from the logs' measurements: weighted by 1 / (sigma^2 +
 * repeatability^2) (each turn-on draws its own offset); with logs on at least two dates more
 * than min_span_days apart, a straight line in time (the aging trend), else a constant (the
 * previous trend kept). reference_unix_s: the latest log. Throws std::invalid_argument when no
 * log measured anything. */
FieldOffset combineFieldLogs(const std::vector<FieldLogOffset>& logs, double repeatability_dph,
							 const std::optional<FieldOffset>& previous, double min_span_days = 1.0);

}  // namespace mrpt_fog::refine
