/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CompensatorKernel.h
 * The compensator's per-channel polynomial kernel (an implementation detail of Compensator:
 * internal, not installed; the tests compare its two builds through the build-tree path). For every tracked channel c, a
 * degree-5 polynomial in its temperature T_c and a degree-3 one in its rate R_c = dT_c/dt:
 *
 *   bias_dph = sum_c sum_k tq[k][c] (clamp(T_c) - t_centre[c])^k + rq[k][c] (clamp(R_c) - r_centre[c])^k
 *
 * with each signal clamped to its calibrated range [lo, hi] first. The model's normalisation
 * z = (v - centre) / scale is folded into the coefficients (tq_k = p_k / scale^k): the same
 * polynomial, one multiplication less per signal; centring is kept, so no raw powers of degC.
 * Channels come in blocks of 4 (absent signals and padding lanes: zero coefficients and an
 * infinite range, so they add 0 and are never counted as clamped).
 *
 * One evaluation (Horner, per 4-channel block), written with vector extensions for 2 or 4
 * lanes: the baseline build uses 2 (SSE2 on x86-64); the compensator's AVX2 build of its step
 * (CompensatorAvx2.cpp, chosen at run time) uses 4. For one block (<= 4 channels, the only
 * case the AVX2 build runs) both give bitwise the same numbers.
 * The sum is returned and the number of clamped signal values added to `clamped`.
 */

#include <cstddef>
#include <cstring>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace mrpt_fog
{
namespace detail
{
struct alignas(32) KernelBlock
{
	double t_centre[4], t_lo[4], t_hi[4], t_q[5][4];  // t_q[k - 1][j]: coefficient of (T - centre)^k
	double r_centre[4], r_lo[4], r_hi[4], r_q[3][4];
};

/** Exact number of clamped signal values of the blocks (the rare path after a clamp). */
int countClamped(const KernelBlock* k, std::size_t blocks, const double* temp_C, const double* rate_C_s);

/** True when this CPU (and OS) support AVX2. */
bool cpuHasAvx2();

// The 4-lane helpers return 32-byte vectors; they are always inlined into AVX2 code (or split
// by the compiler), so the "AVX vector return without AVX changes the ABI" note does not apply.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wpsabi"
namespace vec
{
/** W doubles as one GCC/Clang vector: W = 2 is SSE2 (baseline x86-64), W = 4 is one AVX
 * register where the caller is compiled for AVX2 (elsewhere the compiler splits it). */
template <int W>
struct Lanes
{
	typedef double V __attribute__((vector_size(8 * W)));
	typedef long long M __attribute__((vector_size(8 * W)));
};
template <int W>
[[gnu::always_inline]] inline typename Lanes<W>::V loadu(const double* p)
{
	typename Lanes<W>::V v;
	std::memcpy(&v, p, sizeof v);
	return v;
}
template <int W>
[[gnu::always_inline]] inline typename Lanes<W>::V loada(const double* p)  // KernelBlock members
{
	return *reinterpret_cast<const typename Lanes<W>::V*>(p);
}
/** True if any lane of the comparison mask m is set (x86-64: an OR of the halves and one
 * movmskpd instead of a lane-by-lane extraction). */
template <int W>
[[gnu::always_inline]] inline bool anyLane(typename Lanes<W>::M m)
{
#if defined(__SSE2__)
	__m128i a, b;
	std::memcpy(&a, &m, 16);
	if constexpr (W == 4)
	{
		std::memcpy(&b, reinterpret_cast<const char*>(&m) + 16, 16);
		a = _mm_or_si128(a, b);
	}
	return _mm_movemask_pd(_mm_castsi128_pd(a)) != 0;
#else
	long long any = 0;
	for (int j = 0; j < W; j++) any |= m[j];
	return any != 0;
#endif
}
/** True if any of the W values at a and b, or of their sums a[j] + b[j], is NaN. */
template <int W>
[[gnu::always_inline]] inline bool anyNaNSum(const double* a, const double* b)
{
	const typename Lanes<W>::V s = loadu<W>(a) + loadu<W>(b);
	return anyLane<W>(s != s);
}
}  // namespace vec

/** The kernel over `blocks` blocks (NB > 0: that many, known at compile time), W lanes at a
 * time (2 or 4). For one block both W give bitwise the same result: the lanes are independent,
 * the partial sums are added as (lane 0 + lane 2) + (lane 1 + lane 3), and there is no fused
 * multiply-add (the AVX2 build is compiled without FMA for this reason). */
template <std::size_t NB, int W = 2>
[[gnu::always_inline]] inline double kernelSum(const KernelBlock* K, std::size_t blocks, const double* T,
											   const double* R, int& clamped)
{
	static_assert(W == 2 || W == 4, "2 or 4 lanes");
	using V = typename vec::Lanes<W>::V;
	using M = typename vec::Lanes<W>::M;
	using vec::loada;
	using vec::loadu;
	const std::size_t nb = NB ? NB : blocks;
	V acc{};  // zeros
	M moved{};
	for (std::size_t blk = 0; blk < nb; blk++)
	{
		const KernelBlock& b = K[blk];
		for (int j = 0; j < 4; j += W)
		{
			const V t = loadu<W>(T + 4 * blk + j), r = loadu<W>(R + 4 * blk + j);
			// clamp to [lo, hi]; `moved` collects the lanes where that changed the value
			V tc = t < loada<W>(b.t_lo + j) ? loada<W>(b.t_lo + j) : t;
			tc = tc > loada<W>(b.t_hi + j) ? loada<W>(b.t_hi + j) : tc;
			V rc = r < loada<W>(b.r_lo + j) ? loada<W>(b.r_lo + j) : r;
			rc = rc > loada<W>(b.r_hi + j) ? loada<W>(b.r_hi + j) : rc;
			moved |= (tc != t) | (rc != r);
			const V u = tc - loada<W>(b.t_centre + j), w = rc - loada<W>(b.r_centre + j);
			// Horner, the two polynomials interleaved
			V h = loada<W>(b.t_q[4] + j) * u + loada<W>(b.t_q[3] + j);
			V g = loada<W>(b.r_q[2] + j) * w + loada<W>(b.r_q[1] + j);
			h = h * u + loada<W>(b.t_q[2] + j);
			g = g * w + loada<W>(b.r_q[0] + j);
			h = h * u + loada<W>(b.t_q[1] + j);
			h = h * u + loada<W>(b.t_q[0] + j);
			acc += h * u + g * w;
		}
	}
	// Clamping is rare: one predictable test here, the exact count only when it happened.
	if (vec::anyLane<W>(moved)) clamped += countClamped(K, nb, T, R);
	if constexpr (W == 4) return (acc[0] + acc[2]) + (acc[1] + acc[3]);
	return acc[0] + acc[1];
}
#pragma GCC diagnostic pop

}  // namespace detail
}  // namespace mrpt_fog
