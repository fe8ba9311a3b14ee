/* mrpt_fog_nav: strapdown attitude, dead reckoning and drift evaluation. */
#pragma once

namespace mrpt_fog::nav
{
/** "mrpt_fog_nav" (lets tools check which library they loaded). */
const char* libraryName();
}  // namespace mrpt_fog::nav
