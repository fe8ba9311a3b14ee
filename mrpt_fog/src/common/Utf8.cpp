/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/Utf8.h>

namespace mrpt_fog
{
std::size_t firstInvalidUtf8(const std::string& t)
{
	// RFC 3629 / Unicode Table 3-7 (well-formed byte sequences): the second byte's range depends
	// on the lead byte, which refuses overlong forms (C0, C1, E0 80..9F, F0 80..8F), UTF-16
	// surrogates (ED A0..BF) and code points above U+10FFFF (F4 90.., F5..FF). libfyaml loops
	// forever on some of these inside a '%' directive line (found by fuzz_calibration_yaml).
	std::size_t i = 0;
	while (i < t.size())
	{
		const auto c = static_cast<unsigned char>(t[i]);
		if (c < 0x80)
		{
			i++;
			continue;
		}
		std::size_t n = 0;
		unsigned char lo = 0x80, hi = 0xBF;  // allowed range of the second byte
		if (c >= 0xC2 && c <= 0xDF) n = 2;
		else if (c >= 0xE0 && c <= 0xEF)
		{
			n = 3;
			if (c == 0xE0) lo = 0xA0;
			if (c == 0xED) hi = 0x9F;
		}
		else if (c >= 0xF0 && c <= 0xF4)
		{
			n = 4;
			if (c == 0xF0) lo = 0x90;
			if (c == 0xF4) hi = 0x8F;
		}
		if (n == 0 || i + n > t.size()) return i;
		const auto second = static_cast<unsigned char>(t[i + 1]);
		if (second < lo || second > hi) return i;
		for (std::size_t k = 2; k < n; k++)
			if ((static_cast<unsigned char>(t[i + k]) >> 6) != 0x2) return i;
		i += n;
	}
	return std::string::npos;
}
}  // namespace mrpt_fog
