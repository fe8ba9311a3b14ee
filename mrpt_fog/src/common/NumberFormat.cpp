/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/NumberFormat.h>

#include <cstdio>

namespace mrpt_fog
{
std::string formatValue(const char* printf_format, double v)
{
	char buf[128];
	const int n = std::snprintf(buf, sizeof buf, printf_format, v);
	if (n < 0) return {};
	if (static_cast<std::size_t>(n) < sizeof buf) return std::string(buf, static_cast<std::size_t>(n));
	std::string big(static_cast<std::size_t>(n) + 1, '\0');
	std::snprintf(big.data(), big.size(), printf_format, v);
	big.resize(static_cast<std::size_t>(n));
	return big;
}

}  // namespace mrpt_fog
