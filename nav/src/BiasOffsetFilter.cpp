/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt_fog_nav/BiasOffsetFilter.h>
#include "NavUnits.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_fog::nav
{
namespace
{
using units::kSecondsPerHour;

void requireNonNegative(double v, const char* name)
{
	if (!(v >= 0) || !std::isfinite(v)) throw std::invalid_argument(std::string("BiasOffsetFilter: ") + name + " must be finite and >= 0");
}
}  // namespace

BiasOffsetFilter::BiasOffsetFilter(double t0_s, double prior_offset_dph, double prior_sigma_dph, const GyroNoiseModel& noise)
	: noise_(noise), t_s_(t0_s)
{
	requireNonNegative(prior_sigma_dph, "prior sigma");
	requireNonNegative(noise.arw_deg_rt_h, "angle random walk");
	requireNonNegative(noise.bias_instability_dph, "bias instability");
	requireNonNegative(noise.rrw_deg_h_rt_h, "rate random walk");
	if (!(noise.bias_corr_time_s > 0)) throw std::invalid_argument("BiasOffsetFilter: bias correlation time must be > 0");
	if (!std::isfinite(prior_offset_dph) || !std::isfinite(t0_s)) throw std::invalid_argument("BiasOffsetFilter: prior offset and time must be finite");
	x_ << prior_offset_dph, 0.0;
	P_.setZero();
	P_(0, 0) = prior_sigma_dph * prior_sigma_dph;
	P_(1, 1) = noise.bias_instability_dph * noise.bias_instability_dph;
}

void BiasOffsetFilter::predictTo(double t_s)
{
	if (!(t_s > t_s_)) return;
	const double dt = t_s - t_s_;
	const double a = std::exp(-dt / noise_.bias_corr_time_s);
	x_(1) *= a;
	P_(0, 1) *= a;
	P_(1, 0) *= a;
	P_(1, 1) = a * a * P_(1, 1) + noise_.bias_instability_dph * noise_.bias_instability_dph * (1 - a * a);
	P_(0, 0) += noise_.rrw_deg_h_rt_h * noise_.rrw_deg_h_rt_h * dt / kSecondsPerHour;
	t_s_ = t_s;
}

bool BiasOffsetFilter::update(double t_s, double z_dph, double dt_s)
{
	if (!std::isfinite(z_dph) || !(dt_s > 0) || !std::isfinite(dt_s) || !std::isfinite(t_s)) return false;
	predictTo(t_s);
	const double sigma_w = units::kSqrtSecondsPerHour * noise_.arw_deg_rt_h / std::sqrt(dt_s);
	const Eigen::RowVector2d H(1.0, 1.0);
	const double S = (H * P_ * H.transpose())(0, 0) + sigma_w * sigma_w;
	if (!(S > 0)) return false;  // no noise and no uncertainty: nothing to learn
	const Eigen::Vector2d K = P_ * H.transpose() / S;
	x_ += K * (z_dph - (H * x_)(0, 0));
	// Joseph form: stays symmetric and positive over the thousands of samples of a standstill
	const Eigen::Matrix2d IKH = Eigen::Matrix2d::Identity() - K * H;
	P_ = IKH * P_ * IKH.transpose() + K * (sigma_w * sigma_w) * K.transpose();
	return true;
}

double BiasOffsetFilter::offset_sigma_dph() const { return std::sqrt(std::max(0.0, P_(0, 0))); }

double BiasOffsetFilter::correctionAt_dph(double t_s) const
{
	const double dt = t_s > t_s_ ? t_s - t_s_ : 0.0;
	return x_(0) + x_(1) * std::exp(-dt / noise_.bias_corr_time_s);
}

}  // namespace mrpt_fog::nav
