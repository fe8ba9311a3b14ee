/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SyntheticCoil.h
 * Test data with known truth, independent of the code under test: a small thermal network of
 * a fiber coil in a chamber (housing -> two outer nodes -> two inner nodes, explicit Euler,
 * 1 s steps) whose bias is a known function of the NODE temperatures and their exact
 * derivatives (static polynomial + Shupe-like rate terms + radial-gradient terms). Thermistors
 * Ti1/To1 (0 deg) and Ti2/To2 (180 deg) read the nodes through a 10 s lag, quantised to
 * 0.01 degC. Profiles: "A" = the seed's chamber cycle (25 -> -40 C at 1 C/min, 2 h soak,
 * -> 60 C at 1 C/min, 2 h soak); "B" = a different one (ramps at 0.5 C/min, a 1 h-period sine,
 * steps) for held-out validation. */

#include <mrpt_fog/obs/FogSeries.h>

#include <cmath>
#include <random>
#include <string>

namespace fogtest
{
inline double chamberA(double t)
{
	const double r = 1.0 / 60.0;  // 1 C/min
	const double t1 = 65 / r, t2 = t1 + 7200, t3 = t2 + 100 / r;
	if (t < t1) return 25 - r * t;
	if (t < t2) return -40;
	if (t < t3) return -40 + r * (t - t2);
	return 60;
}
inline double durationA() { return 65 * 60.0 + 7200 + 100 * 60.0 + 7200; }

inline double chamberB(double t)
{
	const double r = 0.5 / 60.0;
	if (t < 3600) return 20 + r * t;  // 20 -> 50
	if (t < 7200) return 50;
	if (t < 18000) return 35 + 15 * std::cos(2 * M_PI * (t - 7200) / 3600.0);  // sine, 1 h period
	if (t < 21600) return 0;  // step down
	return 30;  // step up
}
inline double durationB() { return 25200; }

struct CoilTruth
{
	// bias [deg/h] = static(Tmean) + sum_j shupe_j * dnode_j/dt [C/s] + grad * sum (I_j - O_j)
	double static_lin = 0.002, static_quad = 2e-5;
	double shupe_i1 = 60, shupe_o1 = -35, shupe_i2 = 40, shupe_o2 = -55;
	double grad = 0.01;
};

/** profile "A" or "B"; noise_dph: white gyro noise per 1 Hz sample. */
inline mrpt_fog::FogSeries makeCoilRun(const std::string& profile, unsigned seed, double noise_dph = 0.003,
									   const CoilTruth& truth = {})
{
	using namespace mrpt_fog;
	FogSeries s;
	s.sensor_label = "FOG";
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}, {"To1", CoilSide::Outer, 0}, {"Ti2", CoilSide::Inner, 180},
					 {"To2", CoilSide::Outer, 180}};
	s.has_axis = {{false, false, true}};
	const bool A = profile == "A";
	const double dur = A ? durationA() : durationB();
	const auto chamber = [&](double t) { return A ? chamberA(t) : chamberB(t); };
	std::mt19937 rng(seed);
	std::normal_distribution<double> nd(0.0, 1.0);
	double T0 = chamber(0);
	double H = T0, O1 = T0, O2 = T0, I1 = T0, I2 = T0;
	double m[4] = {T0, T0, T0, T0};  // thermistor lag states (Ti1, To1, Ti2, To2)
	const double dt = 1.0;
	s.temp_C.assign(4, {});
	for (double t = 0; t < dur; t += dt)
	{
		const double Ta = chamber(t);
		const double dH = (Ta - H) / 1200, dO1 = (H - O1) / 200, dO2 = (H - O2) / 350;
		const double dI1 = (O1 - I1) / 400, dI2 = (O2 - I2) / 600;
		const double Tm = 0.25 * (O1 + O2 + I1 + I2) - 20;
		const double bias = 1.5 + truth.static_lin * Tm + truth.static_quad * Tm * Tm +
							truth.shupe_i1 * dI1 + truth.shupe_o1 * dO1 + truth.shupe_i2 * dI2 + truth.shupe_o2 * dO2 +
							truth.grad * ((I1 - O1) + (I2 - O2));
		s.time_s.push_back(t);
		s.rate_dph[2].push_back(bias + noise_dph * nd(rng));
		const double node[4] = {I1, O1, I2, O2};
		for (int i = 0; i < 4; i++)
		{
			m[i] += (node[i] - m[i]) * dt / 10.0;
			s.temp_C[i].push_back(std::round(m[i] * 100) / 100);
		}
		H += dH * dt;
		O1 += dO1 * dt;
		O2 += dO2 * dt;
		I1 += dI1 * dt;
		I2 += dI2 * dt;
	}
	return s;
}
}  // namespace fogtest
