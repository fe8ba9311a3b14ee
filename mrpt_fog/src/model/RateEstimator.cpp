/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/model/CausalRateTrackerInline.h>
#include <mrpt_fog/model/RateEstimator.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;

void checkColumns(const std::vector<double>& t, const std::vector<double>& x)
{
	if (t.size() != x.size())
		throw std::invalid_argument("rate estimator: time_s has " + std::to_string(t.size()) + " samples but x has " +
									std::to_string(x.size()));
	for (std::size_t k = 0; k < t.size(); k++)
	{
		if (!std::isfinite(t[k])) throw std::invalid_argument("rate estimator: time_s[" + std::to_string(k) + "] is not finite");
		if (k > 0 && !(t[k] > t[k - 1]))
			throw std::invalid_argument("rate estimator: time_s not strictly increasing at sample " + std::to_string(k));
	}
}
}  // namespace

namespace
{
constexpr EnumName<RateEstimatorKind> kKinds[] = {{RateEstimatorKind::Causal, "causal"},
												  {RateEstimatorKind::SavitzkyGolay, "savgol"}};
}  // namespace

const char* toString(RateEstimatorKind kind) { return nameIn(kKinds, kind, "causal"); }

RateEstimatorKind rateEstimatorKindFromString(const std::string& text)
{
	if (const auto k = valueIn(kKinds, text)) return *k;
	throw std::invalid_argument("rate estimator kind must be 'causal' or 'savgol', got '" + text + "'");
}

std::string RateEstimatorSettings::describe() const
{
	std::ostringstream o;
	o << toString(kind) << "(window_s=" << formatValue("%g", window_s);
	if (kind == RateEstimatorKind::SavitzkyGolay || poly_order != 1) o << ", order=" << poly_order;
	o << ")";
	return o.str();
}

namespace
{
constexpr double kMaxWindow_s = 3600.0;
}

void RateEstimatorSettings::validate() const
{
	if (!std::isfinite(window_s) || window_s <= 0)
		throw std::invalid_argument("rate estimator window_s must be a positive number of seconds");
	if (window_s > kMaxWindow_s)  // window_s 1e9 was accepted (worse than raw)
		throw std::invalid_argument("rate estimator window_s " + std::to_string(window_s) +
									" s exceeds the limit of 3600 s (the causal estimate lags by half the window)");
	if (kind == RateEstimatorKind::Causal && poly_order != 1 && poly_order != 2)
		throw std::invalid_argument("rate estimator: the causal estimator has order 1 (the slope over the window, "
									"delayed by half of it) or 2 (delay-compensated), got order " +
									std::to_string(poly_order));
	if (kind == RateEstimatorKind::SavitzkyGolay && (poly_order < 1 || poly_order > 4))
		throw std::invalid_argument("rate estimator: savgol order must be 1..4, got " + std::to_string(poly_order));
}

double readingQuantum_C(const std::vector<double>& x)
{
	ReadingQuantum q;
	for (const double v : x) q.add(v);
	return q.quantum_C();
}

double windowForQuantum_s(double base_window_s, double quantum_C)
{
	// a quantum at the start up to the round-off of decimal readings keeps the base exactly
	if (!(quantum_C > kQuantumWindowStart_C * (1 + 1e-6))) return base_window_s;
	const double w = std::round(base_window_s * quantum_C / kQuantumWindowStart_C);  // whole seconds
	return std::max(base_window_s, std::min(w, kMaxQuantumWindow_s));
}

std::unique_ptr<RateEstimator> makeRateEstimator(const RateEstimatorSettings& s)
{
	s.validate();
	if (s.kind == RateEstimatorKind::Causal) return std::make_unique<CausalRateEstimator>(s.window_s, s.poly_order);
	return std::make_unique<SavitzkyGolayRateEstimator>(s.window_s, s.poly_order);
}

// ---------------------------------------------------------------- CausalRateTracker

CausalRateTracker::CausalRateTracker(std::size_t channels, double window_s)
	: channels_(channels), window_s_(window_s)
{
	if (!std::isfinite(window_s) || window_s <= 0)
		throw std::invalid_argument("CausalRateTracker: window_s must be positive");
	t_.resize(64);
	x_.resize(64 * channels_);
	slot_all_valid_.resize(64);
	reset();
}

void CausalRateTracker::reset()
{
	head_ = count_ = since_rebuild_ = 0;
	any_ = false;
	t_ref_ = 0.0;
	nan_slots_ = 0;
	nan_since_rebuild_ = false;
	for (auto* v : {&s1_, &s2_, &sx_, &stx_, &n_, &x_ref_}) v->assign(channels_, 0.0);
}

void CausalRateTracker::dropOldest()
{
	const std::size_t cap = t_.size();
	const double dt = t_[head_] - t_ref_;
	const double* xs = x_.data() + (head_ * channels_);
	for (std::size_t c = 0; c < channels_; c++)
	{
		if (std::isnan(xs[c])) continue;
		const double dx = xs[c] - x_ref_[c];
		s1_[c] -= dt;
		s2_[c] -= dt * dt;
		sx_[c] -= dx;
		stx_[c] -= dt * dx;
		n_[c] -= 1.0;
	}
	if (!slot_all_valid_[head_]) nan_slots_--;
	head_ = (head_ + 1) & (cap - 1);  // capacity is a power of two
	count_--;
}

void CausalRateTracker::rebuildSums()
{
	// Exact recomputation relative to fresh references: bounds the round-off of the running
	// add/subtract updates. O(1) amortised (see push).
	const std::size_t cap = t_.size();
	t_ref_ = last_t_;
	ref_set_.assign(channels_, 0);
	for (auto* v : {&s1_, &s2_, &sx_, &stx_, &n_}) std::fill(v->begin(), v->end(), 0.0);
	for (std::size_t i = 0; i < count_; i++)
	{
		const std::size_t slot = (head_ + count_ - 1 - i) & (cap - 1);  // newest first: refs = newest value
		const double dt = t_[slot] - t_ref_;
		for (std::size_t c = 0; c < channels_; c++)
		{
			const double x = x_[slot * channels_ + c];
			if (std::isnan(x)) continue;
			if (!ref_set_[c])
			{
				x_ref_[c] = x;
				ref_set_[c] = 1;
			}
			const double dx = x - x_ref_[c];
			s1_[c] += dt;
			s2_[c] += dt * dt;
			sx_[c] += dx;
			stx_[c] += dt * dx;
			n_[c] += 1.0;
		}
	}
	since_rebuild_ = 0;
	nan_since_rebuild_ = nan_slots_ > 0;
}

template <std::size_t NC>
void CausalRateTracker::pushN(double time_s, const double* x)
{
	const std::size_t nc = NC ? NC : channels_;  // NC > 0: loops over channels fully unrolled
	if (!std::isfinite(time_s)) throw std::invalid_argument("CausalRateTracker: time is not finite");
	if (any_ && !(time_s > last_t_))
		throw std::invalid_argument("CausalRateTracker: time not strictly increasing (" + std::to_string(time_s) +
									" after " + std::to_string(last_t_) + ")");
	if (!any_)
	{
		t_ref_ = time_s;
		any_ = true;
	}
	last_t_ = time_s;
	bool new_all_valid = true;
	for (std::size_t c = 0; c < nc; c++) new_all_valid &= !std::isnan(x[c]);
	if (!new_all_valid) nan_since_rebuild_ = true;
	double* S1 = s1_.data();
	double* S2 = s2_.data();
	double* SX = sx_.data();
	double* STX = stx_.data();
	double* N = n_.data();
	const double* XR = x_ref_.data();
	// Common case (uniform sampling): exactly one sample leaves as one enters -> one fused
	// update per channel where both are valid. Per channel the arithmetic depends only on that
	// channel's data (and the timestamps), so any set of channels gives the numbers of a
	// one-channel tracker.
	if (count_ >= 2 && t_[head_] <= time_s - window_s_ && t_[(head_ + 1) & (t_.size() - 1)] > time_s - window_s_ &&
		since_rebuild_ + 1 < 16 * t_.size())
	{
		const std::size_t cap = t_.size();
		const double* xo = x_.data() + (head_ * nc);
		const double dto = t_[head_] - t_ref_, dtn = time_s - t_ref_;
		const double d1 = dtn - dto, d2 = dtn * dtn - dto * dto;
		if (new_all_valid && slot_all_valid_[head_])
			detail::fusedRateSumsUpdate<NC>(nc, x, xo, XR, d1, d2, dto, dtn, S1, S2, SX, STX);
		else
			for (std::size_t c = 0; c < nc; c++)
			{
				const bool old_ok = !std::isnan(xo[c]), new_ok = !std::isnan(x[c]);
				if (old_ok && new_ok)
				{
					const double dxo = xo[c] - XR[c], dxn = x[c] - XR[c];
					S1[c] += d1;
					S2[c] += d2;
					SX[c] += dxn - dxo;
					STX[c] += dtn * dxn - dto * dxo;
					continue;
				}
				if (old_ok)
				{
					const double dx = xo[c] - XR[c];
					S1[c] -= dto;
					S2[c] -= dto * dto;
					SX[c] -= dx;
					STX[c] -= dto * dx;
					N[c] -= 1.0;
				}
				if (new_ok)
				{
					if (N[c] == 0.0)
					{
						x_ref_[c] = x[c];
						S1[c] = S2[c] = SX[c] = STX[c] = 0.0;
					}
					const double dx = x[c] - XR[c];
					S1[c] += dtn;
					S2[c] += dtn * dtn;
					SX[c] += dx;
					STX[c] += dtn * dx;
					N[c] += 1.0;
				}
			}
		// the new sample takes the slot of the one that left: head advances by one
		const std::size_t slot = (head_ + count_) & (cap - 1);
		nan_slots_ += static_cast<std::size_t>(!new_all_valid) - static_cast<std::size_t>(!slot_all_valid_[head_]);
		t_[slot] = time_s;
		slot_all_valid_[slot] = new_all_valid;
		double* xs = x_.data() + (slot * nc);
		for (std::size_t c = 0; c < nc; c++) xs[c] = x[c];
		head_ = (head_ + 1) & (cap - 1);
		since_rebuild_++;
		return;
	}
	// Leave the window (t - window_s, t].
	while (count_ > 0 && t_[head_] <= time_s - window_s_) dropOldest();
	if (count_ == 0)
	{
		t_ref_ = time_s;  // empty window (start or after a gap): fresh time reference
		for (std::size_t c = 0; c < nc; c++) S1[c] = S2[c] = SX[c] = STX[c] = 0.0;
	}
	// Grow the ring when full (irregular sampling: the count per window is not known a priori).
	if (count_ == t_.size())
	{
		const std::size_t cap = t_.size();
		std::vector<double> t2(cap * 2), x2(cap * 2 * nc);
		std::vector<unsigned char> v2(cap * 2);
		for (std::size_t i = 0; i < count_; i++)
		{
			const std::size_t slot = (head_ + i) & (cap - 1);
			t2[i] = t_[slot];
			v2[i] = slot_all_valid_[slot];
			for (std::size_t c = 0; c < nc; c++) x2[i * nc + c] = x_[slot * nc + c];
		}
		t_.swap(t2);
		x_.swap(x2);
		slot_all_valid_.swap(v2);
		head_ = 0;
	}
	const std::size_t cap = t_.size();
	const std::size_t slot = (head_ + count_) & (cap - 1);
	t_[slot] = time_s;
	slot_all_valid_[slot] = new_all_valid;
	nan_slots_ += !new_all_valid;
	double* xs = x_.data() + (slot * nc);
	const double dt = time_s - t_ref_;
	for (std::size_t c = 0; c < nc; c++)
	{
		xs[c] = x[c];
		if (std::isnan(x[c])) continue;
		if (N[c] == 0.0)  // window empty for this channel: fresh reference, no round-off residue
		{
			x_ref_[c] = x[c];
			S1[c] = S2[c] = SX[c] = STX[c] = 0.0;
		}
		const double dx = x[c] - x_ref_[c];
		S1[c] += dt;
		S2[c] += dt * dt;
		SX[c] += dx;
		STX[c] += dt * dx;
		N[c] += 1.0;
	}
	count_++;
	// Exact rebuild every 16 buffer turns: the running sums then accumulate at most ~16 x cap
	// add/subtract round-offs (relative ~1e-14), at 1/16 of a push's cost amortised.
	if (++since_rebuild_ >= 16 * cap) rebuildSums();
}

// The general case of pushFixed<NC>() (declared in the header, called from inline code).
template void CausalRateTracker::pushN<0>(double, const double*);
template void CausalRateTracker::pushN<1>(double, const double*);
template void CausalRateTracker::pushN<2>(double, const double*);
template void CausalRateTracker::pushN<3>(double, const double*);
template void CausalRateTracker::pushN<4>(double, const double*);

void CausalRateTracker::push(double time_s, const double* x)
{
	// Compile-time channel counts for the common small layouts (no loop overhead per channel);
	// the steady-state fast path first, the general update otherwise.
	switch (channels_)
	{
		case 1:
			pushFixed<1>(time_s, x);
			return;
		case 2:
			pushFixed<2>(time_s, x);
			return;
		case 3:
			pushFixed<3>(time_s, x);
			return;
		case 4:
			pushFixed<4>(time_s, x);
			return;
		default:
			pushFixed<0>(time_s, x);
	}
}

double CausalRateTracker::rate(std::size_t c) const
{
	const double n = n_[c];
	if (n < 2) return kNaN;
	const double den = n * s2_[c] - s1_[c] * s1_[c];
	if (!(den > 0)) return kNaN;
	return (n * stx_[c] - s1_[c] * sx_[c]) * (1.0 / den);
}

std::uint32_t CausalRateTracker::ratesAndCoverage(double* rate_out, double min_span_s) const
{
	switch (channels_)
	{
		case 1: return ratesAndCoverageFixed<1>(rate_out, min_span_s);
		case 2: return ratesAndCoverageFixed<2>(rate_out, min_span_s);
		case 3: return ratesAndCoverageFixed<3>(rate_out, min_span_s);
		case 4: return ratesAndCoverageFixed<4>(rate_out, min_span_s);
		default: return ratesAndCoverageFixed<0>(rate_out, min_span_s);
	}
}

bool CausalRateTracker::spanAtLeast(std::size_t c, double span_s) const
{
	const double n = n_[c];
	if (n < 2) return false;
	const double var = s2_[c] / n - (s1_[c] / n) * (s1_[c] / n);
	return 12.0 * var >= span_s * span_s;
}

double CausalRateTracker::coveredSpan_s(std::size_t c) const
{
	const double n = n_[c];
	if (n < 2) return 0.0;
	const double var = s2_[c] / n - (s1_[c] / n) * (s1_[c] / n);
	return var > 0 ? std::sqrt(12.0 * var) : 0.0;
}

// ---------------------------------------------------------------- CausalRateEstimator
CausalRateEstimator::CausalRateEstimator(double window_s, int order) : window_s_(window_s), order_(order)
{
	RateEstimatorSettings{RateEstimatorKind::Causal, window_s, order}.validate();
}

RateEstimatorSettings CausalRateEstimator::settings() const { return {RateEstimatorKind::Causal, window_s_, order_}; }

std::vector<double> CausalRateEstimator::estimate(const std::vector<double>& t, const std::vector<double>& x) const
{
	checkColumns(t, x);
	CausalRateTracker tracker(1, window_s_), half(1, 0.5 * window_s_);
	std::vector<double> out(t.size(), kNaN);
	for (std::size_t k = 0; k < t.size(); k++)
	{
		tracker.push(t[k], &x[k]);
		if (order_ == 2) half.push(t[k], &x[k]);
		if (!std::isnan(x[k]))
			out[k] = order_ == 2 ? CausalRateTracker::extrapolatedRate(tracker, half, 0, t[k]) : tracker.rate(0);
	}
	return out;
}

// ---------------------------------------------------------------- SavitzkyGolayRateEstimator
SavitzkyGolayRateEstimator::SavitzkyGolayRateEstimator(double window_s, int order) : window_s_(window_s), order_(order)
{
	RateEstimatorSettings{RateEstimatorKind::SavitzkyGolay, window_s, order}.validate();
}

RateEstimatorSettings SavitzkyGolayRateEstimator::settings() const { return {RateEstimatorKind::SavitzkyGolay, window_s_, order_}; }

std::vector<double> SavitzkyGolayRateEstimator::estimate(const std::vector<double>& t, const std::vector<double>& x) const
{
	checkColumns(t, x);
	const std::size_t n = t.size();
	std::vector<double> out(n, kNaN);
	const double half = window_s_ / 2;
	std::size_t lo = 0, hi = 0;  // window [lo, hi)
	Eigen::MatrixXd A;
	Eigen::VectorXd b;
	for (std::size_t k = 0; k < n; k++)
	{
		while (t[lo] < t[k] - half) lo++;
		while (hi < n && t[hi] <= t[k] + half) hi++;
		if (std::isnan(x[k])) continue;
		std::size_t valid = 0;
		for (std::size_t i = lo; i < hi; i++)
			if (!std::isnan(x[i])) valid++;
		if (valid < 2) continue;
		// Order reduced where the window holds too few samples (edges, around gaps).
		const int p = static_cast<int>(std::min<std::size_t>(order_, valid - 1));
		const int m = p + 1;
		// Normal equations in u = (t_i - t_k) / half (scaled to [-1, 1]) and x_i - x_k.
		A.setZero(m, m);
		b.setZero(m);
		double pw[10];
		for (std::size_t i = lo; i < hi; i++)
		{
			if (std::isnan(x[i])) continue;
			const double u = (t[i] - t[k]) / half;
			pw[0] = 1.0;
			for (int j = 1; j < 2 * m - 1; j++) pw[j] = pw[j - 1] * u;
			const double dx = x[i] - x[k];
			for (int r = 0; r < m; r++)
			{
				b[r] += pw[r] * dx;
				for (int c = 0; c <= r; c++) A(r, c) += pw[r + c];
			}
		}
		A = A.selfadjointView<Eigen::Lower>();
		const Eigen::VectorXd coef = A.ldlt().solve(b);
		const double r = coef[1] / half;
		if (std::isfinite(r)) out[k] = r;
	}
	return out;
}

}  // namespace mrpt_fog
