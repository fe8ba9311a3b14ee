/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AllocationGuard.h
 * A bounded-allocation guard around MRPT's own deserialisation of foreign objects (lidar scans,
 * range images, point clouds...). Several MRPT readers size their buffers from the file and
 * allocate them through MRPT's aligned allocator (mrpt::aligned_malloc), which returns null on
 * failure, and then write through it: a corrupt size crashes the program instead of failing.
 *
 * libmrpt_fog defines mrpt::aligned_malloc itself (the same code as MRPT's: the size rounded up
 * to the alignment, then aligned_alloc), so that the dynamic linker binds MRPT's calls to it.
 * Outside a guard it behaves exactly as MRPT's. Inside an AllocationGuard (one thread) a request
 * above the guard's limit, or one that fails, throws std::bad_alloc, which MRPT's containers
 * pass on like std::allocator's, and the reader reports it as a corrupt object.
 *
 * Whether the binding took effect depends on the program's library order; active() checks it
 * (through mrpt::aligned_calloc, which calls aligned_malloc from inside libmrpt-core). When it
 * did not, the reader refuses the classes that allocate that way (docs/validation/hardening.md). */

#include <cstddef>

namespace mrpt_fog::io::detail
{
class AllocationGuard
{
   public:
	explicit AllocationGuard(std::size_t max_bytes);
	~AllocationGuard();
	AllocationGuard(const AllocationGuard&) = delete;
	AllocationGuard& operator=(const AllocationGuard&) = delete;

	/** Whether MRPT's aligned allocations reach this library's mrpt::aligned_malloc (checked
	 * once per process). */
	static bool active();

   private:
	std::size_t previous_;
};
}  // namespace mrpt_fog::io::detail
