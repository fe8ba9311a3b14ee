/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file LagFilter.h
 * A bank of first-order lags of thermistor readings, causal, state carried sample to sample: what
 * a point inside the coil sees of a boundary sensor's history (radial diffusion, the housing).
 * For each channel (thermistor i, time constant tau [s]) the lagged temperature y follows
 *
 *   dy/dt = (T_i(t) - y) / tau,
 *
 * integrated EXACTLY for a reading that varies linearly between samples (first-order hold):
 * with h = dt / tau, a = exp(-h),
 *
 *   y_k = a y_{k-1} + (1 - a) T_{k-1} + (T_k - T_{k-1}) (1 - (1 - a) / h),
 *
 * and its rate is dy/dt = (T_k - y_k) / tau [degC/s] (no differentiation of the reading: a
 * quantisation staircase or reading noise is smoothed, not amplified). On a ramp of r degC/s the
 * rate tends to r with the lag tau; after a step it decays as exp(-t / tau).
 *
 * Warm start: y = the first valid reading (the device at thermal equilibrium, rate 0), so the
 * rate exists from the first sample. A NaN reading gives a NaN rate and leaves the state as it
 * was; the next valid reading is reached by the same first-order hold from the last valid one
 * (a dropout or a gap of a burst log is bridged by a straight line). A time that does not
 * advance (dt <= 0) changes only the held reading.
 */

#include <cstddef>
#include <vector>

namespace mrpt_fog
{
/** One lag of the bank: the thermistor it reads (index into the caller's temperature array)
 * and its time constant [s] (> 0). */
struct LagChannel
{
	int thermistor = 0;
	double tau_s = 0;
	bool operator==(const LagChannel& o) const { return thermistor == o.thermistor && tau_s == o.tau_s; }
};

class LagFilterBank
{
   public:
	LagFilterBank() = default;
	/** Throws std::invalid_argument for a time constant that is not finite and > 0. */
	explicit LagFilterBank(std::vector<LagChannel> channels);
	std::size_t size() const { return ch_.size(); }
	const std::vector<LagChannel>& channels() const { return ch_; }
	/** One sample: time [s] and the readings [degC], indexed by LagChannel::thermistor. */
	void push(double time_s, const double* temp_C);
	/** After push(): the lagged temperature's rate of channel i [degC/s] (NaN: no valid reading now). */
	double rate_C_per_s(std::size_t i) const { return rate_[i]; }
	/** After push(): the lagged temperature of channel i [degC] (NaN before the first valid reading). */
	double lagged_C(std::size_t i) const { return y_[i]; }
	/** Forgets the state (the next valid reading warm-starts every channel again). */
	void reset();

   private:
	std::vector<LagChannel> ch_;
	std::vector<double> y_, x_prev_, t_prev_, rate_;
};

}  // namespace mrpt_fog
