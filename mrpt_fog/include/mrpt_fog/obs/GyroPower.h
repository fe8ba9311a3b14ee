/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file GyroPower.h
 * The gyro-off rule, written once (the programs' power counts, the compensator's turn-ons and
 * the heading pipeline's powered spans all use it). A sample is gyro-off when its power is 0;
 * a turn-on is a sample with power 1 right after a sample with power 0. A sample without a
 * power value (NaN: no power column) is neither, and a 0 -> missing -> 1 sequence is no
 * turn-on: the compensator restarts its warm-up only at an explicit 0 -> 1 step. */

namespace mrpt_fog
{
/** The gyro is off when its power is 0 (power: 1, 0, or NaN when unknown). */
inline bool isGyroOff(double power) { return power == 0.0; }
/** A turn-on: power 1 right after power 0. */
inline bool isTurnOn(double prev_power, double power) { return power == 1.0 && prev_power == 0.0; }
}  // namespace mrpt_fog
