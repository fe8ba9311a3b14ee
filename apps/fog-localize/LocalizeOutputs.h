/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file LocalizeOutputs.h
 * fog-localize's outputs: the text summary, the JSON (stable keys, docs/guide/localization.md), the
 * plots (map.png: the world and the stretches; errors.png: position and heading error vs
 * time per gyro), and what MRPT's pf-localization app needs to rerun a gyro's case: the map
 * (map.gridmap.gz), an actions-observations rawlog per gyro, an .ini per gyro and the ground
 * truth as text. Every file is written atomically. */

#include "CalibrationChoice.h"
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog_heading/PowerSpans.h>
#include "Localization.h"
#include "LocalizationErrors.h"
#include "Sensors.h"
#include "World.h"

#include <string>
#include <vector>

namespace mrpt_fog::localize
{
struct GyroResult
{
	std::string name;
	std::vector<unsigned> seeds;
	std::vector<RunErrors> runs;  //!< per seed
	std::vector<double> final_scale;  //!< odometry scale calibrated by the end, per seed
	GyroSummary summary;
	std::vector<HeadingBudget> heading_budget;  //!< per open stretch
	MclRun first_run;  //!< the first seed's estimate (for the plots)
	std::vector<mrpt::poses::CPose2D> odometry;  //!< at the scan times (for the rawlog)
	std::vector<StepSource> odometry_step;  //!< what moved each step (GyroOffOdometry.h)
	WheelOnlyFigures wheel_only;  //!< the errors after the steps without the gyro
	std::size_t refixes = 0;  //!< re-initialisations at turn-ons
};

struct LocalizeResults
{
	std::string drive;
	JsonValue input_notices;  //!< the reading's notes and unit warnings (LogInput::json)
	CalibrationChoice calibration;  //!< what compensated the FOG
	double t0_s = 0, runtime_s = 0;
	std::vector<GyroResult> gyros;  //!< raw, compensated, ideal
	HeadingRelevance relevance;  //!< whether the open fields can judge a gyro's heading
	std::vector<heading::GyroOffStretch> gyro_off;  //!< the FOG's gyro-off stretches (absolute s)
	GyroOffRecovery gyro_off_recovery = GyroOffRecovery::Refix;
	std::vector<std::map<StretchKind, double>> gyro_off_overlap_s;  //!< per stretch: seconds in each stretch kind
};

/** wheel_model: the motion model of the wheel-only steps (MclOptions::wheel_only_motion). */
void printSummary(const LocalizeResults& r, const World& world,
				  const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions::TOptions_GaussianModel& wheel_model);

void writeOutputs(const std::string& dir, const std::string& json_path, const LocalizeResults& r, const World& world,
				  const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans, const std::vector<double>& scan_t_s,
				  const nav::Trajectory& truth, const MclOptions& mcl, const LaserOptions& laser);

}  // namespace mrpt_fog::localize
