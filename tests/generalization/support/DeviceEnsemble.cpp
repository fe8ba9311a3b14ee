/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "DeviceEnsemble.h"

#include <cmath>
#include <random>
#include <sstream>

namespace fogtest
{
using mrpt_fog::CoilSide;
using namespace mrpt_fog::sim;

DrawnDevice drawDevice(std::uint64_t seed)
{
	std::mt19937_64 rng(0x9e3779b97f4a7c15ull ^ (seed * 0x2545F4914F6CDD1Dull));
	const auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
	const auto logUni = [&](double a, double b) { return std::exp(uni(std::log(a), std::log(b))); };
	DrawnDevice d;
	d.seed = seed;
	FogDevice& dev = d.device;
	dev = FogDevice::defaultDevice();
	dev.name = "ensemble_" + std::to_string(seed);
	const double f = logUni(0.5, 2.0);
	dev.thermal.scaleHeatCapacities(f);
	dev.thermal.housing_to_air_W_K = uni(0.3, 1.0);
	dev.thermal.radial_conductivity_W_mK = uni(0.15, 0.4);
	dev.thermal.outer_to_housing_W_K = uni(0.15, 0.5);
	dev.winding.midpoint_offset_m = uni(-2.0, 2.0);
	dev.winding.pattern = uni(0, 1) < 0.75 ? WindingPattern::Quadrupolar : WindingPattern::Octupolar;
	dev.errors.radial_gradient_dph_per_C() = uni(0.02, 0.12);
	dev.errors.gradient_rate_dph_per_C_per_min() = uni(0.03, 0.2);
	dev.errors.hysteresis_dph() = uni(0.0, 0.03);
	dev.errors.temp_poly_dph = {uni(-2e-3, 2e-3), uni(-2e-5, 2e-5)};
	const int count = 1 + static_cast<int>(std::floor(uni(0, 4)));
	const double quanta[] = {0.01, 1.0 / 256.0, 1.0 / 16.0};
	dev.thermistor_quantum_C = quanta[static_cast<int>(std::floor(uni(0, 3)))];
	dev.thermistor_noise_C = uni(0.001, 0.005);
	dev.thermistors.clear();
	double angle = uni(0, 360);
	for (int i = 0; i < count; i++)
	{
		if (i == 2) angle = uni(0, 360);
		ThermistorSpec t;
		const bool inner = i % 2 == 0;
		t.info = {(inner ? "Ti" : "To") + std::to_string(i / 2 + 1), inner ? CoilSide::Inner : CoilSide::Outer,
				  std::round(angle)};
		t.tau_s = uni(2, 20);
		t.offset_C = uni(-0.2, 0.2);
		dev.thermistors.push_back(t);
	}
	dev.noise.arw_deg_rt_h = uni(0.0005, 0.003);
	dev.noise.bias_instability_dph = uni(0.002, 0.008);
	d.rate_hz = logUni(1.0, 100.0);
	std::ostringstream s;
	s.precision(3);
	s << "seed " << seed << ": " << count << " thermistors, " << d.rate_hz << " Hz, C x" << f << ", offset "
	  << dev.winding.midpoint_offset_m << " m, q " << dev.thermistor_quantum_C << " C, arw " << dev.noise.arw_deg_rt_h;
	d.summary = s.str();
	dev.validate();
	return d;
}

std::vector<std::uint64_t> tuningSeeds()
{
	std::vector<std::uint64_t> s;
	for (std::uint64_t i = 1; i <= 16; i++) s.push_back(i);
	return s;
}

std::vector<std::uint64_t> heldOutSeeds()
{
	std::vector<std::uint64_t> s;
	for (std::uint64_t i = 17; i <= 24; i++) s.push_back(i);
	return s;
}

std::vector<std::uint64_t> finalSeeds()
{
	std::vector<std::uint64_t> s;
	for (std::uint64_t i = 25; i <= 32; i++) s.push_back(i);
	return s;
}

std::vector<std::uint64_t> freshSeeds()
{
	std::vector<std::uint64_t> s;
	for (std::uint64_t i = 33; i <= 40; i++) s.push_back(i);
	return s;
}

}  // namespace fogtest
