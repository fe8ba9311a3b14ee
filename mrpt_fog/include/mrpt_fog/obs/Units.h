/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file Units.h
 * Named unit conversions (never bare literals in formulas) and physical constants. */

#include <cmath>
#include <limits>

namespace mrpt_fog::units
{
constexpr double kPi = 3.14159265358979323846;
constexpr double kDegToRad = kPi / 180.0;
constexpr double kRadToDeg = 180.0 / kPi;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kSecondsPerMinute = 60.0;
constexpr double kSecondsPerHour = 3600.0;
/** sqrt(3600 s/h): an angle random walk N [deg/sqrt(h)] is a white rate of density 60 N
 * [deg/h/sqrt(Hz)], i.e. a rate sigma of 60 N / sqrt(T [s]) [deg/h] over an average of T s. */
constexpr double kSqrtSecondsPerHour = 60.0;
/** A missing value (no sample, undefined figure). */
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
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
