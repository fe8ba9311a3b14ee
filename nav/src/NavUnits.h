/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file NavUnits.h
 * Unit conversions shared by the navigation library's sources (the library does not depend on
 * the thermal model's mrpt_fog/obs/Units.h). */

namespace mrpt_fog::nav::units
{
constexpr double kSecondsPerHour = 3600.0;
/** sqrt(3600 s/h): an angle random walk N [deg/sqrt(h)] is a rate sigma of 60 N / sqrt(T [s])
 * [deg/h] over an average of T s. */
constexpr double kSqrtSecondsPerHour = 60.0;
}  // namespace mrpt_fog::nav::units
