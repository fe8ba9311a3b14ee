/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

#include <cstddef>
#include <string>

namespace mrpt_fog
{
/** Offset of the first byte of `text` that is not valid UTF-8 (overlong 2-byte forms rejected),
 * or std::string::npos. Every YAML text is checked with it before MRPT's parser (libfyaml) sees
 * it: libfyaml loops forever on some invalid UTF-8, e.g. "%\xd5\n" (found by fuzzing). */
std::size_t firstInvalidUtf8(const std::string& text);
}  // namespace mrpt_fog
