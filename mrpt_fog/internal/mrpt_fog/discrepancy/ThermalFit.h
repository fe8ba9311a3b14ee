/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ThermalFit.h
 * How well the calibrated thermal network reproduces the measured thermistors, judged before the
 * optical (bias) part: a wrong simulated temperature field propagates into every simulated bias
 * term, so bias effects named on top of a bad thermal fit would be artefacts.
 *
 * Figures: thermistor residual (measured - simulated) RMS over all readings and per thermistor,
 * the worst thermistor, and where the largest |residual| is (thermistor, time).
 * Misfit: overall RMS above misfit_rms_C (default 0.1 C). Why 0.1 C: the default device's
 * elasto-optic coefficient (0.07 deg/h/C) turns a 0.1 C error of Tin - Tout into 0.007 deg/h,
 * the size of the seed's compensated 100 s stability (0.0069 deg/h), so above it the
 * temperature error alone can produce bias errors the workflow would misname; the thermistors'
 * own errors (0.01 C quantum, 0.003 C noise) and a correctly modelled run (0.004 C on fog-sim's
 * `rich` run, docs/guide/model-gap-simulator.md) stay well below.
 * What would fix it (ThermalFix), from the residual's shape, pooled over the thermistors, each
 * thermistor's residual regressed on [1, x] by least squares:
 *  - Lag: x = dT_meas/dt (central difference): r = -tau dT/dt is an unmodelled first-order lag
 *    (a thermistor lag, or a node slower or faster than modelled); tau = -slope;
 *  - HeatSource: x = the gyro power through a first-order lag (tau on a grid 120 s .. 4800 s,
 *    the best one): heat that follows the power and the network does not carry;
 *  - MissingNode: neither explains at least half of the residual's variance (a structure of the
 *    network is missing or wrong: a node, a path, or thermistor placements).
 * The larger explained share wins when it reaches 0.5.
 */

#include <mrpt_fog/discrepancy/TemperatureChannel.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Judges the thermistor residual (measured - simulated, per run thermistor, NaN where unknown)
 * of `run`. Never throws on NaN; an empty residual gives rms 0 and no misfit. */
ThermalFit assessThermalFit(const FogSeries& run, const std::vector<std::vector<double>>& residual_C,
							const ThermalFitOptions& opt = {});

}  // namespace mrpt_fog::discrepancy
