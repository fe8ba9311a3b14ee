/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CausalRateTrackerInline.h
 * The inline hot path of CausalRateTracker (implementation detail, not installed): the
 * fixed-channel-count push and rate evaluation that RateEstimator.cpp and the compensator's
 * per-sample loop (CompensatorStep.h) compile into their own loops. Vector extensions and
 * restrict pointers live here, not in the public RateEstimator.h.
 */

#include <mrpt_fog/model/RateEstimator.h>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>

namespace mrpt_fog
{
template <std::size_t NC>
[[gnu::always_inline]] inline void CausalRateTracker::pushFixed(double time_s, const double* x)
{
	if (!pushSteady<NC>(time_s, x)) pushN<NC>(time_s, x);
}

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
