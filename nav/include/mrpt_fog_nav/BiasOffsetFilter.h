/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

/** \file BiasOffsetFilter.h
 * Kalman filter of what a thermal calibration cannot hold: the gyro's bias offset picked at
 * turn-on (and drifted with age), learned from zero-rate measurements while the vehicle stands
 * still (the compensated rate should then read the Earth rate's vertical component).
 *
 * States [deg/h]: c, the offset (constant over a drive; a rate random walk K lets it move
 * slowly), and g, the gyro's bias instability (first-order Gauss-Markov, sigma B, correlation
 * time tau), which a standstill of a minute cannot tell from c: without g the filter would
 * take one minute's bias instability for the turn-on offset and keep it all drive long.
 *   predict over dt:  c <- c,  g <- a g,  a = exp(-dt / tau),
 *                     Q = diag(K^2 dt / 3600 s/h, B^2 (1 - a^2))
 *   measure a sample z = (compensated rate - Earth rate up) [deg/h], the mean rate over dt:
 *                     z = c + g + w,  var(w) = (60 N)^2 / dt  (N: angle random walk [deg/sqrt h])
 * The prior of c is the calibration's: its offset (0 unless a refined calibration says
 * otherwise) with the thermal model's uncertainty and the turn-on repeatability; g starts at 0
 * with variance B^2. With B = 0 and K = 0 this is the textbook constant-offset filter whose
 * posterior variance after n samples is 1 / (1 / P0 + n / R) (tests/nav/test_BiasOffsetFilter.cpp). */

#include <Eigen/Core>

namespace mrpt_fog::nav
{
/** The gyro's noise, as its datasheet or an Allan deviation states it. */
struct GyroNoiseModel
{
	double arw_deg_rt_h = 0.001;  //!< angle random walk N [deg/sqrt(h)]
	double bias_instability_dph = 0.005;  //!< Gauss-Markov sigma B [deg/h]
	double bias_corr_time_s = 300.0;  //!< its correlation time tau [s]
	double rrw_deg_h_rt_h = 1e-4;  //!< rate random walk K of the offset [deg/h/sqrt(h)]
};

class BiasOffsetFilter
{
   public:
	/** prior_offset_dph / prior_sigma_dph: the offset c at time t0_s and its 1-sigma [deg/h].
	 * Throws std::invalid_argument on a negative or non-finite sigma or noise term. */
	BiasOffsetFilter(double t0_s, double prior_offset_dph, double prior_sigma_dph, const GyroNoiseModel& noise);

	/** Moves the state to t_s (>= the filter's time; an earlier t_s is ignored). */
	void predictTo(double t_s);
	/** One zero-rate sample: z_dph = compensated rate minus the expected (Earth) rate [deg/h],
	 * the mean rate over the interval dt_s (> 0) ending at t_s. A non-finite z or dt is ignored
	 * (returns false). */
	bool update(double t_s, double z_dph, double dt_s);

	double time_s() const { return t_s_; }
	double offset_dph() const { return x_(0); }  //!< c
	double offset_sigma_dph() const;  //!< sqrt(P_cc)
	double instability_dph() const { return x_(1); }  //!< g
	/** The bias to subtract at time t_s >= time_s() (c + g decayed to t_s) [deg/h]. */
	double correctionAt_dph(double t_s) const;
	const Eigen::Matrix2d& covariance() const { return P_; }

   private:
	GyroNoiseModel noise_;
	double t_s_;
	Eigen::Vector2d x_;
	Eigen::Matrix2d P_;
};

}  // namespace mrpt_fog::nav
