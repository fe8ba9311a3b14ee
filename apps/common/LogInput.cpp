/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "LogInput.h"

#include <mrpt_fog/io/LogFormat.h>

#include <cstdio>
#include <memory>

namespace mrpt_fog::app
{
LogInput::LogInput(TCLAP::CmdLine& cmd, std::string program)
	: program_(std::move(program)),
	  format_("", "format",
			  "format file (YAML) mapping a logger CSV's columns and units (docs/reference/format-files.md); every "
			  "input log that is not a .rawlog is read through it. fog-convert --guess-format LOG drafts one",
			  false, "", "F.yaml", cmd)
{
}

const LogReadOptions& LogInput::options()
{
	if (!loaded_)
	{
		loaded_ = true;
		if (!format_.getValue().empty())
			options_.format = std::make_shared<LogFormat>(readLogFormat(format_.getValue()));
		options_.notice = [this](const LogNotice& n) {
			for (const auto& seen : notices_)  // a log read twice (streamed in passes) says it once
				if (seen.kind == n.kind && seen.path == n.path && seen.message == n.message) return;
			notices_.push_back(n);
			std::fprintf(stderr, "%s: %s: %s: %s\n", program_.c_str(),
						 n.kind == LogNotice::Kind::UnitWarning ? "warning: units" : "note", n.path.c_str(),
						 n.message.c_str());
		};
	}
	return options_;
}

std::size_t LogInput::unitWarnings() const
{
	std::size_t n = 0;
	for (const auto& x : notices_) n += x.kind == LogNotice::Kind::UnitWarning;
	return n;
}

JsonValue LogInput::json(const std::string& path) const
{
	JsonValue j = JsonValue::object();
	j["format"] = format_.getValue().empty() ? JsonValue() : JsonValue(format_.getValue());
	JsonValue w = JsonValue::array(), notes = JsonValue::array();
	for (const auto& n : notices_)
		if (path.empty() || n.path == path)
			(n.kind == LogNotice::Kind::UnitWarning ? w : notes)
			.push_back(JsonValue::object({{"file", n.path}, {"message", n.message}}));
	j["unit_warnings"] = w;
	j["notes"] = notes;
	return j;
}
}  // namespace mrpt_fog::app
