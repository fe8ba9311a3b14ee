/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "CommandLine.h"

#include <iostream>

#include "AppMain.h"
#include "Options.h"

namespace mrpt_fog::app
{
void CommandLineOutput::usage(TCLAP::CmdLineInterface& c)
{
	TCLAP::StdOutput::usage(c);
	std::cout << extra_help_;
}

void CommandLineOutput::failure(TCLAP::CmdLineInterface&, TCLAP::ArgException& e)
{
	std::cerr << program_ << ": error: " << e.error() << " (" << e.argId() << "); see " << program_ << " --help\n";
	failed_ = true;
}

std::optional<int> parseCommandLine(TCLAP::CmdLine& cmd, int argc, char** argv, const std::string& program,
									const std::string& extra_help)
{
	CommandLineOutput output(program, extra_help);
	cmd.setOutput(&output);
	const bool go_on = cmd.parse(argc, argv);
	const bool failed = output.failed();
	cmd.setOutput(nullptr);
	if (go_on)
	{
		checkDeclaredFiles();  // the output rule, before any work (Options.h)
		return std::nullopt;
	}
	return failed ? kExitUsage : kExitOk;
}
}  // namespace mrpt_fog::app
