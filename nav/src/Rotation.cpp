/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt/math/wrap2pi.h>
#include <mrpt_fog_nav/Rotation.h>

#include <cmath>

namespace mrpt_fog::nav
{
Eigen::Quaterniond rotvecToQuat(const Eigen::Vector3d& rotvec_rad)
{
	const double angle = rotvec_rad.norm();
	if (angle < 1e-12)
	{
		// First-order series: q = [1, v/2], renormalised (exact to machine precision here).
		return Eigen::Quaterniond(1.0, 0.5 * rotvec_rad.x(), 0.5 * rotvec_rad.y(), 0.5 * rotvec_rad.z())
			.normalized();
	}
	return Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotvec_rad / angle));
}

Eigen::Vector3d quatToRotvec(const Eigen::Quaterniond& q)
{
	Eigen::Quaterniond qn = q.normalized();
	if (qn.w() < 0) qn.coeffs() = -qn.coeffs();  // shortest rotation: angle in [0, pi]
	const Eigen::AngleAxisd aa(qn);
	return aa.angle() * aa.axis();
}

Eigen::Quaterniond quatFromYawPitchRoll(double yaw_rad, double pitch_rad, double roll_rad)
{
	return Eigen::Quaterniond(Eigen::AngleAxisd(yaw_rad, Eigen::Vector3d::UnitZ()) *
							  Eigen::AngleAxisd(pitch_rad, Eigen::Vector3d::UnitY()) *
							  Eigen::AngleAxisd(roll_rad, Eigen::Vector3d::UnitX()));
}

double yawOf(const Eigen::Quaterniond& q_nb)
{
	const Eigen::Matrix3d R = q_nb.normalized().toRotationMatrix();
	return std::atan2(R(1, 0), R(0, 0));
}

double wrapToPi(double angle_rad) { return mrpt::math::wrapToPi(angle_rad); }

}  // namespace mrpt_fog::nav
