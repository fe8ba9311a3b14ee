/* DeadReckoning against closed-form paths: a circle (2D), a circle in a tilted plane (3D). */
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/Rotation.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>

#include <cmath>

using namespace mrpt_fog::nav;

namespace
{
// Circle: speed v [m/s], yaw rate r [rad/s], radius R = v / r, starting at the origin heading
// East: x = R sin(r t), y = R (1 - cos(r t)), yaw = r t.
constexpr double kV = 5.0, kR = 0.1, kRadius = kV / kR;
}  // namespace

// Odometry at 10 Hz and a gyro attitude integrated by StrapdownAttitude from the exact
// (constant) yaw rate: for a constant rate both the trapezoid and the arc model of the dead
// reckoning are exact, so after 1.5 laps (94 s, 471 m) the position must match the closed
// form to rounding (1e-8 m) and the heading to 1e-10 rad.
TEST(DeadReckoning, Circle2D_FromGyro)
{
	StrapdownOptions opt;
	opt.remove_earth_rate = false;
	opt.sampling = RateSampling::Instantaneous;
	StrapdownAttitude att(opt, StrapdownAttitude::Mode::VerticalOnly);
	const double dt = 0.1, duration = 3 * M_PI / kR;
	const int n = static_cast<int>(duration / dt);
	att.initialize(0.0, Eigen::Quaterniond::Identity());
	AttitudeTrack track;
	track.push_back(0.0, att.attitude());
	std::vector<double> t, v;
	t.push_back(0.0);
	v.push_back(kV);
	for (int k = 1; k <= n; ++k)
	{
		att.updateRateZ(k * dt, kR);
		track.push_back(k * dt, att.attitude());
		t.push_back(k * dt);
		v.push_back(kV);
	}
	const Trajectory traj = deadReckon2D(0.0, 0.0, 0.0, odometryFromSpeed(t, v), track);
	ASSERT_EQ(traj.size(), static_cast<std::size_t>(n + 1));
	const double tf = traj.back().t_s;
	EXPECT_NEAR(traj.back().x_m, kRadius * std::sin(kR * tf), 1e-8);
	EXPECT_NEAR(traj.back().y_m, kRadius * (1 - std::cos(kR * tf)), 1e-8);
	EXPECT_NEAR(wrapToPi(traj.back().yaw_rad - kR * tf), 0.0, 1e-10);
	// The path length of the polyline is n chords of 2 R sin(r dt / 2).
	EXPECT_NEAR(pathLength_m(traj), n * 2 * kRadius * std::sin(kR * dt / 2), 1e-8);
}

// Odometry given as cumulative poses (as in CObservationOdometry): odometryFromPoses2D turns
// the chords back into arc lengths exactly (v dt each), also when reversing.
TEST(DeadReckoning, ArcLengthFromPoses)
{
	std::vector<double> t, x, y, phi;
	for (int k = 0; k <= 50; ++k)
	{
		const double tk = 0.2 * k;
		t.push_back(tk);
		x.push_back(kRadius * std::sin(kR * tk));
		y.push_back(kRadius * (1 - std::cos(kR * tk)));
		phi.push_back(kR * tk);
	}
	for (const auto& inc : odometryFromPoses2D(t, x, y, phi)) EXPECT_NEAR(inc.distance_m, kV * 0.2, 1e-12);
	// Same poses driven backwards in time order = reversing: negative distances.
	std::vector<double> xr(x.rbegin(), x.rend()), yr(y.rbegin(), y.rend()), pr(phi.rbegin(), phi.rend());
	for (const auto& inc : odometryFromPoses2D(t, xr, yr, pr)) EXPECT_NEAR(inc.distance_m, -kV * 0.2, 1e-12);
}

// A circle in a plane tilted 20 deg about the x axis: attitude q(t) = Rx(20 deg) Rz(r t), the
// vehicle moving along its body x axis; position = Rx(20 deg) * (planar circle). The
// constant-rate arc model is exact here too (1e-8 m after one lap).
TEST(DeadReckoning, TiltedCircle3D)
{
	const Eigen::Quaterniond tilt(Eigen::AngleAxisd(mrpt::DEG2RAD(20.0), Eigen::Vector3d::UnitX()));
	AttitudeTrack track;
	std::vector<OdometryIncrement> odo;
	const double dt = 0.1;
	const int n = static_cast<int>(2 * M_PI / kR / dt);
	for (int k = 0; k <= n; ++k)
	{
		track.push_back(k * dt, tilt * Eigen::Quaterniond(Eigen::AngleAxisd(kR * k * dt, Eigen::Vector3d::UnitZ())));
		if (k > 0) odo.push_back({k * dt, kV * dt});
	}
	const Trajectory traj = deadReckon3D(0.0, Eigen::Vector3d::Zero(), odo, track);
	const double tf = n * dt;
	const Eigen::Vector3d expected =
		tilt * Eigen::Vector3d(kRadius * std::sin(kR * tf), kRadius * (1 - std::cos(kR * tf)), 0.0);
	EXPECT_NEAR(traj.back().x_m, expected.x(), 1e-8);
	EXPECT_NEAR(traj.back().y_m, expected.y(), 1e-8);
	EXPECT_NEAR(traj.back().z_m, expected.z(), 1e-8);
}

TEST(DeadReckoning, BadInputThrows)
{
	AttitudeTrack track;
	track.push_back(0.0, Eigen::Quaterniond::Identity());
	track.push_back(1.0, Eigen::Quaterniond::Identity());
	DeadReckoning2D dr(0.0, 0, 0);
	EXPECT_THROW(dr.add({0.0, 1.0}, track), std::invalid_argument);  // no time advance
	EXPECT_THROW(dr.add({0.5, std::nan("")}, track), std::invalid_argument);
	EXPECT_THROW(dr.add({2.0, 1.0}, track), std::out_of_range);  // outside the attitude track
	EXPECT_THROW(odometryFromSpeed({0.0, 0.0}, {1.0, 1.0}), std::invalid_argument);
	EXPECT_THROW(odometryFromSpeed({0.0, 1.0}, {1.0}), std::invalid_argument);
}
