/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

#include <string>

namespace mrpt_fog
{
/** The directory part of a path as `dirname` spells it: "." for a bare name, "/" at the root. */
std::string dirOf(const std::string& path);
/** The file name after the last '/' (the whole path when there is none). */
std::string baseOf(const std::string& path);
}  // namespace mrpt_fog
