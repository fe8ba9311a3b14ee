/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file Progress.h
 * Progress of long work on stderr: "fog-x: 1.2 M samples, 410 k samples/s, 38 % of IN, ETA 9 s".
 * Nothing during the first 2 s (short runs stay quiet); then at most one update per second on
 * a terminal (rewritten in place with '\r'), one line every 10 s otherwise; a final newline on a
 * terminal. Off with quiet (--quiet). The fraction and ETA come from the bytes of the input
 * file consumed (compressed bytes for gzip), when its size is known. */

#include <chrono>
#include <cstdint>
#include <string>

namespace mrpt_fog::app
{
class Progress
{
   public:
	Progress(std::string program, bool quiet);
	~Progress();
	/** Cheap: call per sample. */
	void update(std::uint64_t samples, std::uint64_t bytes_done, std::uint64_t bytes_total)
	{
		if (quiet_ || (++calls_ & 0x3FFF) != 0) return;
		report(samples, bytes_done, bytes_total);
	}
	/** Ends the progress line (call before printing the summary). */
	void finish();

   private:
	void report(std::uint64_t samples, std::uint64_t bytes_done, std::uint64_t bytes_total);
	std::string program_;
	bool quiet_ = false, tty_ = false, printed_ = false;
	std::uint64_t calls_ = 0;
	std::chrono::steady_clock::time_point start_, last_;
};
}  // namespace mrpt_fog::app
