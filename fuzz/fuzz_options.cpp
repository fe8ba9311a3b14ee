/* mrpt_fog: libFuzzer target: the programs' option layer (apps/common/Options.h) on any argv.
 * The input is split at NUL bytes into argv words, parsed against a command line holding each
 * kind of option the programs declare. Contract checked: parseCommandLine returns "go on", 0
 * (--help, --version) or the usage exit code, or throws std::invalid_argument from the output
 * rule; after "go on" every numeric value is finite and inside its declared range. Never a
 * crash, a sanitizer report, another exception, a hang or a file written. */
#include <cmath>
#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "AppMain.h"
#include "CommandLine.h"
#include "FuzzTempFile.h"
#include "Options.h"

namespace app = mrpt_fog::app;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	static const bool quiet = [] {
		std::cout.rdbuf(nullptr);  // TCLAP's usage and errors: not the fuzzer's output
		std::cerr.rdbuf(nullptr);
		return true;
	}();
	(void)quiet;
	if (size > 4096) return 0;
	std::vector<std::string> words{"fog-fuzz"};
	std::string w;
	for (size_t i = 0; i < size; i++)
	{
		if (data[i] == 0)
		{
			words.push_back(w);
			w.clear();
		}
		else
			w += static_cast<char>(data[i]);
	}
	words.push_back(w);
	if (words.size() > 64) return 0;
	std::vector<char*> argv;
	for (auto& s : words) argv.push_back(s.data());

	TCLAP::CmdLine cmd("fuzzed command line", ' ', "0.1");
	app::RealArg window(cmd, "window", "a window", "s", app::Range::aboveUpTo(0, 3600), 60.0, "S");
	app::RealArg lat(cmd, "latitude-deg", "latitude", "deg", app::Range::closed(-90, 90));
	app::RealArg alpha(cmd, "alpha", "level", "1", app::Range::open(0, 0.5), 0.005);
	app::CountArg seeds(cmd, "seeds", "seeds", "runs", 1, 1000, 5);
	app::CountArg seed(cmd, "seed", "seed", "seed", 0, UINT64_MAX, 20240501);
	app::InputMultiArg in("i", "input", "runs", false, "RUN", cmd);
	app::InputArg cal("", "cal", "calibration", false, "", "CAL.yaml", cmd);
	app::OutputArg out("o", "output", "output", false, "", "OUT", cmd);
	app::OutputArg json("", "json", "json", false, "", "FILE", cmd);
	app::OutputDirArg plots("", "plots", "plots", false, "", "DIR", cmd);
	TCLAP::SwitchArg q("q", "quiet", "quiet", cmd);
	try
	{
		const auto rc = app::parseCommandLine(cmd, static_cast<int>(argv.size()), argv.data(), "fog-fuzz");
		if (rc)
		{
			if (*rc != app::kExitOk && *rc != app::kExitUsage)
				fogfuzz::contractViolation("parseCommandLine", "unexpected exit code");
			return 0;
		}
		const auto inRange = [](double v, const app::Range& r) { return std::isfinite(v) && r.contains(v); };
		if (!inRange(window.getValue(), app::Range::aboveUpTo(0, 3600)) ||
			(lat.isSet() && !inRange(lat.getValue(), app::Range::closed(-90, 90))) ||
			!inRange(alpha.getValue(), app::Range::open(0, 0.5)) || seeds.getValue() < 1 || seeds.getValue() > 1000)
			fogfuzz::contractViolation("option layer", "a value outside its declared range was accepted");
		(void)seed.getValue();
	}
	catch (const std::invalid_argument&)
	{
	}
	catch (const std::exception& e)
	{
		fogfuzz::contractViolation("parseCommandLine threw something else than std::invalid_argument", e.what());
	}
	return 0;
}
