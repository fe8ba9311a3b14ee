/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt_fog_nav/FieldBiasRefiner.h>
#include "NavUnits.h"

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::nav
{
namespace
{
}

FieldBiasRefiner::FieldBiasRefiner(const FieldRefinementOptions& options, double t0_s)
	: opt_(options),
	  detector_(options.standstill, options.expected_rate_dph),
	  kf_(t0_s, options.prior_offset_dph, options.prior_sigma_dph, options.noise),
	  t0_s_(t0_s)
{
	if (!(options.min_still_s >= 0) || !(options.guard_s >= 0) || !std::isfinite(options.min_still_s) ||
		!std::isfinite(options.guard_s) || !(options.significance_sigma >= 0) || !std::isfinite(options.significance_sigma))
		throw std::invalid_argument("field refinement: min standstill, guard and significance must be finite and >= 0");
}

bool FieldBiasRefiner::beatsPrior(double length_s) const
{
	if (!(length_s > 0)) return false;
	const double white = units::kSqrtSecondsPerHour * opt_.noise.arw_deg_rt_h;
	const double B = opt_.noise.bias_instability_dph;
	const double P = opt_.prior_sigma_dph;  // the prior, not what earlier standstills learned
	return white * white / length_s + B * B < P * P;
}

void FieldBiasRefiner::testSignificance(double t_s)
{
	look_ = false;
	if (applied_) return;
	if (std::abs(kf_.offset_dph() - opt_.prior_offset_dph) > opt_.significance_sigma * kf_.offset_sigma_dph())
	{
		applied_ = true;
		applied_since_s_ = t_s;
	}
}

void FieldBiasRefiner::endRun()
{
	if (in_run_)
	{
		if (current_)
		{
			testSignificance(run_last_s_);  // the second look: what the whole standstill says
			current_->end_s = run_last_s_;
			current_->offset_after_dph = kf_.offset_dph();
			current_->sigma_after_dph = kf_.offset_sigma_dph();
			current_->mean_reading_dph = reading_sum_ / static_cast<double>(current_->samples);
			current_->applied = applied_;
			updates_.push_back(*current_);
		}
		else if (run_last_s_ > run_start_s_)
			short_++;
	}
	in_run_ = false;
	current_.reset();
	run_.clear();
	reading_sum_ = 0;
}

void FieldBiasRefiner::take(const ClassifiedRate& c)
{
	if (c.turn_on && c.t_s > t0_s_)
	{
		endRun();
		kf_ = BiasOffsetFilter(c.t_s, opt_.prior_offset_dph, opt_.prior_sigma_dph, opt_.noise);
		restarts_++;
		applied_ = false;
		applied_since_s_ = std::numeric_limits<double>::quiet_NaN();
	}
	if (!c.still)
		endRun();
	else
	{
		if (!in_run_)
		{
			in_run_ = true;
			run_start_s_ = c.t_s;
		}
		run_last_s_ = c.t_s;
		if (c.t_s >= run_start_s_ + opt_.guard_s) run_.push_back(c);  // the first guard_s are left out
		// use the samples at least guard_s old, once the standstill is long and informative enough
		const double length = c.t_s - opt_.guard_s - (run_start_s_ + opt_.guard_s);
		if (current_ || (c.t_s - run_start_s_ >= opt_.min_still_s && beatsPrior(length)))
			while (!run_.empty() && run_.front().t_s + opt_.guard_s <= c.t_s)
			{
				const ClassifiedRate& u = run_.front();
				const double before = kf_.offset_dph(), sigma_before = kf_.offset_sigma_dph();
				const double z = u.rate_dph - opt_.expected_rate_dph;
				if (kf_.update(u.t_s, z, u.dt_s))
				{
					if (!current_)
					{
						look_ = true;  // the first look: the standstill's first min_still_s
						current_ = StandstillUpdate{};
						current_->start_s = run_start_s_;
						current_->first_used_s = u.t_s;
						current_->offset_before_dph = before;
						current_->sigma_before_dph = sigma_before;
					}
					current_->last_used_s = u.t_s;
					current_->samples++;
					reading_sum_ += z;
				}
				run_.pop_front();
			}
	}
	if (look_) testSignificance(c.t_s);
	RefinedRate r;
	r.t_s = c.t_s;
	r.correction_dph = applied_ ? kf_.correctionAt_dph(c.t_s) : opt_.prior_offset_dph;
	r.rate_dph = c.rate_dph - r.correction_dph;
	out_.push_back(r);
}

void FieldBiasRefiner::drain()
{
	ClassifiedRate c;
	while (detector_.next(c)) take(c);
}

void FieldBiasRefiner::finish()
{
	detector_.finish();
	drain();
	endRun();
}

bool FieldBiasRefiner::next(RefinedRate& out)
{
	if (out_.empty()) return false;
	out = out_.front();
	out_.pop_front();
	return true;
}

}  // namespace mrpt_fog::nav
