/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file AppMain.h
 * What every mrpt_fog program shares: registration of the classes, one-line error reporting
 * and exit codes. A program's main is:
 *
 *   int main(int argc, char** argv) { return mrpt_fog::app::runApp("fog-x", [&] { ... return 0; }); }
 *
 * Any exception escaping the body prints "fog-x: error: <what>" on stderr and exits with 1.
 * TCLAP usage errors exit with 2. */

#include <functional>
#include <string>

namespace mrpt_fog::app
{
/** Exit codes. */
constexpr int kExitOk = 0;
constexpr int kExitError = 1;
constexpr int kExitUsage = 2;

int runApp(const std::string& program, const std::function<int()>& body);

/** Large blocks (a log's columns) from mmap, given back to the system when freed (
 * fog-calibrate and fog-evaluate free columns they no longer need); call first in main(). */
void returnLargeBlocksToSystem();

/** An exception text on one line (MRPT's call-stack and location lines removed). */
std::string oneLineMessage(const std::string& what);

}  // namespace mrpt_fog::app
