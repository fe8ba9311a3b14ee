/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* lumped-coil-gen: writes a run of the second, independent test generator
 * (tests/support/LumpedCoilGenerator.h) as CSV, for integration tests and benches.
 *
 *   lumped-coil-gen -o run.csv [--profile lab|cooling|short] [--seed N] [--dt S] [--effect ID=RATIO]...
 */
#include <mrpt_fog/io/FogLogIO.h>

#include <cstdio>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "LumpedCoilGenerator.h"

int main(int argc, char** argv)
{
	try
	{
		fogtest::LumpedCoilOptions opt;
		std::string out;
		for (int i = 1; i < argc; ++i)
		{
			const std::string a = argv[i];
			auto value = [&]() -> std::string {
				if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
				return argv[++i];
			};
			if (a == "-o") out = value();
			else if (a == "--profile") opt.profile = value();
			else if (a == "--seed") opt.seed = std::stoull(value());
			else if (a == "--dt") opt.dt_s = std::stod(value());
			else if (a == "--effect")
			{
				const std::string v = value();
				const auto eq = v.find('=');
				if (eq == std::string::npos) throw std::invalid_argument("--effect " + v + ": expected ID=RATIO");
				opt.hidden[v.substr(0, eq)] = std::stod(v.substr(eq + 1));
			}
			else if (a == "--help" || a == "-h")
			{
				std::puts("lumped-coil-gen -o OUT.csv [--profile lab|cooling|short] [--seed N] [--dt S] [--effect ID=RATIO]...\n"
						  "A FOG chamber run from the lumped 3-node test generator (tests/support/LumpedCoilGenerator.h).");
				return 0;
			}
			else
				throw std::invalid_argument("unknown argument '" + a + "' (try --help)");
		}
		if (out.empty()) throw std::invalid_argument("-o OUT.csv is required");
		const auto run = fogtest::makeLumpedCoilRun(opt);
		mrpt_fog::writeFogCsv(out, run.series);
		return 0;
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "lumped-coil-gen: error: %s\n", e.what());
		return 1;
	}
}
