/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/PathParts.h>

namespace mrpt_fog
{
std::string dirOf(const std::string& path)
{
	const auto slash = path.find_last_of('/');
	if (slash == std::string::npos) return ".";
	if (slash == 0) return "/";
	return path.substr(0, slash);
}

std::string baseOf(const std::string& path)
{
	const auto slash = path.find_last_of('/');
	return slash == std::string::npos ? path : path.substr(slash + 1);
}
}  // namespace mrpt_fog
