/* mrpt_fog: tests of the vehicle scenario. */
#include <gtest/gtest.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/registerAllClasses.h>
#include <mrpt_fog/sim/DriveRun.h>

#include <cmath>
#include <cstdio>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

TEST(DriveRun, DefaultDriveMeetsScenarioRequirements)
{
	SimSettings s;
	s.rate_hz = 2.0;
	const auto cabin = ChamberProfile::preset("drive_cabin");
	const DriveOutput d = simulateDrive(cabin, FogDevice::defaultDevice(), s);
	EXPECT_GE(d.duration_s, 3600.0);
	EXPECT_GE(d.coil_transient_C, 20.0);
	EXPECT_EQ(d.fog.sensor_label, "FOG");
	EXPECT_EQ(d.fog_ideal.sensor_label, "FOG_IDEAL");
	EXPECT_EQ(d.fog.metadataValue("latitude_deg"), "40");
	EXPECT_EQ(d.others.size(), 3 * d.fog.size());

	// Integrated ideal gyro minus Earth rate follows the true heading (noise only: ARW
	// 0.001 deg/sqrt(h) -> ~0.001 deg, quantisation, bias instability 0.003 deg/h x 1 h).
	const double earth_dph = units::kEarthRate_dph * std::sin(40 * units::kDegToRad);
	double yaw_gyro_deg = 0;
	const auto& t = d.fog_ideal.time_s;
	for (std::size_t k = 1; k < t.size(); k++)
		yaw_gyro_deg += (d.fog_ideal.rate_dph[2][k] - earth_dph) * (t[k] - t[k - 1]) / 3600.0;
	auto truth_last = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(d.others.back());
	ASSERT_TRUE(truth_last);
	const double true_yaw_deg = truth_last->pose.mean.yaw() * units::kRadToDeg;
	EXPECT_NEAR(std::remainder(yaw_gyro_deg - true_yaw_deg, 360.0), 0.0, 0.05);

	// The thermal FOG differs from its ideal twin, and odometry drifts from truth (its errors).
	double max_diff = 0;
	for (std::size_t k = 0; k < t.size(); k++)
		max_diff = std::max(max_diff, std::abs(d.fog.rate_dph[2][k] - d.fog_ideal.rate_dph[2][k]));
	EXPECT_GT(max_diff, 0.1);
	auto odo_last = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(d.others[d.others.size() - 2]);
	ASSERT_TRUE(odo_last);
	const double pos_err = std::hypot(odo_last->odometry.x() - truth_last->pose.mean.x(),
									  odo_last->odometry.y() - truth_last->pose.mean.y());
	EXPECT_GT(pos_err, 1.0);
}

TEST(DriveRun, RawlogRoundTripKeepsAllStreams)
{
	registerAllClasses_mrpt_fog();
	SimSettings s;
	s.rate_hz = 1.0;
	const DriveOutput d = simulateDrive(ChamberProfile::preset("drive_cabin"), FogDevice::defaultDevice(), s);
	const std::string path = std::string(FOG_BINARY_DIR) + "/test_drive_roundtrip.rawlog";
	writeFogRawlog(path, d.fog, d.others);
	const FogRawlogContents c = readFogRawlog(path, "FOG");
	std::remove(path.c_str());
	EXPECT_EQ(c.fog.size(), d.fog.size());
	std::size_t ideal = 0, odo = 0, truth = 0;
	for (const auto& o : c.others)
	{
		if (o->sensorLabel == "FOG_IDEAL" && std::dynamic_pointer_cast<CObservationFOG>(o)) ideal++;
		if (o->sensorLabel == "ODOMETRY" && std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o)) odo++;
		if (o->sensorLabel == "GROUND_TRUTH" && std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o)) truth++;
	}
	EXPECT_EQ(ideal, d.fog.size());
	EXPECT_EQ(odo, d.fog.size());
	EXPECT_EQ(truth, d.fog.size());
	EXPECT_EQ(c.fog.metadataValue("sim.seed"), "20240501");
}
