/* mrpt_fog: fuzzing helper: the readers take paths, so each input goes through a temp file. */
#pragma once

#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace fogfuzz
{
/** Writes the input to one temp file per process (same name every call), returns its path.
 * The file name ends in `suffix` (the readers pick the format by extension). */
inline const std::string& writeInput(const uint8_t* data, size_t size, const char* suffix)
{
	static const std::string path = [&] {
		const char* dir = std::getenv("TMPDIR");
		return std::string(dir && *dir ? dir : "/tmp") + "/mrpt_fog_fuzz_" + std::to_string(::getpid()) + suffix;
	}();
	std::FILE* f = std::fopen(path.c_str(), "wb");
	if (!f) std::abort();
	if (size && std::fwrite(data, 1, size, f) != size) std::abort();
	std::fclose(f);
	return path;
}

/** Reports an escape from the documented error contract and stops the fuzzer. */
[[noreturn]] inline void contractViolation(const char* what, const char* msg)
{
	std::fprintf(stderr, "contract violation: %s: %s\n", what, msg);
	std::abort();
}
}  // namespace fogfuzz
