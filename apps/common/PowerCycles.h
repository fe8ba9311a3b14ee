/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file PowerCycles.h
 * Gyro-off rows and turn-on events of a log, counted row by row as the programs read it
 * (fog-convert, fog-compensate, fog-evaluate report them; docs/reference/logs.md). A row is gyro-off when
 * its power is 0; a turn-on is a row with power 1 right after a row with power 0. A row without
 * a power value (no power column) is neither, and a 0 -> missing -> 1 sequence is no turn-on:
 * the compensator restarts its warm-up only at an explicit 0 -> 1 step. fog-drift's powered
 * spans and gyro-off stretches (apps/fog-drift/GyroOff.h) follow the same rule. */

#include <mrpt_fog/obs/GyroPower.h>

#include <cmath>
#include <cstddef>

namespace mrpt_fog::app
{
/** The rule (obs/GyroPower.h), for the programs' rows. */
using mrpt_fog::isGyroOff;
using mrpt_fog::isTurnOn;

/** Gyro-off rows and turn-ons of a log, counted row by row. */
class PowerCycles
{
   public:
	/** Counts one row; returns whether it is a turn-on. */
	bool add(double power)
	{
		const bool turn_on = isTurnOn(prev_power_, power);
		if (isGyroOff(power)) gyro_off_rows++;
		if (turn_on) turn_ons++;
		prev_power_ = power;
		return turn_on;
	}

	std::size_t gyro_off_rows = 0;
	std::size_t turn_ons = 0;

   private:
	double prev_power_ = NAN;
};
}  // namespace mrpt_fog::app
