/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file Units.h
 * Named unit conversions (never bare literals in formulas) and physical constants. */

#include <cmath>

namespace mrpt_fog::units
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kRadToDeg = 180.0 / kPi;
constexpr double kSecondsPerHour = 3600.0;
/** deg/h -> rad/s */
constexpr double kDegPerHourToRadPerSec = kDegToRad / kSecondsPerHour;
/** rad/s -> deg/h */
constexpr double kRadPerSecToDegPerHour = kRadToDeg * kSecondsPerHour;
/** Earth rotation rate [deg/h] (sidereal; WGS-84 7.292115e-5 rad/s). */
constexpr double kEarthRate_dph = 7.292115e-5 * kRadPerSecToDegPerHour;
/** Earth rotation rate [rad/s] (WGS-84). */
constexpr double kEarthRate_rad_s = 7.292115e-5;
/** Largest plausible applied axial magnetic field [uT]: 10 mT, 150x the Earth's field and beyond
 * the test coils of a gyro lab. Readers refuse larger field cells; a calibration's magnetic term
 * must stay a plausible bias up to it. */
constexpr double kMaxAbsField_uT = 1e4;
}  // namespace mrpt_fog::units
