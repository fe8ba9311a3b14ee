/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/core/aligned_allocator.h>
#include <mrpt_fog/io/AllocationGuard.h>

#include <cstdlib>
#include <new>

namespace mrpt_fog::io::detail
{
namespace
{
thread_local std::size_t t_limit = 0;  // 0: no guard
thread_local std::size_t t_calls = 0;
}  // namespace

AllocationGuard::AllocationGuard(std::size_t max_bytes) : previous_(t_limit) { t_limit = max_bytes > 0 ? max_bytes : 1; }
AllocationGuard::~AllocationGuard() { t_limit = previous_; }

bool AllocationGuard::active()
{
	static const bool is_active = [] {
		const std::size_t before = t_calls;
		void* p = mrpt::aligned_calloc(16, 16);  // libmrpt-core: calls aligned_malloc through its PLT
		mrpt::aligned_free(p);
		return t_calls != before;
	}();
	return is_active;
}
}  // namespace mrpt_fog::io::detail

namespace mrpt
{
/** MRPT's aligned_malloc (libmrpt-core 2.5: size rounded up to a multiple of the alignment, then
 * aligned_alloc; freed by aligned_free = free), with the guard's bound. */
void* aligned_malloc(size_t size, size_t alignment)
{
	using namespace mrpt_fog::io::detail;
	t_calls++;
	if (alignment == 0) alignment = 1;
	if (t_limit && size > t_limit) throw std::bad_alloc();
	if (size % alignment != 0) size = (size / alignment + 1) * alignment;
	void* p = std::aligned_alloc(alignment, size);
	if (!p && t_limit) throw std::bad_alloc();
	return p;
}
}  // namespace mrpt
