/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file FogOdometryRawlog.h
 * A vehicle rawlog rewritten with the odometry's heading taken from the compensated FOG
 * (fog-odometry): every object is kept, in order and in the input's format; only the wheel
 * odometry changes:
 *  - observations-only format: each CObservationOdometry with the odometry label gets the
 *    dead-reckoned pose (wheel distance, FOG heading; HeadingPipeline.h) as its `odometry`;
 *  - actions-observations format: each CActionRobotMovement2D gets the increment between two
 *    consecutive dead-reckoned poses and the FOG motion model (FogMotionModel.h: a3 = 0, a4 =
 *    the scale-factor uncertainty, minStdPHI from the bias uncertainty); a step with the wheels'
 *    heading (gyro off) gets MRPT's default wheel model. The wheel odometry of this format is
 *    the sum of the actions' rawOdometryIncrementReading at their timestamps. The first action
 *    (the alignment) keeps its increment and model.
 * An odometry sample at or before the previous one's time is written unchanged (counted).
 *
 * Streaming: objects wait in a queue only while an odometry in them waits for the FOG sample
 * after its time (HeadingPipeline.h); memory does not grow with the log.
 *
 * Evaluation: with a truth (CObservationRobotPose with the truth label in the input, or in a
 * separate, held-back rawlog), the FOG odometry's and the wheels' tracks are compared with it
 * (TruthComparison.h: each aligned to the truth at its first pose). */

#include <mrpt_fog/io/RawlogObjectReader.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog_heading/FogMotionModel.h>
#include <mrpt_fog_heading/HeadingPipeline.h>
#include <mrpt_fog_heading/TruthComparison.h>

#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>

namespace mrpt_fog::heading
{
struct FogOdometryOptions
{
	std::string fog_label = "FOG";
	std::string odometry_label = "ODOMETRY";
	/** The drive's latitude: pipeline.latitude_deg, else the FOG's metadata (latitudeOf). */
	PipelineOptions pipeline;
	FogMotionModel motion;
	std::string truth_label = "GROUND_TRUTH";
	std::string truth_path;  //!< a held-back truth rawlog (empty: the truth in the input, if any)
	/** Compare over this long from the first compared pose [s]. */
	double compare_s = std::numeric_limits<double>::infinity();
	/** Called now and then with the bytes read and the file's size (0 when unknown). */
	std::function<void(std::uint64_t bytes_done, std::uint64_t bytes_total)> progress;
};

/** Objects per class and label: "CObservationOdometry 'ODOMETRY'", "CActionRobotMovement2D"... */
using LabelCounts = std::map<std::string, std::size_t>;

struct FogOdometryReport
{
	RawlogFormat format = RawlogFormat::ObservationsOnly;
	std::size_t objects_in = 0, objects_out = 0;
	LabelCounts counts_in, counts_out;
	double latitude_deg = 0.0;
	PipelineCounters pipeline;
	std::optional<CompensationCounters> compensation;
	std::vector<ThermistorHealthCounters> screening;
	CalibrationEarthRate earth;
	std::size_t odometry_rewritten = 0;  //!< odometry observations or actions given the FOG heading
	std::size_t odometry_unchanged = 0;  //!< written as read (time not after the previous one)
	std::optional<TrackErrors> fog_vs_truth, wheels_vs_truth;
	/** The standstill updates of the turn-on bias offset (PipelineOptions::field_refinement;
	 * empty when off or when no standstill beat the prior), and the state at the end. */
	bool field_refinement = false;
	std::vector<nav::StandstillUpdate> standstill_updates;
	bool offset_applied = false;
	double offset_dph = 0.0, offset_sigma_dph = 0.0;
};

/** Reads `input`, writes `output` (atomic). cal: the z-axis calibration (null: the raw FOG
 * rate). Throws FogIoError / std::runtime_error with a one-line message. */
FogOdometryReport writeFogOdometry(const std::string& input, const std::string& output, const Calibration* cal,
								   const FogOdometryOptions& options);

/** The class-and-label key of an observation or action, as LabelCounts uses it. */
std::string labelKey(const mrpt::serialization::CSerializable& obj);
/** Counts an object and what it holds (a sensory frame's observations, a collection's actions). */
void countLabels(const mrpt::serialization::CSerializable& obj, LabelCounts& counts);

}  // namespace mrpt_fog::heading
