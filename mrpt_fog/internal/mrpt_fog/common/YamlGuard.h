/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file YamlGuard.h
 * Limits checked on a YAML text BEFORE MRPT's parser (libfyaml + a recursive conversion) sees
 * it. That parser crashes (stack overflow, SIGSEGV) on deep nesting such as 100 000 x '[', and
 * costs ~90 bytes of memory per byte of text. Every YAML file the library reads (calibrations,
 * chamber profiles, device and simulator configurations) goes through readYamlTextLimited():
 *  - size: at most max_bytes (checked on the file size before reading, and while reading);
 *  - nesting: at most max_depth levels, counting block indentation levels, compact "- - x"
 *    sequences, "key:" maps and flow '[' / '{' brackets (an over-estimate: real files of this
 *    project nest at most 6 deep);
 *  - aliases (*name) are refused: the files of this project never use them, and expanding them
 *    is the "billion laughs" memory bomb;
 *  - valid UTF-8 (common/Utf8.h).
 * A violation throws std::invalid_argument "<source>: <what> (limit <n>)". */

#include <cstddef>
#include <string>

namespace mrpt_fog
{
struct YamlLimits
{
	std::size_t max_bytes = 16u << 20;  //!< 16 MiB
	std::size_t max_depth = 64;
};

/** Throws std::invalid_argument when `text` breaks a limit (see the file comment). */
void requireSafeYamlText(const std::string& text, const std::string& source, const YamlLimits& limits = {});

/** Reads a YAML file (at most limits.max_bytes, refused before reading when larger) and checks it
 * with requireSafeYamlText. Throws std::invalid_argument naming the path. */
std::string readYamlTextLimited(const std::string& path, const YamlLimits& limits = {});

}  // namespace mrpt_fog
