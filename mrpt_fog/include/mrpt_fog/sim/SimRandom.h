/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimRandom.h
 * Reproducible random numbers for the simulator: std::mt19937_64 (whose output sequence the C++
 * standard fixes) with our own uniform and Box-Muller normal transforms (std::normal_distribution
 * is implementation-defined, so it would break bit-for-bit reproducibility across standard
 * libraries). Independent streams (gyro noise, thermistors, odometry, trajectory) are seeded
 * from the run seed and a stream id through SplitMix64. */

#include <cstdint>
#include <random>

namespace mrpt_fog::sim
{
/** The run seed used when none is given (documented in docs/reference/simulator.md). */
constexpr std::uint64_t kDefaultSeed = 20240501;

/** Stream ids (never renumber: they fix the datasets). */
enum class RandomStream : std::uint64_t
{
	GyroNoise = 1,
	Thermistors = 2,
	Odometry = 3,
	Trajectory = 4,
	TurnOn = 5  //!< the turn-on offset and scale-factor draws (FogDevice::turn_on)
};

class SimRandom
{
   public:
	SimRandom(std::uint64_t run_seed, RandomStream stream);
	/** Uniform in [0, 1) with 53 random bits. */
	double uniform();
	/** Standard normal (Box-Muller, both values used). */
	double normal();

   private:
	std::mt19937_64 eng_;
	bool has_spare_ = false;
	double spare_ = 0;
};

}  // namespace mrpt_fog::sim
