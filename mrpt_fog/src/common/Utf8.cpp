/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/Utf8.h>

namespace mrpt_fog
{
std::size_t firstInvalidUtf8(const std::string& t)
{
	std::size_t i = 0;
	while (i < t.size())
	{
		const auto c = static_cast<unsigned char>(t[i]);
		const std::size_t n = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
		if (n == 0 || (n == 2 && c < 0xC2) || i + n > t.size()) return i;
		for (std::size_t k = 1; k < n; k++)
			if ((static_cast<unsigned char>(t[i + k]) >> 6) != 0x2) return i;
		i += n;
	}
	return std::string::npos;
}
}  // namespace mrpt_fog
