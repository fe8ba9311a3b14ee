/* EarthModel against published WGS-84 values. */
#include <gtest/gtest.h>
#include <mrpt/core/bits_math.h>
#include <mrpt_fog_nav/EarthModel.h>

#include <cmath>

using namespace mrpt_fog::nav;

// Omega = 7.292115e-5 rad/s = 15.041067 deg/h; its vertical part at 40 deg is 15.041067 * sin(40 deg) = 9.66821 deg/h.
TEST(EarthModel, EarthRateAt40Deg)
{
	const Eigen::Vector3d w = earthRateEnu(mrpt::DEG2RAD(40.0));
	const double to_dph = mrpt::RAD2DEG(1.0) * 3600.0;
	EXPECT_NEAR(w.norm() * to_dph, 15.041067, 1e-5);
	EXPECT_NEAR(w.z() * to_dph, 9.66821, 1e-5);
	EXPECT_NEAR(w.x(), 0.0, 0.0);
}

// WGS-84 radii of curvature: equator RM = a(1-e^2) = 6335439.327 m, RN = a = 6378137 m;
// pole RM = RN = a / sqrt(1 - e^2) = 6399593.626 m.
TEST(EarthModel, RadiiOfCurvature)
{
	EXPECT_NEAR(earthRadii(0).meridian_m, 6335439.327, 1e-3);
	EXPECT_NEAR(earthRadii(0).prime_vertical_m, 6378137.0, 1e-6);
	EXPECT_NEAR(earthRadii(M_PI / 2).meridian_m, 6399593.626, 1e-3);
	EXPECT_NEAR(earthRadii(M_PI / 2).prime_vertical_m, 6399593.626, 1e-3);
}

TEST(EarthModel, TransportRateSignsAndPoles)
{
	const double lat = mrpt::DEG2RAD(45.0);
	const Eigen::Vector3d w = transportRateEnu(lat, 0.0, Eigen::Vector3d(10, 10, 0));
	EXPECT_LT(w.x(), 0);  // moving north tilts the frame about -East
	EXPECT_GT(w.y(), 0);  // moving east tilts it about +North
	EXPECT_NEAR(w.z(), w.y() * std::tan(lat), 1e-18);
	EXPECT_THROW(transportRateEnu(M_PI / 2, 0, Eigen::Vector3d(1, 0, 0)), std::invalid_argument);
}
