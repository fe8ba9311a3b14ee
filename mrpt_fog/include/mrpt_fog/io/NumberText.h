/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file NumberText.h
 * Numbers in text files (CSV cells, metadata): printed in the shortest form that reads back to
 * the same double (so a CSV -> rawlog -> CSV round trip reproduces every digit), and parsed
 * strictly (the whole cell must be a number). */

#include <optional>
#include <string>
#include <string_view>

namespace mrpt_fog::io
{
/** Shortest text that parses back to exactly `v`: plain decimals for 1e-4 <= |v| < 1e16
 * ("0.1", "1700000000"), exponent form otherwise ("1e-07"); "nan", "inf". */
std::string formatNumber(double v);

/** Parses the whole of `text` (surrounding blanks allowed, a leading '+' accepted, "nan" and
 * "inf" accepted); std::nullopt if it is not entirely a number. */
std::optional<double> parseNumber(const std::string& text);
std::optional<double> parseNumber(std::string_view text);
inline std::optional<double> parseNumber(const char* text) { return parseNumber(std::string_view(text)); }

}  // namespace mrpt_fog::io
