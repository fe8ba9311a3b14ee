/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CommandLine.h
 * Command-line parsing shared by every program (MRPT's TCLAP). MRPT's TCLAP does not exit on
 * --help or on a usage error: CmdLine::parse returns false, and the program must stop. Use:
 *
 *   if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-x", kHelp)) return *rc;
 *
 * --help prints TCLAP's usage followed by `extra_help` (method, examples) and gives exit 0; a
 * usage error prints one line "fog-x: error: <what> (<arg>); see fog-x --help" and gives 2. */

#include <mrpt/3rdparty/tclap/CmdLine.h>

#include <optional>
#include <stdexcept>
#include <string>

namespace mrpt_fog::app
{
/** TCLAP output: usage + extra help text; usage errors on one line. */
class CommandLineOutput : public TCLAP::StdOutput
{
   public:
	CommandLineOutput(std::string program, std::string extra_help)
		: program_(std::move(program)), extra_help_(std::move(extra_help))
	{
	}
	void usage(TCLAP::CmdLineInterface& c) override;
	void failure(TCLAP::CmdLineInterface& c, TCLAP::ArgException& e) override;
	bool failed() const { return failed_; }

   private:
	std::string program_, extra_help_;
	bool failed_ = false;
};

/** Parses; returns std::nullopt when the program should go on, else the exit code (0 after
 * --help/--version, kExitUsage after a usage error). Numeric options declared with Options.h
 * are checked while parsing; once parsed, the file options declared there are checked against
 * each other (checkDeclaredFiles: throws std::invalid_argument, exit 1 through runApp). */
std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv, const std::string& program,
									const std::string& extra_help = {});

/** A closed-set option parsed once, here, by the library's spelling (`fromString`, e.g.
 * termSelectionFromString); its error names the option and the choices: "--selection:
 * selection must be 'auto' or 'none', got 'lasso'". */
template <class FromString>
auto parseChoice(TCLAP::ValueArg<std::string>& arg, FromString fromString)
{
	try
	{
		return fromString(arg.getValue());
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument("--" + arg.getName() + ": " + e.what());
	}
}

}  // namespace mrpt_fog::app
