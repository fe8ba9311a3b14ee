/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT.
 * The shared library libmrpt_fog.so: all rooms (static archives) linked in whole, so that it
 * works as an MRPT plugin (rawlog-edit -p, RawLogViewer): loading it runs the MRPT_INITIALIZER
 * in obs/registerAllClasses.cpp, which registers CObservationFOG. */
#include <mrpt_fog/obs/registerAllClasses.h>

namespace mrpt_fog
{
/** Library version "major.minor.patch". */
const char* libraryVersion() { return "0.1.0"; }
}  // namespace mrpt_fog
