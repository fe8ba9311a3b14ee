/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file StrapdownAttitude.h
 * Quaternion attitude from gyro rates (raw or compensated FOG output), in the textbook form
 * KF-GINS uses:
 *
 *   dtheta = dtheta_k + dtheta_{k-1} x dtheta_k / 12      (two-sample coning correction)
 *   q_nb   = rotvec(-omega_in^n dt) * q_nb * rotvec(dtheta)
 *
 * where omega_in^n = Earth rate + transport rate (EarthModel.h) in the ENU navigation frame.
 * Frames and yaw convention: see Rotation.h (yaw CCW from East, as MRPT's phi).
 *
 * Two modes:
 * - ThreeAxis: a full gyro triad; the nav-frame rotation uses all of omega_in^n.
 * - VerticalOnly: one z-up gyro on a (nearly) level vehicle. Only the vertical component of
 *   omega_in^n is removed (15.041 deg/h * sin(lat) plus the vertical transport rate when
 *   enabled); the horizontal components are not sensed by a single gyro and must not tilt the
 *   attitude.
 *
 * Rates are rad/s, times s (any origin, e.g. UNIX time), angle increments rad.
 * Bad input (time not increasing, non-finite values, update before initialize, rate samples
 * without a chosen RateSampling) throws std::invalid_argument naming the sample time.
 *
 * Earth rate: the attitude is referred to the local-level ENU frame, so the gyro's full output
 * (including the Earth rate it senses) goes in. A bias compensation fitted on a static
 * calibration has already removed the Earth rate at the calibration site: add it back
 * (Omega sin(calibration latitude)) before updateRate(), or the Earth rate is removed twice
 * (fog-drift and examples/fog_heading_odometry do this from the calibration file). */

#include <Eigen/Geometry>

#include <optional>
#include <string>

namespace mrpt_fog::nav
{
/** How a rate sample relates to the interval before it. There is no safe default: the wrong
 * choice shifts the heading by half a sample of rotation (0.81 deg at the end of the bundled
 * drive), so updateRate() throws until one is chosen.
 * - IntervalAverage: digital FOGs (closed-loop, the output is the phase accumulated over the
 *   sample period divided by it), `fog-sim`'s output and the bundled datasets, MRPT
 *   CObservationIMU rates made by fog-compensate from such data.
 * - Instantaneous: a sampled analog rate (or a rate evaluated at the sample instant, as in
 *   closed-form tests). */
enum class RateSampling
{
	Unspecified,  //!< not chosen: updateRate() throws (updateIncrement() does not need it)
	Instantaneous,  //!< rate at the sample instant: increments by the trapezoid rule
	IntervalAverage  //!< mean rate over (t_prev, t]: increment = rate * dt (exact)
};

/** "instantaneous" / "average" (as fog-drift's --rate-sampling) -> RateSampling; throws
 * std::invalid_argument naming the text otherwise. */
RateSampling rateSamplingFromString(const std::string& text);
const char* rateSamplingName(RateSampling s);  //!< "instantaneous", "average", "unspecified"

struct StrapdownOptions
{
	double latitude_rad = 0.0;  //!< geodetic latitude of the run [rad]
	double height_m = 0.0;  //!< ellipsoidal height [m] (transport rate only)
	bool remove_earth_rate = true;  //!< rotate the nav frame with the Earth (subtract Omega)
	bool use_transport_rate = false;  //!< also rotate with the transport rate (needs velocity)
	bool coning_correction = true;  //!< two-sample coning term dtheta_{k-1} x dtheta_k / 12
	RateSampling sampling = RateSampling::Unspecified;  //!< must be set before updateRate()
};

class StrapdownAttitude
{
   public:
	enum class Mode
	{
		ThreeAxis,
		VerticalOnly
	};

	explicit StrapdownAttitude(const StrapdownOptions& options = {}, Mode mode = Mode::ThreeAxis);

	/** Sets the attitude q_nb at time t_s (e.g. from truth or an alignment). Resets the
	 * coning and rate history. */
	void initialize(double t_s, const Eigen::Quaterniond& q_nb);

	/** Integrating-sensor input: body angle increment [rad] over (time(), t_s].
	 * vel_enu_mps is used only for the transport rate. */
	void updateIncrement(double t_s, const Eigen::Vector3d& dtheta_b_rad,
						 const Eigen::Vector3d& vel_enu_mps = Eigen::Vector3d::Zero());

	/** Rate-sample input [rad/s] (see RateSampling; throws while it is Unspecified). A first
	 * sample after initialize() at the initialisation time is accepted with either sampling:
	 * with Instantaneous it seeds the trapezoid; with IntervalAverage it is the mean over the
	 * interval that ended at initialisation and contributes nothing. With Instantaneous, a first
	 * sample at a later time is held constant over the first interval. */
	void updateRate(double t_s, const Eigen::Vector3d& omega_b_rad_s,
					const Eigen::Vector3d& vel_enu_mps = Eigen::Vector3d::Zero());

	/** Single vertical gyro [rad/s]: updateRate(t_s, (0, 0, omega_z)). */
	void updateRateZ(double t_s, double omega_z_rad_s,
					 const Eigen::Vector3d& vel_enu_mps = Eigen::Vector3d::Zero());

	const Eigen::Quaterniond& attitude() const { return q_nb_; }
	double time() const { return t_s_; }
	double yaw() const;  //!< [rad] in (-pi, pi]
	const StrapdownOptions& options() const { return options_; }
	Mode mode() const { return mode_; }

   private:
	void checkTime(double t_s, const char* what) const;

	StrapdownOptions options_;
	Mode mode_;
	bool initialized_ = false;
	double t_s_ = 0.0;
	Eigen::Quaterniond q_nb_ = Eigen::Quaterniond::Identity();
	std::optional<Eigen::Vector3d> prev_dtheta_;  //!< for the coning term
	std::optional<Eigen::Vector3d> prev_rate_;  //!< for the trapezoid rule
	bool updated_since_init_ = false;  //!< a time step was taken after initialize()
};

}  // namespace mrpt_fog::nav
