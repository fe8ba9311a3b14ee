/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SectorCoilGenerator.h
 * Test support: a second chamber-run generator written apart from fog-sim, so the
 * bench does not only judge the fit on the physics it was developed with. Structure: 8 nodes
 * (housing, hub, 3 outer + 3 inner coil sectors at 0/120/240 deg), explicit Euler at 0.5 s
 * sub-steps, the electronics heating the housing and the outer sector at 0 deg; the bias is a
 * Shupe-like sum over the coil nodes of w_n dT_n/dt (each weight drawn on its own, not from a
 * winding), a stress term k (mean inner - mean outer), a quadratic in the housing temperature
 * and a constant; gyro noise white (ARW) + first-order Gauss-Markov; thermistors (1..4: Ti1 on
 * inner 0 deg, To1 outer 0 deg, Ti2 inner 120 deg, To2 outer 120 deg) read their node through a
 * first-order lag, with offset, white noise and quantisation. Nothing here is shared with
 * mrpt_fog/sim except the ChamberProfile (air temperature and power versus time).
 * Parameter ranges (drawn per seed): node capacities x (0.5..2), radial conductance 0.2..0.8 W/K
 * per sector, housing-air 0.3..1 W/K, Shupe weights +-(0.02..0.3) deg/h per degC/min, stress
 * 0.02..0.1 deg/h per degC, lag 2..20 s, quantum 0.01 / 1/256 degC, ARW 0.0005..0.003.
 */

#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>

#include <cstdint>

namespace fogtest
{
struct SectorCoilParams
{
	double cap_scale = 1.0;
	double g_radial_W_K = 0.5, g_housing_air_W_K = 0.5, g_outer_housing_W_K = 0.1;
	double w_dph_per_C_min[6] = {0.1, -0.1, 0.05, -0.05, 0.08, -0.08};  // O1..O3, I1..I3
	double stress_dph_per_C = 0.05;
	double c1_dph_per_C = 1e-3, c2_dph_per_C2 = 1e-5;
	double lag_s = 5, quantum_C = 0.01, reading_noise_C = 0.003;
	double offsets_C[4] = {0, 0, 0, 0};
	double arw_deg_rt_h = 0.001, bias_instability_dph = 0.003;
	int thermistors = 4;
	double rate_hz = 1.0;
};

/** Parameters of sector-coil device `seed` (ranges in the file comment). */
SectorCoilParams drawSectorCoil(std::uint64_t seed);

/** Simulates a chamber run; `noise_only` gives the same device's output with no thermal error
 * (same noise realisation): its 100 s stability is the device's noise floor. */
mrpt_fog::FogSeries simulateSectorCoil(const SectorCoilParams& p, const mrpt_fog::sim::ChamberProfile& profile,
									   std::uint64_t run_seed, bool noise_only = false);

}  // namespace fogtest
