/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file Rotation.h
 * Rotation helpers for the strapdown code (KF-GINS style "rotation" file), on Eigen types.
 * Frames: navigation frame ENU (x East, y North, z Up); body frame FLU (x forward, y left,
 * z up), so the yaw of a level vehicle is MRPT's phi: counter-clockwise from East [rad].
 * A quaternion q_nb rotates body-frame vectors into the navigation frame. */

#include <Eigen/Geometry>

namespace mrpt_fog::nav
{
/** Unit quaternion of a rotation vector [rad] (axis * angle); exact for any angle, and
 * well-behaved at zero (Eigen::AngleAxis with a small-angle branch). */
Eigen::Quaterniond rotvecToQuat(const Eigen::Vector3d& rotvec_rad);

/** Rotation vector [rad] of a unit quaternion, angle in [0, pi]. */
Eigen::Vector3d quatToRotvec(const Eigen::Quaterniond& q);

/** Quaternion q_nb from yaw, pitch, roll [rad] (MRPT's CPose3D convention: R = Rz(yaw)
 * Ry(pitch) Rx(roll)). */
Eigen::Quaterniond quatFromYawPitchRoll(double yaw_rad, double pitch_rad, double roll_rad);

/** Yaw [rad] in (-pi, pi] of q_nb (same convention as quatFromYawPitchRoll). */
double yawOf(const Eigen::Quaterniond& q_nb);

/** Angle wrapped to (-pi, pi] [rad]. */
double wrapToPi(double angle_rad);

}  // namespace mrpt_fog::nav
