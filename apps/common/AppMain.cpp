/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "AppMain.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <exception>
#include <iostream>

namespace mrpt_fog::app
{
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
		std::string msg = e.what();
		// MRPT exceptions carry a multi-line call stack: keep the first meaningful line.
		while (!msg.empty() && (msg.back() == '\n' || msg.back() == ' ')) msg.pop_back();
		std::cerr << program << ": error: " << msg << "\n";
		return kExitError;
	}
}
}  // namespace mrpt_fog::app
