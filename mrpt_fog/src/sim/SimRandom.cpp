/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/SimRandom.h>

#include <cmath>

namespace mrpt_fog::sim
{
namespace
{
std::uint64_t splitmix64(std::uint64_t x)
{
	x += 0x9E3779B97F4A7C15ULL;
	x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ULL;
	x = (x ^ (x >> 27)) * 0x94D049BB133111EBULL;
	return x ^ (x >> 31);
}
}  // namespace

SimRandom::SimRandom(std::uint64_t run_seed, RandomStream stream)
	: eng_(splitmix64(run_seed ^ splitmix64(static_cast<std::uint64_t>(stream))))
{
}

double SimRandom::uniform() { return static_cast<double>(eng_() >> 11) * (1.0 / 9007199254740992.0); }

double SimRandom::normal()
{
	if (has_spare_)
	{
		has_spare_ = false;
		return spare_;
	}
	double u1 = uniform();
	while (u1 <= 0.0) u1 = uniform();
	const double u2 = uniform();
	const double r = std::sqrt(-2.0 * std::log(u1));
	const double a = 2.0 * units::kPi * u2;
	spare_ = r * std::sin(a);
	has_spare_ = true;
	return r * std::cos(a);
}

}  // namespace mrpt_fog::sim
