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
 *    Order 2 (the default) removes the delay: the slopes over the whole window
 *    and over its last half are the derivative at their two centroids, and the line through
 *    them is evaluated at t (CausalRateTracker::extrapolatedRate): exact for a quadratic,
 *    still causal, about 5x the rate noise of order 1. The 30 s delay of order 1 was the
 *    largest part of the held-out error above the noise floor on profiles with steps and
 *    sines (docs/validation/generalization.md, "Why the default lost").
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
/** The estimators (see the file comment). */
enum class RateEstimatorKind : unsigned char
{
	Causal,  //!< "causal"
	SavitzkyGolay  //!< "savgol" (non-causal: studies only)
};
/** "causal" / "savgol" (the spelling in calibration files and on command lines). */
const char* toString(RateEstimatorKind kind);
/** Parses "causal" / "savgol"; throws std::invalid_argument "rate estimator kind must be
 * 'causal' or 'savgol', got '...'". */
RateEstimatorKind rateEstimatorKindFromString(const std::string& text);

/** Which estimator and its parameters, as stored in a calibration file. */
struct RateEstimatorSettings
{
	RateEstimatorKind kind = RateEstimatorKind::Causal;
	double window_s = 60.0;  //!< window length [s]
	/** causal: 1 = the window's slope (delayed by about window_s / 2), 2 = delay-compensated
	 * (default, see the file comment); savgol: the local polynomial's order 1..4. */
	int poly_order = 2;

	/** e.g. "causal(window_s=60, order=2)", "causal(window_s=60)" (order 1) or "savgol(window_s=60, order=2)". */
	std::string describe() const;
	/** Throws std::invalid_argument (naming the field) for window_s not finite or <= 0, or an
	 * order outside the kind's range. */
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

/** Reading quantum of a temperature column [degC]: the smallest change between consecutive
 * valid readings (changes below 1e-9 degC ignored). A quantised thermistor changes by whole
 * quanta (0.01, 1/16, 1 degC); unquantised noisy readings give a small value. 0 when the column
 * never changes. O(1) memory. */
double readingQuantum_C(const std::vector<double>& x);

/** readingQuantum_C() fed one reading at a time (logs read in chunks): the same number. */
class ReadingQuantum
{
   public:
	void add(double x_C)
	{
		if (!std::isfinite(x_C)) return;
		const double d = std::abs(x_C - prev_);
		if (d > 1e-9 && d < q_) q_ = d;  // NaN prev_: false
		prev_ = x_C;
	}
	/** [degC]; 0 when no two valid readings differ. */
	double quantum_C() const { return std::isfinite(q_) ? q_ : 0.0; }

   private:
	double prev_ = std::numeric_limits<double>::quiet_NaN();
	double q_ = std::numeric_limits<double>::infinity();
};

/** Quantum at which the default 60 s window was designed (0.01 degC; the seed's chamber logs). */
constexpr double kReferenceQuantum_C = 0.01;
/** Quanta up to this keep the base window; above it the window grows in proportion to the
 * quantum (windowForQuantum_s). Twice kReferenceQuantum_C: chosen on the generalization bench's
 * tuning devices, where 0.01 degC (the window keeping the reference's quantisation bound: 375 s
 * at 1/16 degC) delayed the rates more than the quantisation error it saved (docs/validation/generalization.md,
 * "One calibration run"). */
constexpr double kQuantumWindowStart_C = 0.02;
/** Longest window windowForQuantum_s() gives [s]: the coil-housing time constants are 15-50 min,
 * a longer window no longer follows the rates the bias responds to. */
constexpr double kMaxQuantumWindow_s = 1200.0;

/** The rate window for readings of quantum `quantum_C`: the quantisation error of a
 * window's slope is bounded by about 1.5 q / window (7.5 q / window for the delay-compensated
 * order 2: its half-window slope counts twice), so the window grows in proportion to the
 * quantum to keep the bound of `base_window_s` at kQuantumWindowStart_C (twice the bound at
 * the 0.01 degC the base was designed for; a longer window delays the rates more):
 * base x max(1, q / 0.02 degC) rounded to whole seconds, at most kMaxQuantumWindow_s (never
 * below base; a quantum within 1e-6 of 0.02 degC, decimal round-off, keeps base exactly). A
 * 1/16 degC thermistor gets 188 s for a 60 s base (375 s before the bench's one-run
 * calibration showed the delay cost); 0.01 and 1/256 degC keep the base. */
double windowForQuantum_s(double base_window_s, double quantum_C);

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
	/** Mean time of the valid samples of channel c in the window [s] (NaN when none): the time
	 * at which rate(c) is the derivative for a smooth signal. */
	double centroid_s(std::size_t c) const
	{
		return n_[c] > 0 ? t_ref_ + s1_[c] / n_[c] : std::numeric_limits<double>::quiet_NaN();
	}
	/** The delay-compensated rate (causal estimator of order 2) from a tracker over the whole
	 * window (`full`) and one over its last half (`half`) fed the same samples: the two slopes
	 * are the derivative at their centroids; the line through them, evaluated at `time_s`, is
	 * exact for a quadratic signal sampled regularly. NaN when either slope is. */
	static double extrapolatedRate(const CausalRateTracker& full, const CausalRateTracker& half, std::size_t c,
								   double time_s)
	{
		const double ra = full.rate(c), rb = half.rate(c);
		const double ca = full.centroid_s(c), cb = half.centroid_s(c);
		if (!(cb > ca)) return rb;  // one sample more in the whole window only: nothing to extrapolate from
		return rb + (rb - ra) * (time_s - cb) / (cb - ca);
	}
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
	std::size_t channels() const { return channels_; }
	double window_s() const { return window_s_; }
	void reset();

   private:
	friend class Compensator;  // its per-sample loop inlines the fixed-count forms below
	/** push() and ratesAndCoverage() for a compile-time channel count NC == channels() (NC = 0:
	 * any count), inline in the caller's loop: same results, no per-call dispatch. Defined in
	 * internal/mrpt_fog/model/CausalRateTrackerInline.h (not installed). */
	template <std::size_t NC>
	void pushFixed(double time_s, const double* x);
	template <std::size_t NC>
	std::uint32_t ratesAndCoverageFixed(double* rate_out, double min_span_s) const;
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
	explicit CausalRateEstimator(double window_s, int order = 1);
	RateEstimatorSettings settings() const override;
	bool isCausal() const override { return true; }
	std::vector<double> estimate(const std::vector<double>& time_s, const std::vector<double>& x) const override;

   private:
	double window_s_;
	int order_ = 1;
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

}  // namespace mrpt_fog
