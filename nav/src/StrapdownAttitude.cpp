/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt/core/format.h>
#include <mrpt_fog_nav/EarthModel.h>
#include <mrpt_fog_nav/Rotation.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::nav
{
StrapdownAttitude::StrapdownAttitude(const StrapdownOptions& options, Mode mode) : options_(options), mode_(mode)
{
	if (!std::isfinite(options.latitude_rad) || std::abs(options.latitude_rad) > M_PI / 2)
		throw std::invalid_argument("StrapdownAttitude: latitude must be finite and within [-90, 90] deg");
}

void StrapdownAttitude::initialize(double t_s, const Eigen::Quaterniond& q_nb)
{
	if (!std::isfinite(t_s) || !q_nb.coeffs().allFinite() || q_nb.norm() < 1e-9)
		throw std::invalid_argument("StrapdownAttitude::initialize: non-finite time or invalid quaternion");
	t_s_ = t_s;
	q_nb_ = q_nb.normalized();
	prev_dtheta_.reset();
	prev_rate_.reset();
	initialized_ = true;
	updated_since_init_ = false;
}

RateSampling rateSamplingFromString(const std::string& text)
{
	if (text == "instantaneous") return RateSampling::Instantaneous;
	if (text == "average") return RateSampling::IntervalAverage;
	throw std::invalid_argument("rate sampling '" + text + "' is not instantaneous|average");
}

const char* rateSamplingName(RateSampling s)
{
	switch (s)
	{
		case RateSampling::Instantaneous: return "instantaneous";
		case RateSampling::IntervalAverage: return "average";
		case RateSampling::Unspecified: break;
	}
	return "unspecified";
}

void StrapdownAttitude::checkTime(double t_s, const char* what) const
{
	if (!initialized_) throw std::invalid_argument(mrpt::format("StrapdownAttitude::%s before initialize()", what));
	if (!std::isfinite(t_s) || !(t_s > t_s_))
		throw std::invalid_argument(
			mrpt::format("StrapdownAttitude::%s: time %.6f s does not follow the previous %.6f s", what, t_s, t_s_));
}

void StrapdownAttitude::updateIncrement(double t_s, const Eigen::Vector3d& dtheta_b_rad,
										const Eigen::Vector3d& vel_enu_mps)
{
	checkTime(t_s, "updateIncrement");
	if (!dtheta_b_rad.allFinite() || !vel_enu_mps.allFinite())
		throw std::invalid_argument(mrpt::format("StrapdownAttitude: non-finite increment or velocity at t=%.6f s", t_s));
	const double dt = t_s - t_s_;

	// Body rotation with the two-sample coning correction.
	Eigen::Vector3d dtheta = dtheta_b_rad;
	if (options_.coning_correction && prev_dtheta_) dtheta += prev_dtheta_->cross(dtheta_b_rad) / 12.0;
	prev_dtheta_ = dtheta_b_rad;
	const Eigen::Quaterniond q_bb = rotvecToQuat(dtheta);

	// Navigation-frame rotation (Earth rate + transport rate).
	Eigen::Vector3d omega_in = Eigen::Vector3d::Zero();
	if (options_.remove_earth_rate) omega_in += earthRateEnu(options_.latitude_rad);
	if (options_.use_transport_rate) omega_in += transportRateEnu(options_.latitude_rad, options_.height_m, vel_enu_mps);
	if (mode_ == Mode::VerticalOnly) omega_in = Eigen::Vector3d(0, 0, omega_in.z());
	const Eigen::Quaterniond q_nn = rotvecToQuat(-omega_in * dt);

	q_nb_ = (q_nn * q_nb_ * q_bb).normalized();
	t_s_ = t_s;
	updated_since_init_ = true;
}

void StrapdownAttitude::updateRate(double t_s, const Eigen::Vector3d& omega_b_rad_s, const Eigen::Vector3d& vel_enu_mps)
{
	if (!omega_b_rad_s.allFinite())
		throw std::invalid_argument(mrpt::format("StrapdownAttitude: non-finite rate at t=%.6f s", t_s));
	if (options_.sampling == RateSampling::Unspecified)
		throw std::invalid_argument(
			"StrapdownAttitude::updateRate: StrapdownOptions::sampling is not set: IntervalAverage for digital "
			"FOGs and fog-sim data (mean rate over the preceding interval), Instantaneous for sampled analog rates");
	if (initialized_ && !updated_since_init_ && t_s == t_s_ && options_.sampling == RateSampling::IntervalAverage)
		return;  // mean over the interval that ended at initialisation: nothing to integrate
	if (options_.sampling == RateSampling::Instantaneous)
	{
		if (!prev_rate_ && initialized_ && t_s == t_s_)
		{
			prev_rate_ = omega_b_rad_s;  // seeds the trapezoid, no time elapsed
			return;
		}
		checkTime(t_s, "updateRate");
		const Eigen::Vector3d prev = prev_rate_ ? *prev_rate_ : omega_b_rad_s;
		const double dt = t_s - t_s_;
		prev_rate_ = omega_b_rad_s;
		updateIncrement(t_s, 0.5 * (prev + omega_b_rad_s) * dt, vel_enu_mps);
		return;
	}
	checkTime(t_s, "updateRate");
	updateIncrement(t_s, omega_b_rad_s * (t_s - t_s_), vel_enu_mps);
}

void StrapdownAttitude::updateRateZ(double t_s, double omega_z_rad_s, const Eigen::Vector3d& vel_enu_mps)
{
	updateRate(t_s, Eigen::Vector3d(0, 0, omega_z_rad_s), vel_enu_mps);
}

double StrapdownAttitude::yaw() const { return yawOf(q_nb_); }

}  // namespace mrpt_fog::nav
