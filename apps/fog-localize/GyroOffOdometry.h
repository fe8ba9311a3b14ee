/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file GyroOffOdometry.h
 * The odometry each filter step gets on a drive whose gyro is off in places (power-0 rows:
 * no gyro sample; docs/guide/localization.md, "Gyro off").
 *
 * While the gyro is off its heading is not observable from the gyro. A particle filter does not
 * need to stop there: MRPT's pf-localization, given wheel odometry and no gyro, moves the
 * particles by the wheel odometry's increment (distance and the wheels' own heading change) under
 * MRPT's default Gaussian motion model (heading std 0.2 deg + 1 deg per metre + 5 % of the turn),
 * and the laser re-fixes the heading where the map allows. fog-localize does the same on every
 * step that touches a gyro-off stretch (StepSource::WheelOnly); elsewhere a step is the gyro's
 * (wheel distance + FOG heading, the FOG motion model). The filter is not re-initialised at the
 * turn-on: nothing but the truth could re-initialise it on a simulated drive, and the truth is
 * no sensor.
 *
 * Each powered span is dead-reckoned alone (heading/TruthAlignedDeadReckoning.h, aligned from the
 * truth at the span's start: only the increments reach the filter, and they do not depend on
 * that alignment). The poses at the scan times are chained: the first span's as dead-reckoned,
 * every later span rigidly moved onto the chain at its first scan, and the wheel increments in
 * between. A drive powered throughout gives exactly the poses of the one dead-reckoned
 * trajectory. */

#include <mrpt/poses/CPose2D.h>
#include <mrpt_fog_heading/DriveLog.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <cstddef>
#include <vector>

namespace mrpt_fog::localize
{
/** What moved the particles over a step. */
enum class StepSource
{
	Gyro,  //!< wheel distance + FOG heading, the FOG motion model
	WheelOnly  //!< the wheel odometry's increment (a gyro-off stretch), MRPT's default wheel model
};

struct ScanOdometry
{
	std::vector<mrpt::poses::CPose2D> poses;  //!< at each scan time
	std::vector<StepSource> step;  //!< step[k]: from scan k-1 to scan k (step[0] is Gyro, unused)
	std::size_t wheel_only_steps = 0;
};

/** The wheel odometry's pose at t (linear in x and y, shortest arc in heading; clamped to its
 * first and last pose). */
mrpt::poses::CPose2D wheelPoseAt(const heading::OdometryPoses& wheel, double t_s);

/** spans: the dead-reckoned trajectory of each navigated powered span, in time order and
 * disjoint (one span on a drive powered throughout). A step is Gyro when both its scans lie in
 * the same span's trajectory, else WheelOnly. `start`: the pose at scan_t_s[0] when no span
 * covers it. Throws std::invalid_argument on fewer than 2 scans or no wheel odometry. */
ScanOdometry odometryAtScans(const std::vector<nav::Trajectory>& spans, const heading::OdometryPoses& wheel,
							 const std::vector<double>& scan_t_s, const mrpt::poses::CPose2D& start);

}  // namespace mrpt_fog::localize
