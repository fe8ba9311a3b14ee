/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file DriveTrajectory.h
 * A planar ground-vehicle trajectory with exact truth: a list of segments in each of which the
 * speed changes linearly and the yaw rate is constant, so heading is linear in time and the
 * position has a closed form (no numerical integration anywhere). randomDrive() makes a drive
 * with stops, speed changes and left/right turns at realistic lateral accelerations. */

#include <cstdint>
#include <vector>

namespace mrpt_fog::sim
{
/** One segment: over duration_s the speed goes linearly to speed_end_mps, yaw rate constant. */
struct DriveSegment
{
	double duration_s = 0;
	double speed_end_mps = 0;  //!< >= 0
	double yaw_rate_dps = 0;  //!< [deg/s], positive = left (counter-clockwise, z up)
};

/** Planar state (x east, y north, yaw from x axis counter-clockwise). */
struct PlanarState
{
	double x_m = 0, y_m = 0, yaw_rad = 0;
	double speed_mps = 0, yaw_rate_rad_s = 0;
	double distance_m = 0;  //!< path length travelled since t = 0
};

class DriveTrajectory
{
   public:
	/** Throws std::invalid_argument for a negative speed or non-positive duration. */
	DriveTrajectory(const std::vector<DriveSegment>& segments, double initial_speed_mps = 0.0);

	/** A drive of exactly duration_s: starts with a 120 s stop, then cruises (8-20 m/s), turns
	 * (slowing to 5-9 m/s, +-45 to 180 deg, lateral acceleration <= 2.5 m/s2), stops (10-60 s)
	 * drawn from the seed's Trajectory stream. Accelerations 1.5 m/s2, braking 2 m/s2. */
	static DriveTrajectory randomDrive(std::uint64_t seed, double duration_s);

	double duration_s() const { return duration_s_; }
	const std::vector<DriveSegment>& segments() const { return segs_; }
	/** Exact state at time t (clamped to [0, duration]). */
	PlanarState at(double t_s) const;

   private:
	std::vector<DriveSegment> segs_;
	std::vector<double> start_s_;
	std::vector<PlanarState> start_state_;
	double v0_ = 0, duration_s_ = 0;
	PlanarState propagate(const PlanarState& s0, const DriveSegment& seg, double tau_s, double v_start) const;
};

}  // namespace mrpt_fog::sim
