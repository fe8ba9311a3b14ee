/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/io/NumberText.h>

#include <charconv>
#include <cmath>

namespace mrpt_fog::io
{
std::string formatNumber(double v)
{
	if (std::isnan(v)) return "nan";
	char buf[400];
	// Plain decimals for everyday magnitudes (UNIX times, temperatures), exponents otherwise;
	// either form is the shortest that reads back to exactly v.
	const double a = std::fabs(v);
	const bool fixed = v == 0.0 || (a >= 1e-4 && a < 1e16);
	const auto r = fixed ? std::to_chars(buf, buf + sizeof(buf), v, std::chars_format::fixed)
						 : std::to_chars(buf, buf + sizeof(buf), v);
	return std::string(buf, r.ptr);
}

std::optional<double> parseNumber(const std::string& text) { return parseNumber(std::string_view(text)); }

std::optional<double> parseNumber(std::string_view text)
{
	std::size_t b = 0, e = text.size();
	while (b < e && (text[b] == ' ' || text[b] == '\t')) b++;
	while (e > b && (text[e - 1] == ' ' || text[e - 1] == '\t')) e--;
	if (b == e) return std::nullopt;
	if (text[b] == '+')
	{
		b++;
		if (b >= e || text[b] == '-' || text[b] == '+') return std::nullopt;
	}
	double v = 0;
	const char* first = text.data() + b;
	const char* last = text.data() + e;
	const auto r = std::from_chars(first, last, v);
	if (r.ec != std::errc() || r.ptr != last) return std::nullopt;
	return v;
}

}  // namespace mrpt_fog::io
