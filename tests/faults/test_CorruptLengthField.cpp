/* mrpt_fog: regression of the rawlog fuzzer's findings: a corrupt 32-bit length field. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "FaultRun.h"
#include "support/AddressSpaceLimit.h"
#include "support/ChildProcess.h"

using namespace mrpt_fog;


namespace
{
std::string dataFile(const std::string& name) { return std::string(FOG_SOURCE_DIR) + "/tests/faults/data/" + name; }

/** Reads `path` in a child process limited to 1 GiB of address space (a machine without the
 * memory MRPT's deserialisation asks for). Child exit: 0 = FogIoError naming the file,
 * 1 = read without error, 2 = FogIoError without the file name, 3 = another exception. */
int readInSmallMachine(const std::string& path)
{
	return fogtest::exitCodeInChild([&] {
		fogtest::limitAddressSpace(std::size_t(1) << 30);
		try
		{
			(void)readFogRawlog(path);
		}
		catch (const FogIoError& e)
		{
			return std::string(e.what()).find(path) != std::string::npos ? 0 : 2;
		}
		catch (...)
		{
			return 3;
		}
		return 1;
	});
}
}  // namespace

// Found by fuzz_rawlog: a few corrupt bytes in an object make MRPT's own deserialisation
// (CObservationRawDAQ's vectors, CArchive's std::string) resize to a 32-bit length read from the
// file before reading the data: up to 32 GB for a 3 KB file (in a normal build 4.5 GB and 15 s
// for corrupt_length_rawdaq.rawlog). Our reader must still fail cleanly: with the memory missing
// (std::bad_alloc) the result is a FogIoError naming the file, not a crash.
TEST(CorruptLengthField, ReaderFailsCleanlyWhenMrptCannotAllocate)
{
	// Without the limit MRPT would allocate 4.5 GB: under ASan (no limit possible) skipped, the
	// fuzzer covers it there.
	if (!fogtest::addressSpaceLimitWorks())
		GTEST_SKIP() << "address-space limits do not work under AddressSanitizer (the fuzzer covers this there)";
	for (const char* f : {"corrupt_length_rawdaq.rawlog", "corrupt_length_classname.rawlog"})
		EXPECT_EQ(readInSmallMachine(dataFile(f)), 0) << f;
}

// Found by fuzz_rawlog (300 s local run): a corrupt class name that MRPT resolves to
// mrpt::math::CMatrixD with rows x cols read from the file. MRPT's aligned allocator returns null
// instead of throwing and its matrix code writes through it: SIGSEGV in fog-convert. The reader
// refuses a top-level object that is no observation, sensory frame or action before MRPT reads it.
TEST(CorruptLengthField, TopLevelNonObservationRefusedUnread)
{
	const std::string path = dataFile("corrupt_top_level_matrix.rawlog");
	const int code = fogtest::exitCodeInChild([&] {
		try
		{
			(void)readFogRawlog(path);
		}
		catch (const FogIoError& e)
		{
			const std::string m = e.what();
			return m.find(path) != std::string::npos && m.find("object #0") != std::string::npos &&
						   m.find("mrpt::math::CMatrixD, not an observation") != std::string::npos
					   ? 0
					   : 2;
		}
		catch (...)
		{
			return 3;
		}
		return 1;
	});
	EXPECT_EQ(code, 0) << "0 = FogIoError naming the file, the object and its class; 1 = read; 2 = other message; 3 = other exception; else a crash";
}

namespace
{
/** Reads `path` in a child process. Exit 0 = FogIoError naming the file and holding every one of
 * `parts`; 1 = read without error; 2 = FogIoError with another message; 3 = another exception;
 * anything else = a crash (a signal) or a hang killed by ctest. */
int refusedInChild(const std::string& path, const std::vector<std::string>& parts)
{
	return fogtest::exitCodeInChild([&] {
		try
		{
			(void)readFogRawlog(path);
		}
		catch (const FogIoError& e)
		{
			const std::string m = e.what();
			if (m.find(path) == std::string::npos) return 2;
			for (const auto& part : parts)
				if (m.find(part) == std::string::npos) return 2;
			return 0;
		}
		catch (...)
		{
			return 3;
		}
		return 1;
	});
}
}  // namespace

// The same corrupt CMatrixD written with MRPT's old object header (name length without the 0x80
// flag, 3 zero bytes, a 32-bit version): the first check read only the MRPT 2 header, so MRPT
// deserialised it and fog-convert died of SIGSEGV (exit 139) before the fix.
TEST(CorruptLengthField, OldFormatHeaderRefusedUnread)
{
	EXPECT_EQ(refusedInChild(dataFile("old_top_matrix.rawlog"), {"object #0", "mrpt::math::CMatrixD, not an observation"}), 0)
		<< "0 = FogIoError naming the file, the object and its class; 1 = read; 2 = other message; 3 = other exception; else a crash";
}

// A sensory frame holding the corrupt CMatrixD: MRPT's CSensoryFrame reads whatever class its list
// names (SIGSEGV, exit 139, before the fix). The reader reads frames itself and checks each entry.
TEST(CorruptLengthField, SensoryFrameEntriesCheckedBeforeReading)
{
	EXPECT_EQ(refusedInChild(dataFile("sf_nested_matrix.rawlog"), {"object #0", "sensory frame holds a mrpt::math::CMatrixD"}), 0)
		<< "0 = FogIoError naming the file, the object and its class; 1 = read; 2 = other message; 3 = other exception; else a crash";
}

// A sensory frame whose observation count reads 4294967295: MRPT resizes its list to that count
// first (64 GB of pointers; fog-convert ran past a 60 s timeout before the fix). Bounded now.
TEST(CorruptLengthField, SensoryFrameCountBounded)
{
	EXPECT_EQ(refusedInChild(dataFile("sf_huge_n.rawlog"), {"4294967295 observations, more than the limit"}), 0)
		<< "0 = FogIoError naming the file and the count; 1 = read; 2 = other message; 3 = other exception; else a crash";
}

// A valid MRPT observation class with a corrupt size: a CObservation3DRangeScan (written by MRPT
// 2.5) whose range image claims 2147483647 x 2147483647 pixels. MRPT's matrix allocates through its
// aligned allocator, which returns null, and writes through it: fog-convert died of SIGSEGV (exit
// 139) before the fix. Every observation class is read now, MRPT's readers under the bounded-
// allocation guard (io/AllocationGuard.h): the request beyond the limit throws instead.
TEST(CorruptLengthField, ObservationClassWithUnsafeReaderStoppedByTheAllocationGuard)
{
	EXPECT_EQ(refusedInChild(dataFile("corrupt_3d_range_image.rawlog"),
							 {"object #0", "CObservation3DRangeScan", "more memory than the limit"}),
			  0)
		<< "0 = FogIoError naming the file, the object, its class and why; 1 = read; 2 = other message; 3 = other exception; else a crash";
}
