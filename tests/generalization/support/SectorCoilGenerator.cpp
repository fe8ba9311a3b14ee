/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "SectorCoilGenerator.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <random>

namespace fogtest
{
SectorCoilParams drawSectorCoil(std::uint64_t seed)
{
	std::mt19937_64 rng(0x51ed2701ull + seed * 7919ull);
	const auto uni = [&](double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); };
	SectorCoilParams p;
	p.cap_scale = std::exp(uni(std::log(0.5), std::log(2.0)));
	p.g_radial_W_K = uni(0.2, 0.8);
	p.g_housing_air_W_K = uni(0.3, 1.0);
	p.g_outer_housing_W_K = uni(0.05, 0.2);
	for (double& w : p.w_dph_per_C_min) w = (uni(0, 1) < 0.5 ? -1 : 1) * uni(0.02, 0.3);
	p.stress_dph_per_C = uni(0.02, 0.1);
	p.c1_dph_per_C = uni(-2e-3, 2e-3);
	p.c2_dph_per_C2 = uni(-2e-5, 2e-5);
	p.lag_s = uni(2, 20);
	p.quantum_C = uni(0, 1) < 0.5 ? 0.01 : 1.0 / 256.0;
	p.reading_noise_C = uni(0.001, 0.005);
	for (double& o : p.offsets_C) o = uni(-0.2, 0.2);
	p.arw_deg_rt_h = uni(0.0005, 0.003);
	p.bias_instability_dph = uni(0.002, 0.008);
	p.thermistors = 1 + static_cast<int>(std::floor(uni(0, 4)));
	p.rate_hz = std::exp(uni(0.0, std::log(100.0)));
	return p;
}

mrpt_fog::FogSeries simulateSectorCoil(const SectorCoilParams& p, const mrpt_fog::sim::ChamberProfile& profile,
									   std::uint64_t run_seed, bool noise_only)
{
	using mrpt_fog::CoilSide;
	// Nodes: 0 housing, 1 hub, 2..4 outer sectors (0/120/240 deg), 5..7 inner sectors.
	constexpr int N = 8, H = 0, B = 1, O = 2, I = 5;
	std::array<double, N> C{900, 60, 25, 25, 25, 25, 25, 25};
	for (double& c : C) c *= p.cap_scale;
	const double g_t = 0.08, g_hub_inner = 0.03, g_hub_air = 0.1, heat_W = 2.5, leak_W = 0.15;
	const double period = 1.0 / p.rate_hz;
	const double dt = std::min(0.5, period);
	std::mt19937_64 rng(run_seed * 0x9E3779B97F4A7C15ull + 17);
	std::normal_distribution<double> gauss(0.0, 1.0);
	mrpt_fog::FogSeries s;
	s.sensor_label = "LUMPED";
	s.has_axis = {false, false, true};
	const char* names[4] = {"Ti1", "To1", "Ti2", "To2"};
	const int node_of[4] = {I, O, I + 1, O + 1};
	for (int i = 0; i < p.thermistors; i++)
		s.thermistors.push_back({names[i], i % 2 == 0 ? CoilSide::Inner : CoilSide::Outer, i < 2 ? 0.0 : 120.0});
	s.temp_C.resize(static_cast<std::size_t>(p.thermistors));
	// Initial state: steady with the initial air temperature and power (solved by relaxation).
	const auto s0 = profile.stateAt(0.0);
	std::array<double, N> T;
	T.fill(s0.air_C);
	const auto derivative = [&](const std::array<double, N>& x, double air, bool on, std::array<double, N>& d) {
		std::array<double, N> q{};
		q[H] += p.g_housing_air_W_K * (air - x[H]) + (on ? heat_W - leak_W : 0.0);
		q[B] += g_hub_air * (air - x[B]);
		for (int j = 0; j < 3; j++)
		{
			const int o = O + j, in = I + j, on_next = O + (j + 1) % 3, in_next = I + (j + 1) % 3;
			const double fo = p.g_outer_housing_W_K * (x[H] - x[o]);
			q[o] += fo;
			q[H] -= fo;
			const double fr = p.g_radial_W_K * (x[o] - x[in]);
			q[in] += fr;
			q[o] -= fr;
			const double fh = g_hub_inner * (x[B] - x[in]);
			q[in] += fh;
			q[B] -= fh;
			const double fto = g_t * (x[on_next] - x[o]), fti = g_t * (x[in_next] - x[in]);
			q[o] += fto;
			q[on_next] -= fto;
			q[in] += fti;
			q[in_next] -= fti;
		}
		q[O] += on ? leak_W : 0.0;
		for (int n = 0; n < N; n++) d[n] = q[n] / C[n];
	};
	// Steady state: the network is linear, d = A T + b; solve A T = -b.
	std::array<double, N> d, zero{};
	derivative(zero, s0.air_C, s0.power_on, d);
	Eigen::Matrix<double, N, N> A;
	Eigen::Matrix<double, N, 1> b;
	for (int n = 0; n < N; n++) b[n] = d[n];
	for (int m = 0; m < N; m++)
	{
		std::array<double, N> e{};
		e[m] = 1.0;
		derivative(e, s0.air_C, s0.power_on, d);
		for (int n = 0; n < N; n++) A(n, m) = d[n] - b[n];
	}
	const Eigen::Matrix<double, N, 1> x = A.fullPivLu().solve(-b);
	for (int n = 0; n < N; n++) T[n] = x[n];
	std::array<double, 4> reading;
	for (int i = 0; i < p.thermistors; i++) reading[i] = T[node_of[i]];
	const double white_sigma = 60.0 * p.arw_deg_rt_h * std::sqrt(p.rate_hz);
	const double gm_tau = 300.0;
	double gm = p.bias_instability_dph * gauss(rng);
	double t = 0, next_out = 0;
	std::array<double, N> Tprev = T;
	double t_prev_out = 0;
	while (t <= profile.duration_s() + 1e-9)
	{
		if (t >= next_out - 1e-9)
		{
			const auto st = profile.stateAt(t);
			double bias = 0.4;
			if (!noise_only && t > 0)
			{
				const double span_min = (t - t_prev_out) / 60.0;
				for (int j = 0; j < 3; j++)
				{
					bias += p.w_dph_per_C_min[j] * (T[O + j] - Tprev[O + j]) / span_min;
					bias += p.w_dph_per_C_min[3 + j] * (T[I + j] - Tprev[I + j]) / span_min;
				}
			}
			if (!noise_only)
			{
				const double gi = (T[I] + T[I + 1] + T[I + 2]) / 3, go = (T[O] + T[O + 1] + T[O + 2]) / 3;
				const double x = T[H] - 25.0;
				bias += p.stress_dph_per_C * (gi - go) + p.c1_dph_per_C * x + p.c2_dph_per_C2 * x * x;
			}
			const double a = std::exp(-period / gm_tau);
			gm = a * gm + p.bias_instability_dph * std::sqrt(1 - a * a) * gauss(rng);
			s.time_s.push_back(t);
			s.rate_dph[2].push_back(bias + gm + white_sigma * gauss(rng));
			s.power.push_back(st.power_on ? 1.0 : 0.0);
			for (int i = 0; i < p.thermistors; i++)
			{
				double v = reading[i] + p.offsets_C[i] + p.reading_noise_C * gauss(rng);
				s.temp_C[i].push_back(std::round(v / p.quantum_C) * p.quantum_C);
			}
			Tprev = T;
			t_prev_out = t;
			next_out += period;
		}
		const auto st = profile.stateAt(t + 0.5 * dt);
		derivative(T, st.air_C, st.power_on, d);
		for (int n = 0; n < N; n++) T[n] += dt * d[n];
		for (int i = 0; i < p.thermistors; i++) reading[i] += dt / p.lag_s * (T[node_of[i]] - reading[i]);
		t += dt;
	}
	return s;
}

}  // namespace fogtest
