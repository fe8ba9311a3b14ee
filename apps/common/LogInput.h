/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file LogInput.h
 * What every program that reads a log shares: the --format option (a logger CSV read through a
 * format file, io/LogFormat.h) and the notices of the reading: a note naming the columns the
 * format leaves out, and a warning for every unit the numbers contradict (io/UnitPlausibility.h).
 * Both are printed on stderr as they come and kept for --json:
 *
 *   app::LogInput input(cmd);               // before parsing: adds --format
 *   ... readFogRun(path, label, each, progress, input.options()) ...
 *   j["input_notices"] = input.json();
 */

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/io/FogLogReader.h>

#include "Options.h"

#include <string>
#include <vector>

namespace mrpt_fog::app
{
class LogInput
{
   public:
	/** Adds --format to the command line; `program` prefixes the printed notices. */
	LogInput(TCLAP::CmdLine& cmd, std::string program);

	/** The reading options (the format file is read on the first call; a bad one throws
	 * std::invalid_argument naming the file and the key). */
	const LogReadOptions& options();
	const std::string& formatPath() const { return format_.getValue(); }

	/** {"format": path or null, "unit_warnings": [{"file", "message"}], "notes": [...]}, of
	 * every log read, or of the log `path` only. */
	JsonValue json(const std::string& path = "") const;
	std::size_t unitWarnings() const;

   private:
	std::string program_;
	mutable InputArg format_;  // a file read: under the output rule (Options.h); TCLAP's getValue() is not const
	LogReadOptions options_;
	bool loaded_ = false;
	std::vector<LogNotice> notices_;
};
}  // namespace mrpt_fog::app
