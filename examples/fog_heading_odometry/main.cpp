/* Example: compensated FOG heading as odometry for MRPT localization, with the installed
 * mrpt_fog package (find_package(mrpt_fog)): fog_heading_odometry DRIVE.rawlog CAL.yaml OUT.rawlog
 * Per observation: the FOG is compensated, the calibration's Earth rate added back, the heading
 * integrated (the drive's Earth rate removed) and dead-reckoned with the wheel odometry; the
 * track goes to OUT.rawlog (CObservationOdometry) and is compared with the truth, if any. */
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/RawlogObjectReader.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog_heading/HeadingPipeline.h>
#include <mrpt_fog_heading/TruthComparison.h>
#include <mrpt_fog_nav/OdometryRawlog.h>

#include <cstdio>

using namespace mrpt_fog;

int main(int argc, char** argv)
try
{
	if (argc != 4) return std::fprintf(stderr, "usage: fog_heading_odometry DRIVE.rawlog CAL.yaml OUT.rawlog\n"), 2;
	const FogSeries header = FogLogReader(argv[1], "FOG").header();  // the FOG's layout and metadata
	const Calibration cal = loadCalibrationYaml(argv[2]);
	heading::PipelineOptions options;
	options.latitude_deg = heading::latitudeOf(header).value();  // the Earth rate depends on it
	heading::HeadingPipeline pipeline(header, options, &cal);
	heading::TruthComparison truth;  // the track moved onto the truth at its first pose
	nav::Trajectory track;
	RawlogObjectReader in(argv[1]);
	while (auto obj = in.next())
	{
		auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj);
		if (auto fog = std::dynamic_pointer_cast<CObservationFOG>(o); fog && o->sensorLabel == "FOG") pipeline.addFog(*fog);
		else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o); odo && o->sensorLabel == "ODOMETRY")
			pipeline.addOdometry(*odo);
		else if (auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o); gt && o->sensorLabel == "GROUND_TRUTH")
			truth.addTruth(mrpt::Clock::toDouble(gt->timestamp), gt->pose.mean.x(), gt->pose.mean.y(), gt->pose.mean.yaw());
		if (!o) continue;
		for (heading::DeadReckonedPose p; pipeline.popPose(p);)
		{
			track.push_back({p.t_s, p.x_m, p.y_m, 0.0, p.heading_rad});
			truth.addEstimate(p.t_s, p.x_m, p.y_m, p.heading_rad);
		}
	}
	pipeline.finish();
	for (heading::DeadReckonedPose p; pipeline.popPose(p);)
		track.push_back({p.t_s, p.x_m, p.y_m, 0.0, p.heading_rad}), truth.addEstimate(p.t_s, p.x_m, p.y_m, p.heading_rad);
	writeRawlogObservations(argv[3], nav::makeOdometryObservations(track));
	std::printf("fog_heading_odometry: %zu poses -> %s; final pose (%.3f, %.3f) m, %.6f deg\n", track.size(), argv[3],
				track.back().x_m, track.back().y_m, track.back().yaw_rad * 180 / M_PI);
	if (const heading::TrackErrors e = truth.finish(); e.compared > 0)
		std::printf("  against the truth: heading error %.6g deg, position error %.6g m\n", e.heading_final_deg, e.position_final_m);
	return 0;
}
catch (const std::exception& e)
{
	std::fprintf(stderr, "fog_heading_odometry: %s\n", e.what());
	return 1;
}
