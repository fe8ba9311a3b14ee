/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt_fog_heading/TruthAlignedDeadReckoning.h>

#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/EarthModel.h>
#include <mrpt_fog_nav/Rotation.h>

#include <algorithm>
#include <iterator>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::heading
{
double rollOf(const Eigen::Quaterniond& q_nb)
{
	const Eigen::Matrix3d R = q_nb.toRotationMatrix();
	return std::atan2(R(2, 1), R(2, 2));
}

double pitchOf(const Eigen::Quaterniond& q_nb)
{
	const Eigen::Matrix3d R = q_nb.toRotationMatrix();
	return -std::asin(std::clamp(R(2, 0), -1.0, 1.0));
}

namespace
{
/** x, y null: the vertical gyro alone (VerticalOnly); else the triad (ThreeAxis). */
VariantResult deadReckonImpl(const std::vector<double>& t_s, const std::vector<double>* rate_x_dph,
							 const std::vector<double>* rate_y_dph, const std::vector<double>& rate_dph,
							 const DriveData& drive, const HeadingOptions& options)
{
	const bool triad = rate_x_dph && rate_y_dph;
	if (t_s.size() != rate_dph.size() || t_s.size() < 2 ||
		(triad && (rate_x_dph->size() != t_s.size() || rate_y_dph->size() != t_s.size())))
		throw std::runtime_error("gyro series: sizes differ or fewer than 2 samples");
	const auto& odo = drive.odometry;
	const double t0 = std::max({options.window_t0_s, t_s.front(), odo.t_s.front(), drive.truth.front().t_s});
	const double t_end = std::min({options.window_t1_s, t_s.back(), odo.t_s.back(), drive.truth.back().t_s});
	if (!(t_end > t0)) throw std::runtime_error("the gyro, the odometry and the truth do not overlap in time");

	nav::StrapdownOptions so;
	so.latitude_rad = options.latitude_deg * units::kDegToRad;
	so.use_transport_rate = options.transport_rate;
	so.sampling = options.sampling;
	nav::StrapdownAttitude att(so, triad ? nav::StrapdownAttitude::Mode::ThreeAxis : nav::StrapdownAttitude::Mode::VerticalOnly);
	const nav::TrajectoryPoint start = nav::interpolate(drive.truth, t0);
	att.initialize(t0, triad ? start.q_nb.normalized() : nav::quatFromYawPitchRoll(start.yaw_rad, 0, 0));
	nav::AttitudeTrack track;
	track.reserve(t_s.size() + 1);
	track.push_back(t0, att.attitude());

	VariantResult out;
	if (options.keep_rates) out.t_s.reserve(t_s.size()), out.yaw_rate_rad_s.reserve(t_s.size());
	if (triad) out.roll_rad.reserve(t_s.size()), out.pitch_rad.reserve(t_s.size());
	const double earth_up = nav::earthRateEnu(so.latitude_rad).z();
	// Speed for the transport rate: wheel odometry (as a real vehicle has it), per interval.
	const std::vector<nav::OdometryIncrement> odo_inc =
		options.transport_rate ? nav::odometryFromPoses2D(odo.t_s, odo.x_m, odo.y_m, odo.phi_rad)
							   : std::vector<nav::OdometryIncrement>{};
	auto speedAt = [&](double t) {
		auto it = std::lower_bound(odo_inc.begin(), odo_inc.end(), t,
								   [](const nav::OdometryIncrement& a, double tq) { return a.t_s < tq; });
		if (it == odo_inc.end()) return 0.0;
		const double t_prev = (it == odo_inc.begin()) ? odo.t_s.front() : std::prev(it)->t_s;
		return it->distance_m / (it->t_s - t_prev);
	};
	for (std::size_t k = 0; k < t_s.size(); ++k)
	{
		if (t_s[k] < t0 || (t_s[k] == t0 && options.sampling == nav::RateSampling::IntervalAverage)) continue;
		if (t_s[k] > t_end) break;
		if (!std::isfinite(rate_dph[k]) || (triad && !(std::isfinite((*rate_x_dph)[k]) && std::isfinite((*rate_y_dph)[k]))))
			throw std::runtime_error("gyro rate is not finite at sample " + std::to_string(k) + " (t = " +
									 std::to_string(t_s[k]) + " s; a heading cannot be integrated while the gyro is off)");
		const double w = rate_dph[k] * units::kDegPerHourToRadPerSec;
		Eigen::Vector3d vel = Eigen::Vector3d::Zero();
		if (options.transport_rate)
		{
			const double v = speedAt(t_s[k]), yaw = att.yaw();
			vel = Eigen::Vector3d(v * std::cos(yaw), v * std::sin(yaw), 0.0);
		}
		if (triad)
		{
			const Eigen::Vector3d wb((*rate_x_dph)[k] * units::kDegPerHourToRadPerSec,
									 (*rate_y_dph)[k] * units::kDegPerHourToRadPerSec, w);
			att.updateRate(t_s[k], wb, vel);
			out.roll_rad.push_back(rollOf(att.attitude()));
			out.pitch_rad.push_back(pitchOf(att.attitude()));
		}
		else
			att.updateRateZ(t_s[k], w, vel);
		if (t_s[k] > track.backTime()) track.push_back(t_s[k], att.attitude());
		if (options.keep_rates) out.t_s.push_back(t_s[k]), out.yaw_rate_rad_s.push_back(w - earth_up);
	}

	// Odometry inside the attitude track (a contiguous range: times increase); dead reckoning
	// from the truth position.
	const auto first = static_cast<std::size_t>(std::lower_bound(odo.t_s.begin(), odo.t_s.end(), t0) - odo.t_s.begin());
	const auto last = static_cast<std::size_t>(std::upper_bound(odo.t_s.begin(), odo.t_s.end(), track.backTime()) - odo.t_s.begin());
	if (last < first + 2)
	{
		if (options.empty_if_no_odometry) return out;
		throw std::runtime_error("fewer than 2 odometry samples inside the gyro's time span");
	}
	const nav::TrajectoryPoint p0 = nav::interpolate(drive.truth, odo.t_s[first]);
	out.trajectory = nav::deadReckon2D(odo.t_s[first], p0.x_m, p0.y_m,
									   nav::odometryFromPoses2D(odo.t_s, odo.x_m, odo.y_m, odo.phi_rad, first, last), track);
	return out;
}
}  // namespace

VariantResult deadReckonVariant(const std::vector<double>& t_s, const std::vector<double>& rate_dph,
								const DriveData& drive, const HeadingOptions& options)
{
	return deadReckonImpl(t_s, nullptr, nullptr, rate_dph, drive, options);
}

VariantResult deadReckonVariant(const std::vector<double>& t_s, const std::vector<double>& rate_x_dph,
								const std::vector<double>& rate_y_dph, const std::vector<double>& rate_z_dph,
								const DriveData& drive, const HeadingOptions& options)
{
	return deadReckonImpl(t_s, &rate_x_dph, &rate_y_dph, rate_z_dph, drive, options);
}

}  // namespace mrpt_fog::heading
