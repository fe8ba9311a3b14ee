/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/LagFilter.h>
#include <mrpt_fog/obs/Units.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;

/** 1 - (1 - exp(-h)) / h, without cancellation for small h (series below 1e-3). */
double holdWeight(double h)
{
	if (h < 1e-3) return h / 2 - h * h / 6 + h * h * h / 24;
	return 1.0 + std::expm1(-h) / h;
}
}  // namespace

LagFilterBank::LagFilterBank(std::vector<LagChannel> channels) : ch_(std::move(channels))
{
	for (const auto& c : ch_)
		if (!(std::isfinite(c.tau_s) && c.tau_s > 0))
			throw std::invalid_argument("lag filter: time constant " + std::to_string(c.tau_s) + " s must be finite and > 0");
	reset();
}

void LagFilterBank::reset()
{
	y_.assign(ch_.size(), kNaN);
	x_prev_.assign(ch_.size(), kNaN);
	t_prev_.assign(ch_.size(), kNaN);
	rate_.assign(ch_.size(), kNaN);
}

void LagFilterBank::push(double time_s, const double* temp_C)
{
	for (std::size_t i = 0; i < ch_.size(); i++)
	{
		const double x = temp_C[ch_[i].thermistor];
		if (std::isnan(x))
		{
			rate_[i] = kNaN;
			continue;
		}
		const double tau = ch_[i].tau_s;
		if (std::isnan(y_[i]))  // warm start: at equilibrium with the first valid reading
			y_[i] = x;
		else
		{
			const double dt = time_s - t_prev_[i];
			if (dt > 0)
			{
				const double h = dt / tau;
				const double one_minus_a = -std::expm1(-h);
				y_[i] = (1.0 - one_minus_a) * y_[i] + one_minus_a * x_prev_[i] + (x - x_prev_[i]) * holdWeight(h);
			}
		}
		x_prev_[i] = x;
		t_prev_[i] = time_s;
		rate_[i] = (x - y_[i]) / tau;
	}
}

}  // namespace mrpt_fog
