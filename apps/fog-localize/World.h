/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#pragma once

/** \file World.h
 * A simulated world around the bundled drive's true route: an occupancy grid whose obstacles
 * depend on the kind of stretch the road passes through.
 * - Urban: building facades on both sides (setback 8-25 m, 8-40 m long, 4-20 m gaps): a laser
 *   sees corners and facades, which fix position and heading.
 * - Open (open fields): nothing within the laser's range of the road, and nothing of other
 *   stretches either: the filter dead-reckons on odometry (wheel distance + FOG heading).
 *   These are the observation-poor stretches the FOG is judged on. FieldPlacement::Turns
 *   (default) puts them on the windows of the route that turn most (sum of |heading change|):
 *   there the gyro's bias and its scale-factor error at each turn act, and the raw gyro's
 *   heading drift over a field exceeds the heading error the map-matching leaves at its entry.
 *   FieldPlacement::Straights puts them on the route's longest straight roads, away from turns:
 *   only the gyro's bias acts there, and on the bundled drive its drift over a straight is
 *   below the map-matching's entry heading error, so that even the ideal gyro gives 0.86x the
 *   raw position error (docs/guide/localization.md): there the map makes the gyro nearly irrelevant and
 *   fog-localize says "cannot tell" (HeadingRelevance). Both are chosen by route geometry,
 *   never by any gyro's error.
 * - Tunnel: smooth walls 6 m either side. The laser fixes lateral position and heading but
 *   not the position along the road: here the map makes the FOG heading irrelevant (only the
 *   wheel distance matters), which fog-localize reports separately.
 * The road itself (4 m either side of the route) is always free. Deterministic for a seed. */

#include <mrpt/maps/COccupancyGridMap2D.h>
#include <mrpt_fog_nav/Trajectory.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mrpt_fog::localize
{
enum class StretchKind
{
	Urban,
	Open,
	Tunnel
};
const char* stretchKindName(StretchKind k);  //!< "urban", "open", "tunnel"

/** Where the open fields go (see the file comment). */
enum class FieldPlacement
{
	Straights,
	Turns
};
/** "straights" / "turns"; throws std::invalid_argument naming the allowed values. */
FieldPlacement fieldPlacementFromString(const std::string& text);

struct Stretch
{
	StretchKind kind = StretchKind::Urban;
	double t_begin_s = 0, t_end_s = 0;  //!< absolute (UNIX) time on the true route
	double s_begin_m = 0, s_end_m = 0;  //!< distance along the true route from its start
};

struct WorldOptions
{
	double resolution_m = 2.0;  //!< grid cell size
	int open_stretches = 3;
	FieldPlacement placement = FieldPlacement::Turns;
	double turn_field_m = 4000.0;  //!< open-field length with FieldPlacement::Turns
	double turn_field_gap_m = 2000.0;  //!< urban road at least this long between such fields
	double margin_m = 800.0;  //!< urban road kept at both ends of a straight holding an open stretch
	double min_open_m = 2000.0;  //!< shortest open stretch
	double tunnel_m = 1500.0;  //!< tunnel length (on the next longest straight), 0 = none
	double straight_max_yaw_rate_dps = 0.3;  //!< |true yaw rate| below this counts as straight
	double laser_range_m = 60.0;  //!< open stretches are kept clear of obstacles within this
	std::uint64_t seed = 20240501;  //!< facade layout
};

struct World
{
	std::shared_ptr<mrpt::maps::COccupancyGridMap2D> grid;
	std::vector<Stretch> stretches;  //!< cover the whole route in time order
	double route_length_m = 0;
};

/** Builds the world around truth (time-ordered poses). Throws std::runtime_error when the
 * route has no straight long enough for the requested open stretches. */
World buildWorld(const nav::Trajectory& truth, const WorldOptions& options);

/** The stretch containing time t_s (the last one after the end, the first before the start). */
const Stretch& stretchAt(const std::vector<Stretch>& stretches, double t_s);

}  // namespace mrpt_fog::localize
