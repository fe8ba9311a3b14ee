/* mrpt_fog test support: an address-space limit (setrlimit RLIMIT_AS) for a forked child that
 * checks a reader's memory stays bounded, and whether such a limit can work in this build.
 *
 * AddressSanitizer reserves terabytes of address space for its shadow memory at start-up and maps
 * more as the program allocates, so under ASan any RLIMIT_AS small enough to mean something makes
 * ASan itself fail ("ERROR: Failed to mmap") before the code under test runs. There the limit is
 * not applied: the test still checks the outcome (the error message, no crash) and the sanitizer
 * checks memory safety; the memory bound itself is checked by the Release run of the same test. */
#pragma once

#include <sys/resource.h>

#include <cstddef>

#if defined(__SANITIZE_ADDRESS__)
#define FOG_UNDER_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define FOG_UNDER_ASAN 1
#endif
#endif

namespace fogtest
{
/** True when limitAddressSpace() really limits (a build without AddressSanitizer). */
constexpr bool addressSpaceLimitWorks()
{
#ifdef FOG_UNDER_ASAN
	return false;
#else
	return true;
#endif
}

/** Limits this process's address space to `bytes` (call in a forked child only). Does nothing
 * under AddressSanitizer (see the file comment). Returns false if setrlimit failed. */
inline bool limitAddressSpace(std::size_t bytes)
{
	if (!addressSpaceLimitWorks()) return true;
	const rlimit lim{bytes, bytes};
	return ::setrlimit(RLIMIT_AS, &lim) == 0;
}
}  // namespace fogtest
