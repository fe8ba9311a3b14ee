/* vehicle-rawlog-gen: a vehicle rawlog as a user's MRPT logger would write it, around a drive's
 * FOG and wheel odometry, written with MRPT's own classes and archive only (none of mrpt_fog's
 * readers or writers; the FOG objects are copied as MRPT deserialises them):
 *
 *   vehicle-rawlog-gen DRIVE.rawlog OUT_PREFIX [--duration-s S] [--repeat N] [--scan-hz H]
 *
 * writes OUT_PREFIX_obs.rawlog (observations-only), OUT_PREFIX_act.rawlog (actions-
 * observations: CActionRobotMovement2D from the odometry increments + CSensoryFrame) and
 * OUT_PREFIX_truth.rawlog (the drive's GROUND_TRUTH, held back: the vehicle logs have none).
 * The vehicle logs hold the drive's metadata comment, FOG 'FOG' and ODOMETRY (FOG_IDEAL and the
 * truth dropped), and at --scan-hz (default 1 Hz) a 2-D lidar 'LIDAR' (CObservation2DRangeScan,
 * 181 rays), and at 1 Hz a GPS 'GPS' (CObservationGPS: GGA + RMC from the truth, a local tangent
 * plane around the drive's latitude), a camera 'CAMERA' (CObservationImage, external image
 * file, not written) and a MEMS IMU 'IMU_MEMS' (CObservationIMU: the truth yaw rate + 0.5 deg/s
 * bias). --repeat N drives the drive N times in a row (odometry and time continued; for the
 * memory check). */
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationGPS.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationImage.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <memory>
#include <string>

using namespace mrpt::obs;

namespace
{
constexpr double kR = 6378137.0;

struct Writers
{
	mrpt::io::CFileGZOutputStream obs_f, act_f, truth_f;
	std::unique_ptr<mrpt::serialization::CArchive> obs, act, truth;
	CSensoryFrame sf;
	bool have_odo = false;
	mrpt::poses::CPose2D last_odo;
	Writers(const std::string& prefix)
		: obs_f(prefix + "_obs.rawlog"), act_f(prefix + "_act.rawlog"), truth_f(prefix + "_truth.rawlog")
	{
		obs = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZOutputStream>>(obs_f);
		act = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZOutputStream>>(act_f);
		truth = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZOutputStream>>(truth_f);
	}
	/** An observation of the vehicle log, in both formats. */
	void put(const CObservation::Ptr& o)
	{
		*obs << *o;
		sf.insert(o);
	}
	void odometry(const CObservationOdometry::Ptr& o)
	{
		*obs << *o;
		if (have_odo)
		{
			if (sf.size()) *act << sf, sf.clear();
			CActionCollection acts;
			CActionRobotMovement2D mv;
			CActionRobotMovement2D::TMotionModelOptions wheel;  // MRPT's default model
			mv.computeFromOdometry(o->odometry - last_odo, wheel);
			mv.timestamp = o->timestamp;
			acts.insert(mv);
			*act << acts;
		}
		have_odo = true;
		last_odo = o->odometry;
	}
	void finish()
	{
		if (sf.size()) *act << sf, sf.clear();
	}
};
}  // namespace

int main(int argc, char** argv)
try
{
	if (argc < 3)
	{
		std::fprintf(stderr, "usage: vehicle-rawlog-gen DRIVE.rawlog OUT_PREFIX [--duration-s S] [--repeat N] [--scan-hz H]\n");
		return 2;
	}
	double duration_s = INFINITY, scan_hz = 1.0;
	int repeat = 1;
	for (int i = 3; i + 1 < argc; i += 2)
	{
		if (!std::strcmp(argv[i], "--duration-s")) duration_s = std::atof(argv[i + 1]);
		else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
		else if (!std::strcmp(argv[i], "--scan-hz")) scan_hz = std::atof(argv[i + 1]);
		else throw std::runtime_error(std::string("unknown option ") + argv[i]);
	}
	Writers w(argv[2]);
	double lat0_deg = 40.0, t_start = NAN, t_shift = 0, t_last = 0;
	mrpt::poses::CPose2D odo_shift;  // moves repeat r's odometry onto the end of repeat r - 1
	std::size_t fog = 0, scans = 0, slow = 0;
	for (int r = 0; r < repeat; r++)
	{
		mrpt::io::CFileGZInputStream in(argv[1]);
		auto arch = mrpt::serialization::archiveFrom(in);
		double next_scan = NAN, next_slow = NAN;
		CObservationRobotPose::Ptr truth, prev_truth;
		mrpt::poses::CPose2D first_odo, last_odo_r;
		bool any_odo = false;
		const auto shifted = [&](mrpt::Clock::time_point t) {
			return mrpt::Clock::fromDouble(mrpt::Clock::toDouble(t) + t_shift);
		};
		for (;;)
		{
			mrpt::serialization::CSerializable::Ptr obj;
			try
			{
				obj = arch.ReadObject();
			}
			catch (const std::exception&)
			{
				break;  // end of the file
			}
			auto o = std::dynamic_pointer_cast<CObservation>(obj);
			if (!o) continue;
			const double t = mrpt::Clock::toDouble(o->timestamp) + t_shift;
			if (std::isnan(t_start)) t_start = t;
			if (t - t_start > duration_s) break;
			t_last = std::max(t_last, t);
			if (auto c = std::dynamic_pointer_cast<CObservationComment>(o))
			{
				if (r == 0)
				{
					const auto p = c->text.find("latitude_deg");
					if (p != std::string::npos) lat0_deg = std::atof(c->text.c_str() + c->text.find_first_of("-0123456789", p + 12));
					w.put(o);
				}
				continue;
			}
			if (o->sensorLabel == "FOG_IDEAL") continue;
			if (auto gt = std::dynamic_pointer_cast<CObservationRobotPose>(o))
			{
				if (r == 0) *w.truth << *gt;
				prev_truth = truth;
				truth = gt;
				continue;
			}
			o->timestamp = shifted(o->timestamp);
			if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(o))
			{
				if (!any_odo) first_odo = odo->odometry, any_odo = true;
				if (r > 0) odo->odometry = odo_shift + (odo->odometry - first_odo);
				last_odo_r = odo->odometry;
				w.odometry(odo);
				continue;
			}
			w.put(o);
			if (o->sensorLabel != "FOG") continue;
			fog++;
			// the other sensors, at the FOG sample times
			if (std::isnan(next_scan)) next_scan = t, next_slow = t;
			if (t >= next_scan)
			{
				auto scan = CObservation2DRangeScan::Create();
				scan->sensorLabel = "LIDAR";
				scan->timestamp = o->timestamp;
				scan->aperture = static_cast<float>(M_PI);
				scan->maxRange = 80.0f;
				scan->resizeScan(181);
				for (std::size_t i = 0; i < 181; i++)
				{
					scan->setScanRange(i, static_cast<float>(10.0 + 5.0 * std::sin(0.1 * i + t)));
					scan->setScanRangeValidity(i, true);
				}
				w.put(scan);
				scans++;
				next_scan += 1.0 / scan_hz;
			}
			if (t >= next_slow && truth)
			{
				const auto& m = truth->pose.mean;
				const double lat = lat0_deg + m.y() / kR * 180.0 / M_PI;
				const double lon = 11.0 + m.x() / (kR * std::cos(lat0_deg * M_PI / 180.0)) * 180.0 / M_PI;
				auto gps = CObservationGPS::Create();
				gps->sensorLabel = "GPS";
				gps->timestamp = o->timestamp;
				gnss::Message_NMEA_GGA gga;
				gga.fields.latitude_degrees = lat;
				gga.fields.longitude_degrees = lon;
				gga.fields.altitude_meters = 500.0;
				gga.fields.fix_quality = 1;
				gga.fields.satellitesUsed = 9;
				gga.fields.thereis_HDOP = true;
				gga.fields.HDOP = 0.9f;
				gps->setMsg(gga);
				double speed = 0, course = 0, yaw_rate = 0;
				if (prev_truth)
				{
					const auto& p = prev_truth->pose.mean;
					const double dt = mrpt::Clock::toDouble(truth->timestamp) - mrpt::Clock::toDouble(prev_truth->timestamp);
					if (dt > 0)
					{
						speed = std::hypot(m.x() - p.x(), m.y() - p.y()) / dt;
						course = std::atan2(m.x() - p.x(), m.y() - p.y()) * 180.0 / M_PI;  // from North, clockwise
						if (course < 0) course += 360.0;
						yaw_rate = std::remainder(m.yaw() - p.yaw(), 2 * M_PI) / dt;
					}
				}
				gnss::Message_NMEA_RMC rmc;
				rmc.fields.validity_char = 'A';
				rmc.fields.latitude_degrees = lat;
				rmc.fields.longitude_degrees = lon;
				rmc.fields.speed_knots = speed * 3600.0 / 1852.0;
				rmc.fields.direction_degrees = course;
				rmc.fields.positioning_mode = 'A';
				gps->setMsg(rmc);
				w.put(gps);
				auto img = CObservationImage::Create();
				img->sensorLabel = "CAMERA";
				img->timestamp = o->timestamp;
				img->image.setExternalStorage("CAMERA_" + std::to_string(slow) + ".png");
				w.put(img);
				auto imu = CObservationIMU::Create();
				imu->sensorLabel = "IMU_MEMS";
				imu->timestamp = o->timestamp;
				imu->set(IMU_WZ, yaw_rate + 0.5 * M_PI / 180.0);
				imu->set(IMU_X_ACC, 0.0);
				imu->set(IMU_Y_ACC, 0.0);
				imu->set(IMU_Z_ACC, 9.81);
				w.put(imu);
				slow++;
				next_slow += 1.0;
			}
		}
		odo_shift = last_odo_r;
		t_shift = t_last + 0.1 - t_start;  // the next repeat starts 0.1 s after the last object
		if (t_last - t_start > duration_s) break;
	}
	w.finish();
	std::printf("vehicle-rawlog-gen: %zu FOG samples, %zu scans, %zu GPS/camera/IMU samples each, %.1f s\n", fog, scans, slow,
				t_last - t_start);
	return 0;
}
catch (const std::exception& e)
{
	std::fprintf(stderr, "vehicle-rawlog-gen: %s\n", e.what());
	return 1;
}
