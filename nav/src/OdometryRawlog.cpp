/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt_fog_nav/OdometryRawlog.h>
#include <mrpt_fog_nav/Rotation.h>

#include <stdexcept>

namespace mrpt_fog::nav
{
std::vector<mrpt::obs::CObservation::Ptr> makeOdometryObservations(const Trajectory& traj,
																	const std::vector<double>& imu_rate_z_rad_s,
																	const OdometryRawlogOptions& options)
{
	if (!imu_rate_z_rad_s.empty() && imu_rate_z_rad_s.size() != traj.size())
		throw std::invalid_argument("makeOdometryObservations: imu_rate_z_rad_s size differs from the trajectory");
	std::vector<mrpt::obs::CObservation::Ptr> out;
	out.reserve(traj.size() * (options.with_imu ? 2 : 1));
	for (std::size_t k = 0; k < traj.size(); ++k)
	{
		const auto& p = traj[k];
		const auto stamp = mrpt::Clock::fromDouble(p.t_s);
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->sensorLabel = options.odometry_label;
		odo->timestamp = stamp;
		odo->odometry = mrpt::poses::CPose2D(p.x_m, p.y_m, p.yaw_rad);
		out.push_back(odo);
		if (!options.with_imu) continue;
		double wz = 0.0;
		if (!imu_rate_z_rad_s.empty())
			wz = imu_rate_z_rad_s[k];
		else if (k > 0)
			wz = wrapToPi(p.yaw_rad - traj[k - 1].yaw_rad) / (p.t_s - traj[k - 1].t_s);
		auto imu = mrpt::obs::CObservationIMU::Create();
		imu->sensorLabel = options.imu_label;
		imu->timestamp = stamp;
		imu->set(mrpt::obs::IMU_WZ, wz);
		out.push_back(imu);
	}
	return out;
}

}  // namespace mrpt_fog::nav
