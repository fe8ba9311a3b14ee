/* makeOdometryObservations: what pf-localization will read. */
#include <gtest/gtest.h>
#include <mrpt/core/Clock.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog_nav/OdometryRawlog.h>

using namespace mrpt_fog::nav;

TEST(OdometryRawlog, InterleavesOdometryAndImu)
{
	Trajectory traj(3);
	for (int k = 0; k < 3; ++k)
	{
		traj[k].t_s = 1.7e9 + 0.1 * k;
		traj[k].x_m = k;
		traj[k].yaw_rad = 0.01 * k;
	}
	const auto obs = makeOdometryObservations(traj);
	ASSERT_EQ(obs.size(), 6u);
	for (int k = 0; k < 3; ++k)
	{
		auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(obs[2 * k]);
		auto imu = std::dynamic_pointer_cast<mrpt::obs::CObservationIMU>(obs[2 * k + 1]);
		ASSERT_TRUE(odo && imu);
		EXPECT_EQ(odo->sensorLabel, "ODOMETRY_FOG");
		EXPECT_EQ(imu->sensorLabel, "IMU_FOG");
		EXPECT_NEAR(odo->odometry.x(), k, 1e-12);
		EXPECT_NEAR(odo->odometry.phi(), 0.01 * k, 1e-12);
		EXPECT_NEAR(mrpt::Clock::toDouble(odo->timestamp), traj[k].t_s, 1e-6);
		EXPECT_NEAR(imu->get(mrpt::obs::IMU_WZ), k == 0 ? 0.0 : 0.1, 1e-6);  // finite difference
	}
	// Serialisation round trip (what a rawlog holds).
	mrpt::io::CMemoryStream buf;
	auto ar = mrpt::serialization::archiveFrom(buf);
	for (const auto& o : obs) ar << *o;
	buf.Seek(0);
	auto back = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(ar.ReadObject());
	ASSERT_TRUE(back);
	EXPECT_NEAR(back->odometry.x(), 0.0, 1e-12);
	EXPECT_THROW(makeOdometryObservations(traj, {1.0}), std::invalid_argument);
}
