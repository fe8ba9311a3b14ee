/* mrpt_fog: fuzzing helper: operator new that refuses allocations above 256 MiB with
 * std::bad_alloc (as a machine with little memory would), instead of the sanitizer's fatal
 * out-of-memory report.
 *
 * Why: MRPT's own deserialisation (e.g. CObservationRawDAQ, std::string in CArchive) resizes a
 * vector to a 32-bit length read from the file before reading the data, so a 3 KB corrupt rawlog
 * makes it allocate (and zero) up to 32 GB before the read fails. Our reader turns the failure
 * (end of data, or std::bad_alloc) into FogIoError; with this limit the fuzzer checks exactly
 * that, at full speed, instead of stopping on the allocation. Heap errors are still caught:
 * memory comes from the sanitizer's malloc. Linked into every fuzz target. */
#include <cstdlib>
#include <new>

namespace
{
constexpr std::size_t kLimitBytes = std::size_t(256) << 20;

void* allocate(std::size_t n)
{
	if (n > kLimitBytes) throw std::bad_alloc();
	if (void* p = std::malloc(n ? n : 1)) return p;
	throw std::bad_alloc();
}

void* allocateAligned(std::size_t n, std::align_val_t a)
{
	if (n > kLimitBytes) throw std::bad_alloc();
	const std::size_t al = static_cast<std::size_t>(a);
	if (void* p = std::aligned_alloc(al, ((n ? n : 1) + al - 1) / al * al)) return p;
	throw std::bad_alloc();
}
}  // namespace

void* operator new(std::size_t n) { return allocate(n); }
void* operator new[](std::size_t n) { return allocate(n); }
void* operator new(std::size_t n, const std::nothrow_t&) noexcept
{
	return n > kLimitBytes ? nullptr : std::malloc(n ? n : 1);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept
{
	return n > kLimitBytes ? nullptr : std::malloc(n ? n : 1);
}
void* operator new(std::size_t n, std::align_val_t a) { return allocateAligned(n, a); }
void* operator new[](std::size_t n, std::align_val_t a) { return allocateAligned(n, a); }
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
