/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt_fog_heading/StandstillCorrection.h>

#include <cmath>

namespace mrpt_fog::heading
{
double thermalModelSigma_dph(const Calibration& cal)
{
	const double held = cal.held_out.stability_dph, in = cal.in_sample.stability_dph;
	return std::isfinite(held) && held > 0 ? held : (std::isfinite(in) && in > 0 ? in : 0.0);
}

void StandstillCorrection::drain()
{
	nav::RefinedRate x;
	while (refiner_->next(x))
	{
	}  // the pipeline integrates what correct() returned; the refiner's delayed copies are dropped
}

double StandstillCorrection::correct(const RateCorrectionInput& in)
{
	if (!refiner_)
	{
		nav::FieldRefinementOptions o;
		o.standstill = opt_.standstill;
		o.noise = opt_.noise;
		o.min_still_s = opt_.min_still_s;
		o.guard_s = opt_.guard_s;
		o.significance_sigma = opt_.significance_sigma;
		o.expected_rate_dph = in.still_reading_dph;
		const double cal = std::isfinite(in.compensation_sigma_dph) ? in.compensation_sigma_dph : 0.0;
		o.prior_sigma_dph = std::hypot(cal, opt_.turn_on_repeatability_dph);
		still_reading_dph_ = in.still_reading_dph;
		refiner_ = std::make_unique<nav::FieldBiasRefiner>(o, in.t_s);
		if (early_) refiner_->addOdometry(early_->t_s, early_->x_m, early_->y_m, early_->phi_rad);
	}
	const bool on = in.gyro_on && std::isfinite(in.compensated_dph);
	refiner_->addRate(in.t_s, on ? in.compensated_dph : NAN, in.turn_on);
	drain();
	if (!on) return in.compensated_dph;
	return in.compensated_dph - refiner_->currentCorrection_dph(in.t_s);
}

void StandstillCorrection::noteOdometry(const WheelOdometry& o)
{
	if (!refiner_)
	{
		early_ = o;  // the start of the first interval the gyro's samples may fall in
		return;
	}
	refiner_->addOdometry(o.t_s, o.x_m, o.y_m, o.phi_rad);
	drain();
}

void StandstillCorrection::finish()
{
	if (!refiner_) return;
	refiner_->finish();
	drain();
}

}  // namespace mrpt_fog::heading
