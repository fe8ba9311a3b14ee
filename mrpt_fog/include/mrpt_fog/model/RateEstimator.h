/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RateEstimator.h
 * Temperature rates dT/dt [degC/s] from noisy, quantised (0.01 degC) thermistor samples with
 * irregular timestamps, NaN dropouts and gaps. Two estimators share one interface:
 *
 *  - "causal" (CausalRateEstimator): slope of a least-squares line through the samples of the
 *    trailing window (t - window_s, t]. Uses only past samples, O(1) amortised per sample
 *    (running sums over a ring buffer, recomputed exactly every 16 buffer turns so round-off
 *    cannot drift). Delay: for a smooth signal the slope is the derivative at the centre of the
 *    window, i.e. about window_s / 2 late. This is what the real-time compensator uses, and the
 *    fit uses it by default so that the compensator reproduces the fitted model (to round-off).
 *  - "savgol" (SavitzkyGolayRateEstimator): derivative at t of a local polynomial (order 1..4)
 *    fitted by least squares over the centred window [t - window_s/2, t + window_s/2] (a
 *    Savitzky-Golay filter generalised to irregular timestamps). Non-causal, no delay; for
 *    calibration studies only.
 *
 * NaN samples are skipped (they never enter a window). A rate is NaN where it cannot be
 * estimated: a NaN input sample, or fewer than 2 valid samples (2 distinct times) in the window
 * (start of the log, after a gap longer than the window). Settings are recorded by name +
 * parameters (RateEstimatorSettings) in calibration files.
 */

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** Which estimator and its parameters, as stored in a calibration file. */
struct RateEstimatorSettings
{
	std::string kind = "causal";  //!< "causal" or "savgol"
	double window_s = 60.0;  //!< window length [s]
	int poly_order = 1;  //!< local polynomial order (causal: always 1; savgol: 1..4)

	/** e.g. "causal(window_s=60)" or "savgol(window_s=60, order=2)". */
	std::string describe() const;
	/** Throws std::invalid_argument (naming the field) for an unknown kind, window_s not
	 * finite or <= 0, or an order outside the kind's range. */
	void validate() const;
	bool operator==(const RateEstimatorSettings& o) const
	{
		return kind == o.kind && window_s == o.window_s && poly_order == o.poly_order;
	}
};

/** Batch interface: the rate of a whole column. */
class RateEstimator
{
   public:
	virtual ~RateEstimator() = default;
	virtual RateEstimatorSettings settings() const = 0;
	virtual bool isCausal() const = 0;
	/** dx/dt [unit of x per s] at every sample; NaN where not estimable (see file comment).
	 * Throws std::invalid_argument if sizes differ or time is not strictly increasing. */
	virtual std::vector<double> estimate(const std::vector<double>& time_s, const std::vector<double>& x) const = 0;
};

/** Builds the estimator named by settings (validated first; throws std::invalid_argument). */
std::unique_ptr<RateEstimator> makeRateEstimator(const RateEstimatorSettings& settings);

/** Streaming, multi-channel form of the causal estimator: all channels share the timestamps
 * (one thermistor per channel). push() is O(1) amortised; memory is the samples of one window.
 * Times must be strictly increasing across push() calls (throws std::invalid_argument). */
class CausalRateTracker
{
   public:
	CausalRateTracker(std::size_t channels, double window_s);
	/** Adds one sample; x[c] NaN = channel c missing at this time. */
	void push(double time_s, const double* x);
	/** Current slope of channel c [unit/s]; NaN with fewer than 2 valid samples in the window. */
	double rate(std::size_t c) const;
	/** Valid samples of channel c now inside the window. */
	std::size_t validCount(std::size_t c) const { return static_cast<std::size_t>(n_[c]); }
	/** Time spread of the valid samples of channel c in the window, as sqrt(12) x their
	 * standard deviation in time [s] (= the span for uniform sampling; 0 when < 2 samples).
	 * The compensator flags "rate warm-up" while this is below half the window. */
	double coveredSpan_s(std::size_t c) const;
	/** coveredSpan_s(c) >= span_s, without a square root (per-sample hot path). */
	bool spanAtLeast(std::size_t c, double span_s) const;
	/** All channels at once (the compensator's hot path, channels <= 32): rate_out[c] = rate(c);
	 * returns a bit mask of the channels whose coveredSpan_s is below min_span_s. */
	std::uint32_t ratesAndCoverage(double* rate_out, double min_span_s) const;
	/** push() and ratesAndCoverage() for a compile-time channel count NC == channels() (NC = 0:
	 * any count), inline in the caller's loop: same results, no per-call dispatch. */
	template <std::size_t NC>
	[[gnu::always_inline]] void pushFixed(double time_s, const double* x)
	{
		if (!pushSteady<NC>(time_s, x)) pushN<NC>(time_s, x);
	}
	template <std::size_t NC>
	std::uint32_t ratesAndCoverageFixed(double* rate_out, double min_span_s) const;
	std::size_t channels() const { return channels_; }
	double window_s() const { return window_s_; }
	void reset();

   private:
	/** push() for NC channels (NC = 0: channels_ at run time): the general case (any timing,
	 * dropouts, ring growth, exact rebuilds; validates the time), out of line. */
	template <std::size_t NC>
	void pushN(double time_s, const double* x);
	/** The common case of push() only (see its definition); false, with nothing changed, otherwise. */
	template <std::size_t NC>
	bool pushSteady(double time_s, const double* x);
	void dropOldest();
	void rebuildSums();
	std::size_t channels_;
	double window_s_;
	// Ring buffer: time, and per channel value (NaN when missing).
	std::vector<double> t_;
	std::vector<double> x_;  // [slot * channels_ + c]
	std::size_t head_ = 0, count_ = 0, since_rebuild_ = 0;
	double t_ref_ = 0.0;
	double last_t_ = 0.0;
	bool any_ = false;
	/** Per-channel running sums over the valid samples in the window, relative to t_ref_ and
	 * x_ref_ (one array per sum: the hot loops run over channels and vectorise). */
	std::vector<double> s1_, s2_, sx_, stx_, n_, x_ref_;
	std::vector<unsigned char> slot_all_valid_;  // per ring slot: no NaN channel
	/** Ring slots holding a NaN, and whether a NaN entered since the last exact rebuild: when
	 * both are zero every channel's time sums (s1, s2, n) are bitwise equal (same operations),
	 * so 1/den is computed once for all channels. */
	std::size_t nan_slots_ = 0;
	bool nan_since_rebuild_ = false;
	std::vector<char> ref_set_;  // scratch of rebuildSums
};

class CausalRateEstimator : public RateEstimator
{
   public:
	explicit CausalRateEstimator(double window_s);
	RateEstimatorSettings settings() const override;
	bool isCausal() const override { return true; }
	std::vector<double> estimate(const std::vector<double>& time_s, const std::vector<double>& x) const override;

   private:
	double window_s_;
};

class SavitzkyGolayRateEstimator : public RateEstimator
{
   public:
	SavitzkyGolayRateEstimator(double window_s, int poly_order);
	RateEstimatorSettings settings() const override;
	bool isCausal() const override { return false; }
	std::vector<double> estimate(const std::vector<double>& time_s, const std::vector<double>& x) const override;

   private:
	double window_s_;
	int order_;
};

namespace detail
{
/** The rate sums' update for one sample in and one out, every channel valid (restrict: no
 * aliasing; NC > 0: compile-time channel count, the loop unrolls). */
template <std::size_t NC>
[[gnu::always_inline]] inline void fusedRateSumsUpdate(std::size_t nc, const double* __restrict x, const double* __restrict xo,
								const double* __restrict xr, double d1, double d2, double dto, double dtn,
								double* __restrict s1, double* __restrict s2, double* __restrict sx,
								double* __restrict stx)
{
	const std::size_t n = NC ? NC : nc;
	for (std::size_t c = 0; c < n; c++)
	{
		const double dxo = xo[c] - xr[c], dxn = x[c] - xr[c];
		s1[c] += d1;
		s2[c] += d2;
		sx[c] += dxn - dxo;
		stx[c] += dtn * dxn - dto * dxo;
	}
}
}  // namespace detail

// ---- inline hot path of CausalRateTracker (the compensator's per-sample loop)
template <std::size_t NC>
[[gnu::always_inline]] inline bool CausalRateTracker::pushSteady(double time_s, const double* x)
{
	// The steady state of uniform sampling, taken by nearly every sample: the time is valid,
	// exactly one sample leaves the window as this one enters, both have every channel valid and
	// no exact rebuild is due. Anything else returns false with nothing changed, and pushN()
	// (which validates and handles every case) runs instead. The arithmetic is pushN's.
	const std::size_t nc = NC ? NC : channels_;
	const std::size_t mask = t_.size() - 1;  // capacity is a power of two
	const double t_out = time_s - window_s_;
	if (!(count_ >= 2 && time_s > last_t_ && time_s < std::numeric_limits<double>::infinity() &&
		  t_[head_] <= t_out && t_[(head_ + 1) & mask] > t_out && since_rebuild_ + 1 < 16 * t_.size() &&
		  slot_all_valid_[head_]))
		return false;
	// Sum of the values: NaN if one is NaN (or +inf meets -inf, which pushN also handles).
	double all = 0.0;
	for (std::size_t c = 0; c < nc; c++) all += x[c];
	if (std::isnan(all)) return false;
	last_t_ = time_s;
	const double dto = t_[head_] - t_ref_, dtn = time_s - t_ref_;
	const double d1 = dtn - dto, d2 = dtn * dtn - dto * dto;
	const double* xo = x_.data() + (head_ * nc);
	detail::fusedRateSumsUpdate<NC>(nc, x, xo, x_ref_.data(), d1, d2, dto, dtn, s1_.data(), s2_.data(), sx_.data(), stx_.data());
	// the new sample goes after the newest; the leaving one's slot is freed (head advances)
	const std::size_t slot = (head_ + count_) & mask;
	if (nc > 0) std::memcpy(x_.data() + (slot * nc), x, nc * sizeof(double));  // no channel: no buffer (null)
	t_[slot] = time_s;
	slot_all_valid_[slot] = 1;  // one valid slot in, one out: nan_slots_ unchanged
	head_ = (head_ + 1) & mask;
	since_rebuild_++;
	return true;
}

template <std::size_t NC>
[[gnu::always_inline]] inline std::uint32_t CausalRateTracker::ratesAndCoverageFixed(double* rate_out, double min_span_s) const
{
	const std::size_t nc = NC ? NC : channels_;
	const double span2 = min_span_s * min_span_s;
	// restrict: rate_out is the caller's buffer, never one of the sums (no overlap checks)
	double* __restrict out = rate_out;
	const double* __restrict S1 = s1_.data();
	const double* __restrict S2 = s2_.data();
	const double* __restrict SX = sx_.data();
	const double* __restrict STX = stx_.data();
	const double* __restrict N = n_.data();
	if (nc > 0 && nan_slots_ == 0 && !nan_since_rebuild_)
	{
		// Shared time sums: one reciprocal for all channels (bitwise the per-channel value).
		const double n = N[0];
		const double den = n * S2[0] - S1[0] * S1[0];  // = n^2 var(t)
		const bool ok = n >= 2 && den > 0;
		if (!ok)
		{
			for (std::size_t c = 0; c < nc; c++) out[c] = std::numeric_limits<double>::quiet_NaN();
			return nc >= 32 ? ~0u : ((1u << nc) - 1u);
		}
		const double inv = 1.0 / den, s1 = S1[0];
		if constexpr (NC == 4)
		{
			// As one 4-wide vector (the same operations per lane): written as whole vectors, so a
			// caller that loads the rates as vectors never reads back narrower stores (which
			// stalls store forwarding); compilers do not always vectorise the loop below.
			typedef double V4 __attribute__((vector_size(32)));
			V4 stx, sx;
			std::memcpy(&stx, STX, sizeof stx);
			std::memcpy(&sx, SX, sizeof sx);
			const V4 r = (n * stx - s1 * sx) * inv;
			std::memcpy(out, &r, sizeof r);
		}
		else
			for (std::size_t c = 0; c < nc; c++) out[c] = (n * STX[c] - s1 * SX[c]) * inv;
		const bool short_span = !(12.0 * den >= span2 * n * n);
		return short_span ? (nc >= 32 ? ~0u : ((1u << nc) - 1u)) : 0u;
	}
	std::uint32_t short_mask = 0;
	for (std::size_t c = 0; c < nc; c++)
	{
		const double n = N[c];
		const double den = n * S2[c] - S1[c] * S1[c];
		const bool ok = n >= 2 && den > 0;
		out[c] = ok ? (n * STX[c] - S1[c] * SX[c]) * (1.0 / den) : std::numeric_limits<double>::quiet_NaN();
		// coveredSpan^2 = 12 var(t) = 12 den / n^2
		if (!(ok && 12.0 * den >= span2 * n * n)) short_mask |= (1u << c);
	}
	return short_mask;
}

}  // namespace mrpt_fog
