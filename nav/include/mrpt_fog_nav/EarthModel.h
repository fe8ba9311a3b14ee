/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file EarthModel.h
 * WGS-84 Earth model for the attitude update (KF-GINS style "earth" file): Earth rotation
 * rate and transport rate expressed in the local-level ENU navigation frame.
 *
 * A gyro fixed to the Earth senses the Earth rate; in ENU it is
 *   omega_ie^n = Omega * (0, cos(lat), sin(lat)),
 * so a vertical (z-up) gyro reads Omega sin(lat) = 15.041 deg/h * sin(lat) (9.67 deg/h at
 * 40 deg): that must be removed before judging a 0.01 deg/h thermal effect. Moving over the
 * curved Earth rotates the local-level frame at the transport rate
 *   omega_en^n = (-vN / (RM + h), vE / (RN + h), vE tan(lat) / (RN + h)). */

#include <Eigen/Core>

namespace mrpt_fog::nav
{
namespace earth
{
constexpr double kRotationRate_rad_s = 7.292115e-5;  //!< WGS-84 Omega [rad/s]
constexpr double kSemiMajorAxis_m = 6378137.0;  //!< WGS-84 a [m]
constexpr double kEccentricitySq = 6.69437999014e-3;  //!< WGS-84 e^2 [-]
}  // namespace earth

/** Meridian (RM) and prime-vertical (RN) radii of curvature [m] at a latitude [rad]. */
struct EarthRadii
{
	double meridian_m = 0;  //!< RM
	double prime_vertical_m = 0;  //!< RN
};
EarthRadii earthRadii(double latitude_rad);

/** Earth rate in ENU [rad/s] at a latitude [rad]. */
Eigen::Vector3d earthRateEnu(double latitude_rad);

/** Transport rate in ENU [rad/s] for a velocity vel_enu [m/s] at latitude [rad] and height
 * [m]. Throws std::invalid_argument at the poles (|lat| > 89.9 deg), where tan(lat) diverges
 * and a local-level ENU frame is not defined. */
Eigen::Vector3d transportRateEnu(double latitude_rad, double height_m, const Eigen::Vector3d& vel_enu_mps);

}  // namespace mrpt_fog::nav
