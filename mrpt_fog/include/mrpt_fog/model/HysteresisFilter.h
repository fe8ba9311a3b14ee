/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file HysteresisFilter.h
 * Hysteresis operators of thermistor readings, causal, state carried sample to sample: the bias
 * of a coil whose adhesive and jacket stress sticks while the temperature reverses (a heating vs
 * cooling offset). Each channel (thermistor i, operator, width w [degC]) outputs h in [-1, 1]:
 *
 *  - Play (backlash, the elementary operator of a Prandtl-Ishlinskii model), half-width w:
 *      p <- min(max(p, x - w), x + w),   h = (x - p) / w.
 *    The position p moves only when the reading x leaves [p - w, p + w]: after a reversal h is
 *    linear in the temperature until it saturates at +-1 (heating: +1, cooling: -1); it holds
 *    through soaks. Reading noise or a quantisation staircase of peak-to-peak amplitude a moves
 *    h by at most a / w and never flips its branch while a < 2 w.
 *  - Branch (exponential approach to +-1), span w:
 *      h <- s + (h - s) exp(-|dq| / w),   s = sign(dq),
 *    with dq the change of a play of half-width kHysteresisDeadBand_C driven by the reading (a
 *    dead band): the sign of the raw reading's change flips on every quantum or noise step and
 *    would make h chatter; the dead band's position reverses only after the reading has moved
 *    2 kHysteresisDeadBand_C back, so noise below that never flips the branch. (The price: the
 *    branch starts its approach kHysteresisDeadBand_C after a reversal.)
 *
 * Warm start: at the first valid reading p (and the dead band's position) = that reading and
 * h = 0 (no branch known: the device's earlier history is unknown). A NaN reading gives a NaN
 * output and leaves the state as it was; the next valid reading continues from it (a dropout is
 * bridged by one step of the operator, exact for the play: it depends only on the path's
 * extremes, not on time). Rate-independent: no time input.
 */

#include <cstddef>
#include <vector>

namespace mrpt_fog
{
/** Dead band of the branch operator [degC]: five quanta of the usual 0.01 C thermistor reading
 * (half the peak-to-peak noise it rides through), a tenth of the narrowest span the discrepancy
 * workflow names (0.5 C). */
inline constexpr double kHysteresisDeadBand_C = 0.05;

enum class HysteresisOperator : unsigned char
{
	Play = 0,  //!< play (backlash) of half-width w
	Branch = 1  //!< exponential branch of span w, behind a dead band of kHysteresisDeadBand_C
};

/** One operator of the bank: the thermistor it reads (index into the caller's temperature array),
 * the operator and its width [degC] (> 0: play half-width or branch span). */
struct HysteresisChannel
{
	int thermistor = 0;
	HysteresisOperator op = HysteresisOperator::Play;
	double width_C = 1.0;
	bool operator==(const HysteresisChannel& o) const
	{
		return thermistor == o.thermistor && op == o.op && width_C == o.width_C;
	}
};

class HysteresisFilterBank
{
   public:
	HysteresisFilterBank() = default;
	/** Throws std::invalid_argument for a width that is not finite and > 0. */
	explicit HysteresisFilterBank(std::vector<HysteresisChannel> channels);
	std::size_t size() const { return ch_.size(); }
	const std::vector<HysteresisChannel>& channels() const { return ch_; }
	/** One sample: the readings [degC], indexed by HysteresisChannel::thermistor. */
	void push(const double* temp_C);
	/** After push(): the output of channel i, in [-1, 1] (NaN: no valid reading now). */
	double value(std::size_t i) const { return h_[i]; }
	/** Forgets the state (the next valid reading warm-starts every channel again). */
	void reset();

   private:
	std::vector<HysteresisChannel> ch_;
	std::vector<double> p_, state_, h_;  // play or dead-band position [degC]; branch state; output
};

}  // namespace mrpt_fog
