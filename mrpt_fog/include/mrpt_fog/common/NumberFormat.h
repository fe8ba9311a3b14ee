/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file NumberFormat.h
 * The one formatter of numbers for reports and messages: printf-style, one number.
 * formatValue("%.4g", 0.000123456) == "0.0001235". (io::formatNumber in io/NumberText.h is the
 * other kind: the shortest text that reads back to the same double, for data files.)
 * An ostream with precision p and default flags prints like "%.<p>g".
 */

#include <string>

namespace mrpt_fog
{
/** `v` printed with `printf_format`, which must hold exactly one double conversion (%g, %f,
 * %e with flags / width / precision). Non-finite values print as printf does ("nan", "inf"). */
std::string formatValue(const char* printf_format, double v);

}  // namespace mrpt_fog
