/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/HysteresisFilter.h>
#include <mrpt_fog/obs/Units.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;
}  // namespace

HysteresisFilterBank::HysteresisFilterBank(std::vector<HysteresisChannel> channels) : ch_(std::move(channels))
{
	for (const auto& c : ch_)
		if (!(std::isfinite(c.width_C) && c.width_C > 0))
			throw std::invalid_argument("hysteresis filter: width " + std::to_string(c.width_C) +
										" degC must be finite and > 0");
	reset();
}

void HysteresisFilterBank::reset()
{
	p_.assign(ch_.size(), kNaN);
	state_.assign(ch_.size(), 0.0);
	h_.assign(ch_.size(), kNaN);
}

void HysteresisFilterBank::push(const double* temp_C)
{
	for (std::size_t i = 0; i < ch_.size(); i++)
	{
		const double x = temp_C[ch_[i].thermistor];
		if (std::isnan(x))
		{
			h_[i] = kNaN;
			continue;
		}
		const double w = ch_[i].width_C;
		if (std::isnan(p_[i]))  // warm start: no branch known
		{
			p_[i] = x;
			state_[i] = 0.0;
		}
		if (ch_[i].op == HysteresisOperator::Play)
		{
			p_[i] = std::min(std::max(p_[i], x - w), x + w);
			h_[i] = std::min(1.0, std::max(-1.0, (x - p_[i]) / w));  // |x - p| <= w up to rounding
		}
		else
		{
			const double q = std::min(std::max(p_[i], x - kHysteresisDeadBand_C), x + kHysteresisDeadBand_C);
			const double dq = q - p_[i];
			p_[i] = q;
			if (dq != 0.0)
			{
				const double s = dq > 0 ? 1.0 : -1.0;
				state_[i] = s + (state_[i] - s) * std::exp(-std::fabs(dq) / w);
			}
			h_[i] = state_[i];
		}
	}
}

}  // namespace mrpt_fog
