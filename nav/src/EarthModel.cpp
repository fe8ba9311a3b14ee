/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt/core/bits_math.h>
#include <mrpt_fog_nav/EarthModel.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::nav
{
EarthRadii earthRadii(double latitude_rad)
{
	const double s = std::sin(latitude_rad);
	const double w2 = 1.0 - earth::kEccentricitySq * s * s;
	const double w = std::sqrt(w2);
	EarthRadii r;
	r.prime_vertical_m = earth::kSemiMajorAxis_m / w;
	r.meridian_m = earth::kSemiMajorAxis_m * (1.0 - earth::kEccentricitySq) / (w2 * w);
	return r;
}

Eigen::Vector3d earthRateEnu(double latitude_rad)
{
	return {0.0, earth::kRotationRate_rad_s * std::cos(latitude_rad),
			earth::kRotationRate_rad_s * std::sin(latitude_rad)};
}

Eigen::Vector3d transportRateEnu(double latitude_rad, double height_m, const Eigen::Vector3d& vel_enu_mps)
{
	if (std::abs(latitude_rad) > mrpt::DEG2RAD(89.9))
		throw std::invalid_argument("transportRateEnu: latitude too close to a pole for a local-level ENU frame");
	const EarthRadii r = earthRadii(latitude_rad);
	const double vE = vel_enu_mps.x(), vN = vel_enu_mps.y();
	return {-vN / (r.meridian_m + height_m), vE / (r.prime_vertical_m + height_m),
			vE * std::tan(latitude_rad) / (r.prime_vertical_m + height_m)};
}

}  // namespace mrpt_fog::nav
