/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file StepRunner.h
 * fog-demo runs the project's own programs one step at a time, exactly as a user would, so the
 * report can list every command that reproduces a figure. Each step's output goes to
 * <out>/logs/<name>.log; progress is printed as "[i/n] what ... done (12.3 s)". */

#include <string>
#include <vector>

namespace mrpt_fog::demo
{
struct Step
{
	std::string name;  //!< short id, also the log file name
	std::string what;  //!< what the user sees in the progress line
	std::vector<std::string> argv;  //!< program (full path) and arguments
};

class StepRunner
{
   public:
	StepRunner(std::string bin_dir, std::string log_dir, int total_steps);

	/** Path of one of our programs (next to fog-demo). */
	std::string program(const std::string& name) const;

	/** Runs a step; throws std::runtime_error naming the step and its log on a non-zero exit
	 * (the log's last line is the program's one-line error). */
	void run(const Step& step);

	/** Commands run so far, shell-quoted, for the report. */
	const std::vector<std::string>& commands() const { return commands_; }

   private:
	std::string bin_dir_, log_dir_;
	int total_ = 0, done_ = 0;
	std::vector<std::string> commands_;
};

/** Directory holding the running executable. */
std::string executableDir();

}  // namespace mrpt_fog::demo
