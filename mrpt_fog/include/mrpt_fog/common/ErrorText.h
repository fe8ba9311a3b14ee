/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

#include <string>

namespace mrpt_fog
{
/** An exception text on one line. MRPT exceptions read "==== MRPT exception ====\nMessage:
 * ...\nLocation: ...\nCall stack backtrace:\n...": only the message lines are kept, joined by
 * "; ". Other texts have their lines joined the same way. */
std::string oneLineErrorMessage(const std::string& what);
}  // namespace mrpt_fog
