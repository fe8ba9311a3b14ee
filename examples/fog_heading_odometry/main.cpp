/* Example: compensated FOG heading as odometry for MRPT localization, with the installed
 * mrpt_fog package (find_package(mrpt_fog)).
 *
 *   fog_heading_odometry DRIVE.rawlog CAL.yaml OUT.rawlog
 *
 * 1. read a drive rawlog (CObservationFOG "FOG", CObservationOdometry "ODOMETRY", optional
 *    CObservationRobotPose "GROUND_TRUTH") with the library's checked reader;
 * 2. compensate the gyro's thermal bias with the calibration (causal Compensator);
 * 3. integrate heading with StrapdownAttitude: FOG samples are interval averages, the Earth
 *    rate the static calibration absorbed (at the latitude the calibration file records) is
 *    added back once, and the Earth rate at the drive's latitude is removed by the attitude
 *    update;
 * 4. dead-reckon with the wheel distances and write CObservationOdometry for pf-localization.
 * Prints the final heading and position error when the drive has a ground truth. */
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/OdometryRawlog.h>
#include <mrpt_fog_nav/Rotation.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>

#include <cmath>
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

using namespace mrpt_fog;

int main(int argc, char** argv)
try
{
	if (argc != 4)
	{
		std::fprintf(stderr, "usage: fog_heading_odometry DRIVE.rawlog CAL.yaml OUT.rawlog\n");
		return 2;
	}
	const std::string drive_path = argv[1], cal_path = argv[2], out_path = argv[3];

	// 1. The drive: FOG series + odometry + truth.
	const FogRawlogContents drive = readFogRawlog(drive_path, "FOG");
	std::vector<double> odo_t, odo_x, odo_y, odo_phi;
	nav::Trajectory truth;
	for (const auto& o : drive.others)
	{
		const double t = mrpt::Clock::toDouble(o->timestamp);
		if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o); odo && o->sensorLabel == "ODOMETRY")
		{
			if (!odo_t.empty() && !(t > odo_t.back())) continue;
			odo_t.push_back(t);
			odo_x.push_back(odo->odometry.x());
			odo_y.push_back(odo->odometry.y());
			odo_phi.push_back(odo->odometry.phi());
		}
		else if (auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o); gt && o->sensorLabel == "GROUND_TRUTH")
		{
			if (!truth.empty() && !(t > truth.back().t_s)) continue;
			nav::TrajectoryPoint p;
			p.t_s = t;
			p.x_m = gt->pose.mean.x();
			p.y_m = gt->pose.mean.y();
			p.yaw_rad = gt->pose.mean.yaw();
			p.q_nb = nav::quatFromYawPitchRoll(p.yaw_rad, 0, 0);
			truth.push_back(p);
		}
	}
	if (odo_t.size() < 2) throw std::runtime_error(drive_path + ": fewer than 2 ODOMETRY observations");
	const std::string lat_text = drive.fog.metadataValue("latitude_deg");
	if (lat_text.empty()) throw std::runtime_error(drive_path + ": no latitude_deg in the FOG metadata");
	const double lat_deg = std::stod(lat_text);

	// 2. Compensation (z gyro). A static calibration's bias holds the vertical Earth rate at the
	// calibration site; the file (version 2) records that site's latitude and how the Earth rate
	// was handled, so it is added back exactly once. A file without a latitude (version 1, or
	// runs without latitude_deg) is taken as made at the drive's latitude, and says so.
	const Calibration cal = loadCalibrationYaml(cal_path);
	const CompensatedSeries comp = compensate(cal, drive.fog);  // feeds the log's field to a magnetic term
	if (const std::string w = fieldMissingWarning(cal, drive.fog); !w.empty())
		std::fprintf(stderr, "fog_heading_odometry: warning: %s\n", w.c_str());
	double cal_earth_dph = 0.0;
	if (cal.earth_rate == EarthRateHandling::InBias)
	{
		double cal_lat_deg = cal.latitude_deg;
		if (!std::isfinite(cal_lat_deg))
		{
			cal_lat_deg = lat_deg;
			std::printf("fog_heading_odometry: %s records no latitude: assuming the drive's %.4f deg\n", cal_path.c_str(),
						lat_deg);
		}
		cal_earth_dph = units::kEarthRate_dph * std::sin(cal_lat_deg * units::kDegToRad);
	}

	// 3. Heading: start from the truth (an aligned vehicle) or zero.
	nav::StrapdownOptions so;
	so.latitude_rad = lat_deg * units::kDegToRad;
	so.sampling = nav::RateSampling::IntervalAverage;  // fog-sim and digital FOGs
	nav::StrapdownAttitude att(so, nav::StrapdownAttitude::Mode::VerticalOnly);
	const double t0 = std::max(drive.fog.epoch_s + drive.fog.time_s.front(), odo_t.front());
	const double yaw0 = truth.empty() ? 0.0 : nav::interpolate(truth, t0).yaw_rad;
	att.initialize(t0, nav::quatFromYawPitchRoll(yaw0, 0, 0));
	nav::AttitudeTrack track;
	track.push_back(t0, att.attitude());
	for (std::size_t k = 0; k < drive.fog.size(); ++k)
	{
		const double t = drive.fog.epoch_s + drive.fog.time_s[k];
		if (t < t0) continue;
		att.updateRateZ(t, (comp.compensated_dph[k] + cal_earth_dph) * units::kDegPerHourToRadPerSec);
		if (t > track.backTime()) track.push_back(t, att.attitude());
	}

	// 4. Dead reckoning with the wheel distances, written as CObservationOdometry.
	std::vector<double> t, x, y, p;
	for (std::size_t k = 0; k < odo_t.size(); ++k)
		if (odo_t[k] >= t0 && odo_t[k] <= track.backTime())
		{
			t.push_back(odo_t[k]);
			x.push_back(odo_x[k]);
			y.push_back(odo_y[k]);
			p.push_back(odo_phi[k]);
		}
	const nav::TrajectoryPoint start = truth.empty() ? nav::TrajectoryPoint{} : nav::interpolate(truth, t.front());
	const nav::Trajectory traj =
		nav::deadReckon2D(t.front(), start.x_m, start.y_m, nav::odometryFromPoses2D(t, x, y, p), track);
	writeRawlogObservations(out_path, nav::makeOdometryObservations(traj));

	const auto& end = traj.back();
	std::printf("fog_heading_odometry: %zu poses -> %s; final pose (%.3f, %.3f) m, %.6f deg\n", traj.size(),
				out_path.c_str(), end.x_m, end.y_m, end.yaw_rad * units::kRadToDeg);
	if (!truth.empty())
	{
		const auto tr = nav::interpolate(truth, end.t_s);
		std::printf("  against the truth: heading error %.6g deg, position error %.6g m\n",
					nav::wrapToPi(end.yaw_rad - tr.yaw_rad) * units::kRadToDeg, std::hypot(end.x_m - tr.x_m, end.y_m - tr.y_m));
	}
	return 0;
}
catch (const std::exception& e)
{
	std::fprintf(stderr, "fog_heading_odometry: %s\n", e.what());
	return 1;
}
