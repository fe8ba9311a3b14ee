/* vehicle-rawlog-gen: a vehicle rawlog as a user's MRPT logger would write it, around a drive's
 * FOG and wheel odometry, written with MRPT's own classes and archive only (none of mrpt_fog's
 * readers or writers; the FOG objects are copied as MRPT deserialises them):
 *
 *   vehicle-rawlog-gen DRIVE.rawlog OUT_PREFIX [--duration-s S] [--repeat N] [--scan-hz H]
 *                      [--map MAP.gridmap.gz] [--seed N] [--obs-only]
 *
 * writes OUT_PREFIX_obs.rawlog (observations-only), OUT_PREFIX_act.rawlog (actions-
 * observations, MRPT's order: each CActionCollection with the CActionRobotMovement2D of one
 * odometry increment, MRPT's default motion model, then the CSensoryFrame of the observations up
 * to that odometry's time) and the drive's GROUND_TRUTH, held back (the vehicle logs have none):
 * OUT_PREFIX_truth.rawlog, and OUT_PREFIX_truth.txt ("time x y yaw" per line, [s] [m] [m] [rad],
 * pf-localization's ground_truth_path_file; it starts at the first truth time that is not a
 * whole second, because pf-localization takes the first column for times only when its first
 * two values are not whole numbers).
 * The vehicle logs hold the drive's metadata comment, FOG 'FOG' and ODOMETRY (FOG_IDEAL and the
 * truth dropped), and at --scan-hz (default 1 Hz) a 2-D lidar 'LIDAR' (CObservation2DRangeScan,
 * 181 rays), and at 1 Hz a GPS 'GPS' (CObservationGPS: GGA + RMC from the truth, a local tangent
 * plane around the drive's latitude), a camera 'CAMERA' (CObservationImage, external image
 * file, not written) and a MEMS IMU 'IMU_MEMS' (CObservationIMU: the truth yaw rate + 0.5 deg/s
 * bias). Without --map the lidar's ranges are synthetic (no world behind them); with --map
 * (an MRPT COccupancyGridMap2D, e.g. fog-localize's map.gridmap.gz) each scan is MRPT's
 * COccupancyGridMap2D::laserScanSimulator at the true pose of its time: 360 deg, 60 m range,
 * range noise 0.05 m from MRPT's random generator seeded with --seed (default 1).
 * --repeat N drives the drive N times in a row (odometry and time continued; for the memory
 * check; not with --map). --obs-only writes the observations-only log and the truth only.
 *
 *   vehicle-rawlog-gen --count FILE.rawlog
 *
 * prints the format and one line per class and label ("COUNT <class> '<label>' <n>"), read with
 * MRPT's archive alone. */
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/maps/COccupancyGridMap2D.h>
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
#include <mrpt/random/RandomGenerators.h>
#include <mrpt/serialization/CArchive.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <map>
#include <memory>
#include <string>
#include <vector>

using namespace mrpt::obs;

namespace
{
constexpr double kR = 6378137.0;

struct Writers
{
	bool with_act;
	mrpt::io::CFileGZOutputStream obs_f, act_f, truth_f;
	std::unique_ptr<mrpt::serialization::CArchive> obs, act, truth;
	std::FILE* truth_txt = nullptr;
	bool truth_txt_started = false;
	CSensoryFrame sf;
	bool have_odo = false;
	mrpt::poses::CPose2D last_odo;
	Writers(const std::string& prefix, bool act_too) : with_act(act_too)
	{
		obs_f.open(prefix + "_obs.rawlog");
		truth_f.open(prefix + "_truth.rawlog");
		obs = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZOutputStream>>(obs_f);
		truth = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZOutputStream>>(truth_f);
		if (with_act)
		{
			act_f.open(prefix + "_act.rawlog");
			act = std::make_unique<mrpt::serialization::CArchiveStreamBase<mrpt::io::CFileGZOutputStream>>(act_f);
		}
		truth_txt = std::fopen((prefix + "_truth.txt").c_str(), "w");
		if (!truth_txt) throw std::runtime_error(prefix + "_truth.txt: cannot open for writing");
	}
	~Writers()
	{
		if (truth_txt) std::fclose(truth_txt);
	}
	/** An observation of the vehicle log, in both formats. */
	void put(const CObservation::Ptr& o)
	{
		*obs << *o;
		if (with_act) sf.insert(o);
	}
	/** The held-back truth, as a rawlog and as pf-localization's text. */
	void putTruth(const CObservationRobotPose& gt)
	{
		*truth << gt;
		const double t = mrpt::Clock::toDouble(gt.timestamp);
		truth_txt_started = truth_txt_started || t != std::floor(t);
		if (truth_txt_started)
			std::fprintf(truth_txt, "%.6f %.6f %.6f %.9f\n", t, gt.pose.mean.x(), gt.pose.mean.y(), gt.pose.mean.yaw());
	}
	/** An odometry sample: in the actions format the action of its increment, then the frame of
	 * the observations since the previous one (the first sample: the frame alone). */
	void odometry(const CObservationOdometry::Ptr& o)
	{
		*obs << *o;
		if (!with_act) return;
		if (have_odo)
		{
			CActionCollection acts;
			CActionRobotMovement2D mv;
			CActionRobotMovement2D::TMotionModelOptions wheel;  // MRPT's default model
			mv.computeFromOdometry(o->odometry - last_odo, wheel);
			mv.timestamp = o->timestamp;
			acts.insert(mv);
			*act << acts;
		}
		if (sf.size()) *act << sf, sf.clear();
		have_odo = true;
		last_odo = o->odometry;
	}
	void finish()
	{
		if (with_act && sf.size()) *act << sf, sf.clear();
	}
};

/** The lidar: synthetic ranges, or MRPT's simulator on a map at the true pose. */
struct Lidar
{
	std::shared_ptr<mrpt::maps::COccupancyGridMap2D> map;
	CObservation2DRangeScan::Ptr scan(mrpt::Clock::time_point stamp, double t, const CObservationRobotPose* truth) const
	{
		auto scan = CObservation2DRangeScan::Create();
		scan->sensorLabel = "LIDAR";
		scan->timestamp = stamp;
		if (map)
		{
			constexpr std::size_t rays = 181;
			constexpr double range_m = 60.0, noise_m = 0.05;
			scan->aperture = static_cast<float>(2 * M_PI * (rays - 1) / rays);  // no ray twice at +-180 deg
			scan->maxRange = static_cast<float>(range_m);
			scan->rightToLeft = true;
			scan->stdError = static_cast<float>(noise_m);
			const auto& m = truth->pose.mean;
			map->laserScanSimulator(*scan, mrpt::poses::CPose2D(m.x(), m.y(), m.yaw()), 0.5f, rays,
									static_cast<float>(noise_m));
			return scan;
		}
		scan->aperture = static_cast<float>(M_PI);
		scan->maxRange = 80.0f;
		scan->resizeScan(181);
		for (std::size_t i = 0; i < 181; i++)
		{
			scan->setScanRange(i, static_cast<float>(10.0 + 5.0 * std::sin(0.1 * i + t)));
			scan->setScanRangeValidity(i, true);
		}
		return scan;
	}
};
}  // namespace

/** --count: the objects of a rawlog by class and label, with MRPT's archive. */
int countObjects(const char* path)
{
	mrpt::io::CFileGZInputStream in(path);
	auto arch = mrpt::serialization::archiveFrom(in);
	std::map<std::string, std::size_t> n;
	bool actions = false;
	const auto key = [](const mrpt::serialization::CSerializable& o) {
		std::string k = o.GetRuntimeClass()->className;
		if (const auto* ob = dynamic_cast<const CObservation*>(&o)) k += " '" + ob->sensorLabel + "'";
		return k;
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
			break;
		}
		n[key(*obj)]++;
		if (auto sf = std::dynamic_pointer_cast<CSensoryFrame>(obj))
		{
			actions = true;
			for (const auto& o : *sf) n[key(*o)]++;
		}
		else if (auto acts = std::dynamic_pointer_cast<CActionCollection>(obj))
		{
			actions = true;
			for (std::size_t i = 0; i < acts->size(); i++) n[key(*acts->get(i))]++;
		}
	}
	std::printf("FORMAT %s\n", actions ? "actions-observations" : "observations-only");
	for (const auto& [k, c] : n) std::printf("COUNT %s %zu\n", k.c_str(), c);
	return 0;
}

int main(int argc, char** argv)
try
{
	if (argc == 3 && !std::strcmp(argv[1], "--count")) return countObjects(argv[2]);
	if (argc < 3)
	{
		std::fprintf(stderr,
					 "usage: vehicle-rawlog-gen DRIVE.rawlog OUT_PREFIX [--duration-s S] [--repeat N] [--scan-hz H] "
					 "[--map MAP.gridmap.gz] [--seed N] [--obs-only]\n");
		return 2;
	}
	double duration_s = INFINITY, scan_hz = 1.0;
	int repeat = 1;
	unsigned seed = 1;
	bool obs_only = false;
	Lidar lidar;
	for (int i = 3; i < argc; i += 2)
	{
		if (!std::strcmp(argv[i], "--obs-only"))
		{
			obs_only = true;
			i--;
			continue;
		}
		if (i + 1 >= argc) throw std::runtime_error(std::string("option ") + argv[i] + " needs a value");
		if (!std::strcmp(argv[i], "--duration-s")) duration_s = std::atof(argv[i + 1]);
		else if (!std::strcmp(argv[i], "--repeat")) repeat = std::atoi(argv[i + 1]);
		else if (!std::strcmp(argv[i], "--scan-hz")) scan_hz = std::atof(argv[i + 1]);
		else if (!std::strcmp(argv[i], "--seed")) seed = static_cast<unsigned>(std::atol(argv[i + 1]));
		else if (!std::strcmp(argv[i], "--map"))
		{
			lidar.map = std::make_shared<mrpt::maps::COccupancyGridMap2D>();
			mrpt::io::CFileGZInputStream mf(argv[i + 1]);
			auto ar = mrpt::serialization::archiveFrom(mf);
			ar >> *lidar.map;
		}
		else throw std::runtime_error(std::string("unknown option ") + argv[i]);
	}
	if (lidar.map && repeat != 1) throw std::runtime_error("--map with --repeat: the repeats are not on the map");
	mrpt::random::getRandomGenerator().randomize(seed);
	Writers w(argv[2], !obs_only);
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
		// The objects of one time stamp (FOG, FOG_IDEAL, ODOMETRY, GROUND_TRUTH) are handled
		// together: a scan on the map is taken at the pose of the truth of its own time.
		std::vector<CObservation::Ptr> group;
		CObservationRobotPose::Ptr group_truth;
		const auto handle = [&](CObservation::Ptr o) {
			const double t = mrpt::Clock::toDouble(o->timestamp) + t_shift;
			if (auto c = std::dynamic_pointer_cast<CObservationComment>(o))
			{
				if (r == 0)
				{
					const auto p = c->text.find("latitude_deg");
					if (p != std::string::npos) lat0_deg = std::atof(c->text.c_str() + c->text.find_first_of("-0123456789", p + 12));
					w.put(o);
				}
				return;
			}
			if (o->sensorLabel == "FOG_IDEAL") return;
			if (auto gt = std::dynamic_pointer_cast<CObservationRobotPose>(o))
			{
				if (r == 0) w.putTruth(*gt);
				prev_truth = truth;
				truth = gt;
				return;
			}
			o->timestamp = shifted(o->timestamp);
			if (auto odo = std::dynamic_pointer_cast<CObservationOdometry>(o))
			{
				if (!any_odo) first_odo = odo->odometry, any_odo = true;
				if (r > 0) odo->odometry = odo_shift + (odo->odometry - first_odo);
				last_odo_r = odo->odometry;
				w.odometry(odo);
				return;
			}
			w.put(o);
			if (o->sensorLabel != "FOG") return;
			fog++;
			// the other sensors, at the FOG sample times
			if (std::isnan(next_scan)) next_scan = t, next_slow = t;
			if (t >= next_scan && (!lidar.map || group_truth))
			{
				w.put(lidar.scan(o->timestamp, t, group_truth.get()));
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
		};
		bool more = true;
		while (more)
		{
			mrpt::serialization::CSerializable::Ptr obj;
			try
			{
				obj = arch.ReadObject();
			}
			catch (const std::exception&)
			{
				more = false;  // end of the file
			}
			auto o = std::dynamic_pointer_cast<CObservation>(obj);
			if (more && !o) continue;
			if (!group.empty() && (!more || o->timestamp != group.front()->timestamp))
			{
				for (const auto& g : group)
					if (auto gt = std::dynamic_pointer_cast<CObservationRobotPose>(g)) group_truth = gt;
				for (const auto& g : group) handle(g);
				group.clear();
			}
			if (!more) break;
			const double t = mrpt::Clock::toDouble(o->timestamp) + t_shift;
			if (std::isnan(t_start)) t_start = t;
			if (t - t_start > duration_s) break;
			t_last = std::max(t_last, t);
			group.push_back(o);
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
