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

int runApp(const std::string& program, const std::function<int()>& body)
{
	// Large blocks (a log's columns) always from mmap and back to the system when freed: glibc's
	// dynamic threshold otherwise rises to the size of the first freed column and later columns
	// come from the heap, where freeing one does not lower the peak memory (issue 14).
	mallopt(M_MMAP_THRESHOLD, 128 * 1024);  // glibc's default, fixed
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
