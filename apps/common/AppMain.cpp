/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "AppMain.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <exception>
#include <iostream>
#include <sstream>

namespace mrpt_fog::app
{
std::string oneLineMessage(const std::string& what)
{
	// MRPT exceptions look like "==== MRPT exception ====\nMessage: ...\nLocation: ...\nCall stack
	// backtrace:\n...": keep the message lines only, joined on one line.
	std::istringstream in(what);
	std::string line, out;
	while (std::getline(in, line))
	{
		if (line.rfind("Call stack backtrace", 0) == 0) break;
		if (line.rfind("==== MRPT exception", 0) == 0 || line.rfind("Location:", 0) == 0) continue;
		if (line.rfind("Message:", 0) == 0) line = line.substr(8);
		const auto b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t\r");
		if (b == std::string::npos) continue;
		out += (out.empty() ? "" : "; ") + line.substr(b, e - b + 1);
	}
	return out.empty() ? "unknown error" : out;
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
