/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "RangeWarning.h"

#include <cstdio>

namespace mrpt_fog::app
{
namespace
{
double share(std::size_t n, std::size_t of) { return of ? static_cast<double>(n) / static_cast<double>(of) : 0.0; }
}  // namespace

std::string outOfRangeWarning(const CompensationCounters& c, ExtrapolationPolicy policy)
{
	std::string out;
	char b[320];
	if (c.temp_outside_samples)
	{
		std::snprintf(b, sizeof b,
					  "  warning: %.1f %% of samples (%zu) have a temperature outside the calibrated range, up to %.3g "
					  "degC beyond it (extrapolation: %s)\n",
					  100.0 * share(c.temp_outside_samples, c.samples), c.temp_outside_samples, c.max_temp_excursion_C,
					  toString(policy));
		out += b;
	}
	if (c.rate_outside_samples)
	{
		std::snprintf(b, sizeof b,
					  "  warning: %.1f %% of samples (%zu) have a temperature rate outside the calibrated range, up to "
					  "%.3g degC/min beyond it (extrapolation: %s)\n",
					  100.0 * share(c.rate_outside_samples, c.samples), c.rate_outside_samples,
					  60.0 * c.max_rate_excursion_C_per_s, toString(policy));
		out += b;
	}
	return out;
}

JsonValue outOfRangeJson(const CompensationCounters& c, ExtrapolationPolicy policy)
{
	JsonValue j = JsonValue::object();
	j["policy"] = toString(policy);
	j["samples"] = static_cast<unsigned long>(c.samples);
	j["temperature"]["outside_samples"] = static_cast<unsigned long>(c.temp_outside_samples);
	j["temperature"]["outside_share"] = share(c.temp_outside_samples, c.samples);
	j["temperature"]["max_beyond_C"] = c.max_temp_excursion_C;
	j["rate"]["outside_samples"] = static_cast<unsigned long>(c.rate_outside_samples);
	j["rate"]["outside_share"] = share(c.rate_outside_samples, c.samples);
	j["rate"]["max_beyond_C_per_min"] = 60.0 * c.max_rate_excursion_C_per_s;
	return j;
}
}  // namespace mrpt_fog::app
