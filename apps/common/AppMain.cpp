/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "AppMain.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/ErrorText.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <malloc.h>

#include <exception>
#include <iostream>
#include <sstream>

namespace mrpt_fog::app
{
std::string oneLineMessage(const std::string& what) { return oneLineErrorMessage(what); }

void returnLargeBlocksToSystem()
{
	// glibc's default threshold (128 KiB), fixed: otherwise it rises to the size of the first
	// freed column and later columns come from the heap, where freeing one does not lower the
	// peak memory. Not for every program: one that allocates and frees many mid-size blocks
	// (fog-discrepancy) then spends its time in mmap/munmap.
	mallopt(M_MMAP_THRESHOLD, 128 * 1024);
}

int runApp(const std::string& program, const std::function<int()>& body)
{
	try
	{
		mrpt_fog::registerAllClasses_mrpt_fog();
		return body();
	}
	catch (const TCLAP::ArgException& e)
	{
		std::cerr << program << ": error: " << e.error() << " (argument " << e.argId() << "); see " << program
				  << " --help\n";
		return kExitUsage;
	}
	catch (const std::exception& e)
	{
		std::cerr << program << ": error: " << oneLineMessage(e.what()) << "\n";
		return kExitError;
	}
}
}  // namespace mrpt_fog::app
