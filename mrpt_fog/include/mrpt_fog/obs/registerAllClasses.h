/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** Registers mrpt_fog's serializable classes (CObservationFOG) with MRPT's RTTI so that
 * rawlog readers can create them. Called automatically when libmrpt_fog.so is loaded (an
 * MRPT_INITIALIZER), and exported so that programs can call it explicitly: GCC links with
 * --as-needed here, and a library none of whose symbols a program uses is dropped, its classes
 * then never registered. Safe to call more than once. */
namespace mrpt_fog
{
void registerAllClasses_mrpt_fog();
}  // namespace mrpt_fog
