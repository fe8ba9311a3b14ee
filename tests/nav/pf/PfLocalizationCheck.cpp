/* Integration check of the dead-reckoned odometry rawlog against MRPT's own pf-localization
 * (tests/integration/nav.cmake runs the three steps as ctest tests):
 *
 *   nav_pf_check write DIR     synthesises a drive (figure of eight with speed changes), a
 *                              vertical FOG that senses yaw rate + Earth rate at 40 deg, runs
 *                              StrapdownAttitude + DeadReckoning2D, and writes
 *                              DIR/nav_odometry.rawlog (makeOdometryObservations) and
 *                              DIR/expected_odo.txt (x y phi of every pose, our trajectory)
 *   pf-localization DIR/pf.ini (MRPT's program; writes <logOutput_dir>_000_<N>/odo_est.txt)
 *   nav_pf_check compare DIR ODO_EST_FILE
 *                              odo_est.txt (pf-localization's odometry estimate, one line
 *                              per filter step) must match expected_odo.txt line by line
 *                              within 1e-5 m / 1e-5 rad (odo_est is printed with %f, i.e.
 *                              rounded to 5e-7; the pose composition adds rounding only).
 *   nav_pf_check circle ODO_EST_FILE N RADIUS
 *                              for fog-drift's --odometry-out on the closed-form circle drive
 *                              (tests/nav/drive/TestDrive.cpp): N rows, every pose on the
 *                              circle of RADIUS centred at (0, RADIUS) within 1e-3 m, and the
 *                              last pose back at the origin (4 whole laps) within 1e-3 m.
 * Exit 0 = pass, 1 = mismatch or error (one line on stderr). */
#include <mrpt/core/bits_math.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/EarthModel.h>
#include <mrpt_fog_nav/OdometryRawlog.h>
#include <mrpt_fog_nav/Rotation.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

using namespace mrpt_fog::nav;

namespace
{
constexpr double kT0 = 1.7e9;  // UNIX time of the start [s]
constexpr double kDt = 0.1;  // 10 Hz gyro and odometry
constexpr int kSteps = 600;  // 60 s
constexpr double kLat = 40.0;  // [deg]

int writeCase(const std::string& dir)
{
	// Truth yaw rate: a figure of eight (sinusoidal yaw rate); speed 3..7 m/s.
	auto yawRate = [](double t) { return 0.3 * std::sin(2 * M_PI * t / 40.0); };
	auto speed = [](double t) { return 5.0 + 2.0 * std::sin(2 * M_PI * t / 25.0); };
	const double lat = mrpt::DEG2RAD(kLat);
	const double earth_up = earth::kRotationRate_rad_s * std::sin(lat);

	StrapdownOptions opt;
	opt.latitude_rad = lat;
	opt.sampling = RateSampling::Instantaneous;  // rates evaluated at the sample instants
	StrapdownAttitude att(opt, StrapdownAttitude::Mode::VerticalOnly);
	const double yaw0 = mrpt::DEG2RAD(30.0);
	att.initialize(kT0, quatFromYawPitchRoll(yaw0, 0, 0));
	AttitudeTrack track;
	track.push_back(kT0, att.attitude());
	att.updateRateZ(kT0, yawRate(0) + earth_up);
	std::vector<double> t{kT0}, v{speed(0)}, wz{yawRate(0)};
	for (int k = 1; k <= kSteps; ++k)
	{
		const double tk = k * kDt;
		att.updateRateZ(kT0 + tk, yawRate(tk) + earth_up);  // what the FOG senses
		track.push_back(kT0 + tk, att.attitude());
		t.push_back(kT0 + tk);
		v.push_back(speed(tk));
		wz.push_back(yawRate(tk));
	}
	const Trajectory traj = deadReckon2D(kT0, 10.0, -5.0, odometryFromSpeed(t, v), track);

	const auto obs = makeOdometryObservations(traj, wz);
	{
		mrpt::io::CFileGZOutputStream f(dir + "/nav_odometry.rawlog");
		auto ar = mrpt::serialization::archiveFrom(f);
		for (const auto& o : obs) ar << *o;
	}
	std::ofstream out(dir + "/expected_odo.txt");
	out.precision(12);
	for (const auto& p : traj) out << p.x_m << " " << p.y_m << " " << p.yaw_rad << "\n";
	std::cout << "nav_pf_check: wrote " << traj.size() << " poses, path " << pathLength_m(traj) << " m\n";
	return out ? 0 : 1;
}

std::vector<std::vector<double>> readRows(const std::string& path)
{
	std::ifstream in(path);
	if (!in) throw std::runtime_error("cannot open " + path);
	std::vector<std::vector<double>> rows;
	std::string line;
	while (std::getline(in, line))
	{
		std::istringstream ss(line);
		std::vector<double> r;
		double x;
		while (ss >> x) r.push_back(x);
		if (!r.empty()) rows.push_back(r);
	}
	return rows;
}

int compareCase(const std::string& dir, const std::string& odo_est)
{
	const auto exp = readRows(dir + "/expected_odo.txt");
	const auto got = readRows(odo_est);
	if (got.size() != exp.size())
	{
		std::cerr << "nav_pf_check: " << odo_est << " has " << got.size() << " rows, expected " << exp.size() << "\n";
		return 1;
	}
	double max_pos = 0, max_yaw = 0;
	for (std::size_t k = 0; k < exp.size(); ++k)
	{
		if (got[k].size() < 3)
		{
			std::cerr << "nav_pf_check: " << odo_est << " line " << k + 1 << ": fewer than 3 columns\n";
			return 1;
		}
		max_pos = std::max(max_pos, std::hypot(got[k][0] - exp[k][0], got[k][1] - exp[k][1]));
		max_yaw = std::max(max_yaw, std::abs(wrapToPi(got[k][2] - exp[k][2])));
	}
	std::printf("nav_pf_check: %zu poses, max |position diff| %.3g m, max |yaw diff| %.3g rad\n", exp.size(), max_pos,
				max_yaw);
	return (max_pos < 1e-5 && max_yaw < 1e-5) ? 0 : 1;
}
int circleCase(const std::string& odo_est, std::size_t n, double radius)
{
	const auto got = readRows(odo_est);
	if (got.size() != n)
	{
		std::cerr << "nav_pf_check: " << odo_est << " has " << got.size() << " rows, expected " << n << "\n";
		return 1;
	}
	double max_dev = 0;
	for (const auto& r : got) max_dev = std::max(max_dev, std::abs(std::hypot(r.at(0), r.at(1) - radius) - radius));
	const double end = std::hypot(got.back()[0], got.back()[1]);
	std::printf("nav_pf_check: %zu poses, max distance from the circle %.3g m, end %.3g m from the origin\n", n,
				max_dev, end);
	return (max_dev < 1e-3 && end < 1e-3) ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		const std::string mode = argc > 2 ? argv[1] : "";
		if (mode == "write" && argc == 3) return writeCase(argv[2]);
		if (mode == "compare" && argc == 4) return compareCase(argv[2], argv[3]);
		if (mode == "circle" && argc == 5) return circleCase(argv[2], std::stoul(argv[3]), std::stod(argv[4]));
		std::cerr << "usage: nav_pf_check write DIR | compare DIR ODO_EST_FILE | circle ODO_EST_FILE N RADIUS\n";
		return 2;
	}
	catch (const std::exception& e)
	{
		std::cerr << "nav_pf_check: error: " << e.what() << "\n";
		return 1;
	}
}
