/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The AVX2 build of Compensator::step (CompensatorStep.h) for 1..4 tracked channels: one 4-wide
 * vector per signal kind in the kernel, and the tracker's per-channel updates vectorised 4 wide.
 * Only stepAvx2 carries the AVX2 target (a function attribute, not a compiler flag: every other
 * function, in this file too, stays baseline x86-64), and the compensator calls it only after
 * cpuHasAvx2(). No FMA: a fused multiply-add rounds once instead of twice, and the build must
 * give bitwise the numbers of the baseline one. */
#include <mrpt_fog/model/CompensatorStep.h>

// 32-byte vectors only cross always-inlined helpers here (see CompensatorKernel.h).
#pragma GCC diagnostic ignored "-Wpsabi"

namespace mrpt_fog
{
#if defined(__x86_64__) && (defined(__GNUC__) || defined(__clang__))
bool detail::cpuHasAvx2()
{
	// __builtin_cpu_supports also requires that the OS saves the AVX state (OSXSAVE / XCR0).
	__builtin_cpu_init();
	return __builtin_cpu_supports("avx2");
}

[[gnu::target("avx2")]] Compensator::Output Compensator::stepAvx2(double time_s, double raw_dph, const double* temp_C)
{
	switch (channel_col_.size())
	{
		case 4: return stepBody<4, 4>(time_s, raw_dph, temp_C);
		case 1: return stepBody<1, 4>(time_s, raw_dph, temp_C);
		case 2: return stepBody<2, 4>(time_s, raw_dph, temp_C);
		default: return stepBody<3, 4>(time_s, raw_dph, temp_C);  // use_avx2_ only for 1..4
	}
}

[[gnu::target("avx2")]] void Compensator::stepBatchAvx2(std::size_t n, const double* time_s, const double* raw_dph,
													   const double* temp_C, std::size_t stride, Output* out)
{
	switch (channel_col_.size())
	{
		case 4: return stepLoop<4, 4>(n, time_s, raw_dph, temp_C, stride, out);
		case 1: return stepLoop<1, 4>(n, time_s, raw_dph, temp_C, stride, out);
		case 2: return stepLoop<2, 4>(n, time_s, raw_dph, temp_C, stride, out);
		default: return stepLoop<3, 4>(n, time_s, raw_dph, temp_C, stride, out);
	}
}
#else
bool detail::cpuHasAvx2() { return false; }
void Compensator::stepBatchAvx2(std::size_t n, const double* time_s, const double* raw_dph, const double* temp_C,
								std::size_t stride, Output* out)
{
	for (std::size_t k = 0; k < n; k++) out[k] = step(time_s[k], raw_dph[k], temp_C + k * stride);
}
Compensator::Output Compensator::stepAvx2(double time_s, double raw_dph, const double* temp_C)
{
	return step(time_s, raw_dph, temp_C);  // never called: use_avx2_ stays false
}
#endif

}  // namespace mrpt_fog
