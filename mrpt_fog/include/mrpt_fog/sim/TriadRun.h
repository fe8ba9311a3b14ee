/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file TriadRun.h
 * A three-axis FOG (a triad: x, y, z coils in one housing) in the chamber or on the vehicle.
 *
 * Model (a simplification, said in docs/reference/simulator.md): the three coils share one thermal network
 * (same housing, same temperatures) and one set of thermistors (the device's, read by the up
 * axis' simulation); they differ in their error sensitivities (triadAxisDevice: estimates) and
 * in their noise (each axis its own seed, triadAxisSeed). Each axis is a FogSimulator of its
 * own device over the same chamber or cabin states; only the rate it is applied differs:
 *  - the up axis (the table axis in the chamber, z on the vehicle) is simulated exactly as the
 *    single-axis runs are (simulateChamber / simulateDrive with its device and seed): the z
 *    column of a z-up triad IS the single-axis run, bit for bit;
 *  - the two horizontal axes see the horizontal Earth rate, Omega cos(latitude), projected on
 *    them: at platform angle theta (table angle or vehicle yaw, counter-clockwise from the
 *    mount's reference) the axis east at theta = 0 sees Omega cos(lat) sin(theta), the one
 *    north at theta = 0 Omega cos(lat) cos(theta) (exact means over each sample interval).
 *    A level platform: no pitch or roll.
 * Mount at theta = 0 (right-handed): up z -> x east, y north; up x -> y east, z north; up y ->
 * z east, x north.
 *
 * Metadata (besides the single-axis run's): triad.up_axis, triad.mount, table_axis (the axis
 * the table turns about, = up axis), earth_rate_dph.<axis> for every axis whose Earth-rate
 * projection is constant over the run (the up axis always; the horizontal ones only when the
 * platform never turns), sim.triad.<axis>.<parameter> for the parameters in which the x and y
 * devices differ from the z device, and sim.triad.<axis>.seed. */

#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/DriveRun.h>

#include <cstdint>

namespace mrpt_fog::sim
{
/** The triad's coil on `axis`: z = `device` itself; x and y = the same coil and thermal
 * network with other error sensitivities (engineering estimates, docs/reference/simulator.md "Three-axis FOG"):
 *   x: midpoint_offset x -0.6, radial_gradient x 0.7, sf_ppm_per_C 14, constant_bias -0.2 deg/h
 *   y: midpoint_offset x 1.3,  radial_gradient x 1.3, sf_ppm_per_C 27, constant_bias 0.45 deg/h */
FogDevice triadAxisDevice(const FogDevice& device, GyroAxis axis);

/** Run seed of the triad's axis: z = `seed`; x, y = SplitMix64 of seed and the axis. */
std::uint64_t triadAxisSeed(std::uint64_t seed, GyroAxis axis);

/** A chamber run of the triad with `up` vertical (the profile's table turns about it). */
FogSeries simulateTriadChamber(const ChamberProfile& profile, const FogDevice& device, const SimSettings& settings,
							   GyroAxis up = GyroAxis::Z);

/** The vehicle drive (simulateDrive) with a z-up triad: fog and fog_ideal get x and y columns
 * (FOG_IDEAL observations in `others` too). */
DriveOutput simulateTriadDrive(const ChamberProfile& cabin, const FogDevice& device, const SimSettings& settings,
							   const OdometryErrors& odo = {});

}  // namespace mrpt_fog::sim
