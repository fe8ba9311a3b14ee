/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* shell-coil-gen: writes a run of the third test generator (tests/support/ShellCoilGenerator.h)
 * as CSV, for integration checks and benches.
 *
 *   shell-coil-gen -o run.csv [--seed N] [--dt S] [--effect ID=RATIO]... [--average-s A]
 */
#include <mrpt_fog/io/FogLogIO.h>

#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "ShellCoilGenerator.h"

int main(int argc, char** argv)
{
	try
	{
		fogtest::ShellCoilOptions opt;
		std::string out;
		double average_s = 0;
		for (int i = 1; i < argc; ++i)
		{
			const std::string a = argv[i];
			auto value = [&]() -> std::string {
				if (i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
				return argv[++i];
			};
			if (a == "-o") out = value();
			else if (a == "--seed") opt.seed = std::stoull(value());
			else if (a == "--dt") opt.dt_s = std::stod(value());
			else if (a == "--average-s") average_s = std::stod(value());
			else if (a == "--effect")
			{
				const std::string v = value();
				const auto eq = v.find('=');
				if (eq == std::string::npos) throw std::invalid_argument("--effect " + v + ": expected ID=RATIO");
				opt.hidden[v.substr(0, eq)] = std::stod(v.substr(eq + 1));
			}
			else if (a == "--help" || a == "-h")
			{
				std::puts("shell-coil-gen -o OUT.csv [--seed N] [--dt S] [--effect ID=RATIO]... [--average-s A]\n"
						  "A FOG chamber run (~9.7 h) from the five-shell test generator (tests/support/ShellCoilGenerator.h).\n"
						  "--dt: sample period [s] (0.01..10); --average-s: write A-second averages of the samples\n"
						  "(the same run as a slower logger averaging the increments would record).\n"
						  "Example: shell-coil-gen -o a.csv --dt 0.1 --seed 2 --effect magnetic=3");
				return 0;
			}
			else
				throw std::invalid_argument("unknown argument '" + a + "' (try --help)");
		}
		if (out.empty()) throw std::invalid_argument("-o OUT.csv is required");
		const auto run = fogtest::makeShellCoilRun(opt);
		mrpt_fog::writeFogCsv(out, average_s > 0 ? fogtest::averagedShellCoilSeries(run.series, opt.dt_s, average_s) : run.series);
		return 0;
	}
	catch (const std::exception& e)
	{
		std::fprintf(stderr, "shell-coil-gen: error: %s\n", e.what());
		return 1;
	}
}
