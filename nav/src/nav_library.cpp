/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#include <mrpt_fog_nav/version.h>

namespace mrpt_fog::nav
{
const char* libraryName() { return "mrpt_fog_nav"; }
}  // namespace mrpt_fog::nav
