/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/ErrorText.h>

#include <sstream>

namespace mrpt_fog
{
std::string oneLineErrorMessage(const std::string& what)
{
	std::istringstream in(what);
	std::string line, out;
	while (std::getline(in, line))
	{
		if (line.rfind("Call stack backtrace", 0) == 0) break;
		if (line.rfind("==== MRPT exception", 0) == 0 || line.rfind("Location:", 0) == 0) continue;
		if (line.rfind("Message:", 0) == 0) line = line.substr(8);
		const auto b = line.find_first_not_of(" \t"), e = line.find_last_not_of(" \t\r");
		if (b == std::string::npos) continue;
		out += (out.empty() ? "" : "; ") + line.substr(b, e - b + 1);
	}
	return out.empty() ? "unknown error" : out;
}
}  // namespace mrpt_fog
