/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ChamberReconstruction.h
 * The chamber air temperature of a measured run, reconstructed from its thermistor readings
 * through the simulator's thermal network (a regularised linear inverse), for
 * `fog-discrepancy --sim` on a run whose chamber program is not given.
 *
 * The network (coil layers x sectors, hub, housing, electronics, thermistor lags) is linear and
 * time-invariant in the air temperature; the gyro power enters additively. The air is a
 * piecewise-linear function of time with knots every knot_spacing_s: air(t) = a_0 + sum_j d_j
 * r_j(t), r_j a unit ramp over knot interval j (0 before, 1 after). So every thermistor reads
 *   T_i(t) = B_i(t) + a_0 + sum_j d_j u_i(t - t_{j-1}),
 * B = the simulator at 0 C air with the run's power (steady start), u = its response to one unit
 * ramp from rest: two simulations, the other columns are time shifts of u. (a_0, d) minimise
 *   sum_i,k (T_meas_ik - T_i(t_k))^2 + lambda sum_j (d_j - d_{j-1})^2
 * (the penalty is on the second difference of the air at the knots), lambda by generalised
 * cross-validation over a grid. Rows: every sample with a reading, thinned to at most
 * max_rows_per_thermistor per thermistor.
 * Uncertainty: 95 % half-width of the air at each knot, 1.96 sqrt(diag(L C L^T)) with
 * C = s2_LR (G^T G + lambda P)^-1 and L the cumulative sum, s2_LR the long-run residual variance
 * by batch means (blocks of round(sqrt(m)) rows, per thermistor). Approximate: it ignores the
 * regularisation bias (a step in the air is smoothed over about one knot spacing) and the
 * network's own error (that is what the thermal-fit check, ThermalFit.h, judges).
 * Identifiability, stated: with a free air input, a slow common heat that follows no air is not
 * separable from warmer air (only its angular/radial pattern and its timing with the power
 * remain visible); the thermistor offsets' mean is not separable from a_0 (the offsets are
 * calibrated afterwards as usual).
 */

#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/ErrorEffects.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <cstddef>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct AirReconstructionOptions
{
	/** Air knots every this [s] (rounded to whole simulator steps). On fog-sim's `rich` run at
	 * 0.05 Hz: 60 s fits the thermistors to 0.0056 C RMS (the true profile: 0.0042 C), 120 s to
	 * 0.0078 C, 600 s to 0.11 C (docs/guide/model-gap-simulator.md). */
	double knot_spacing_s = 60.0;
	std::size_t max_knots = 800;  //!< the spacing grows for long runs to keep at most this many
	std::size_t max_rows_per_thermistor = 3000;  //!< rows are thinned to at most this many
	double lambda = 0;  //!< > 0: this regularisation weight, no GCV search (faster)
	bool uncertainty = true;  //!< false: no 95 % half-widths (faster)
};

struct AirReconstruction
{
	std::vector<double> knot_time_s;  //!< from the first run sample [s]
	std::vector<double> knot_air_C;  //!< reconstructed air at the knots [degC]
	std::vector<double> knot_ci95_half_C;  //!< 95 % half-widths (see file comment)
	double lambda = 0;  //!< chosen by GCV
	double fit_rms_C = 0;  //!< thermistor residual RMS of the reconstruction
	double mean_ci95_half_C = 0, max_ci95_half_C = 0;
	/** Air at time t from the first sample (linear between knots, held beyond). */
	double airAt(double t_s) const;
};

/** Reconstructs the air for a run driven by `states` (power, table, field per simulator step on
 * a grid of 1 / rate_hz from the first run sample; their air_C is ignored). Run sample k is
 * simulator step sim_index[k]. Throws std::invalid_argument when the run has no thermistor
 * reading or a run thermistor is not one of the device's. */
AirReconstruction reconstructChamberAir(const sim::FogDevice& device, const sim::EffectSet& effects,
										double thermal_time_scale, const std::vector<sim::ChamberState>& states,
										double rate_hz, const FogSeries& run, const std::vector<std::size_t>& sim_index,
										const AirReconstructionOptions& opt = {});

}  // namespace mrpt_fog::discrepancy
