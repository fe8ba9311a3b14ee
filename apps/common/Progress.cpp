/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "Progress.h"

#include <mrpt_fog/common/NumberFormat.h>

#include <unistd.h>

#include <cstdio>

namespace mrpt_fog::app
{
namespace
{
std::string amount(double v)
{
	if (v >= 1e6) return formatValue("%.1f M", v / 1e6);
	if (v >= 1e3) return formatValue("%.0f k", v / 1e3);
	return formatValue("%.0f ", v);
}
}  // namespace

Progress::Progress(std::string program, bool quiet)
	: program_(std::move(program)), quiet_(quiet), tty_(::isatty(STDERR_FILENO) == 1),
	  start_(std::chrono::steady_clock::now()), last_(start_)
{
}

Progress::~Progress() { finish(); }

void Progress::report(std::uint64_t samples, std::uint64_t done, std::uint64_t total)
{
	const auto now = std::chrono::steady_clock::now();
	const double elapsed = std::chrono::duration<double>(now - start_).count();
	const double since = std::chrono::duration<double>(now - last_).count();
	if (elapsed < 2.0 || since < (tty_ ? 1.0 : 10.0)) return;
	last_ = now;
	std::string line = program_ + ": " + amount(static_cast<double>(samples)) + "samples, " +
					   amount(static_cast<double>(samples) / elapsed) + "samples/s";
	if (total > 0 && done <= total)
	{
		const double f = static_cast<double>(done) / static_cast<double>(total);
		line += formatValue(", %.0f %%", 100.0 * f);
		if (f > 0.01) line += formatValue(", ETA %.0f s", elapsed * (1.0 - f) / f);
	}
	std::fprintf(stderr, tty_ ? "\r%s   " : "%s\n", line.c_str());
	std::fflush(stderr);
	printed_ = true;
}

void Progress::finish()
{
	if (printed_ && tty_) std::fputs("\n", stderr);
	printed_ = false;
}
}  // namespace mrpt_fog::app
