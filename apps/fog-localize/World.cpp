/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "World.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

namespace mrpt_fog::localize
{
const char* stretchKindName(StretchKind k)
{
	switch (k)
	{
		case StretchKind::Urban: return "urban";
		case StretchKind::Open: return "open";
		case StretchKind::Tunnel: return "tunnel";
	}
	return "?";
}

FieldPlacement fieldPlacementFromString(const std::string& text)
{
	if (text == "straights") return FieldPlacement::Straights;
	if (text == "turns") return FieldPlacement::Turns;
	throw std::invalid_argument("field placement '" + text + "' is not straights|turns");
}

const Stretch& stretchAt(const std::vector<Stretch>& stretches, double t_s)
{
	for (const auto& s : stretches)
		if (t_s < s.t_end_s) return s;
	return stretches.back();
}

namespace
{
/** A straight piece of the route: indices into the truth and its distance interval. */
struct Straight
{
	double s0 = 0, s1 = 0;
	double length() const { return s1 - s0; }
};

/** Time at distance s along the route (linear in the cumulative distance). */
double timeAt(const nav::Trajectory& truth, const std::vector<double>& s_m, double s)
{
	auto it = std::lower_bound(s_m.begin(), s_m.end(), s);
	if (it == s_m.begin()) return truth.front().t_s;
	if (it == s_m.end()) return truth.back().t_s;
	const std::size_t i = static_cast<std::size_t>(it - s_m.begin());
	const double f = (s - s_m[i - 1]) / std::max(1e-12, s_m[i] - s_m[i - 1]);
	return truth[i - 1].t_s + f * (truth[i].t_s - truth[i - 1].t_s);
}

void markOccupied(mrpt::maps::COccupancyGridMap2D& g, double x, double y)
{
	const int cx = g.x2idx(x), cy = g.y2idx(y);
	if (cx >= 0 && cy >= 0 && cx < static_cast<int>(g.getSizeX()) && cy < static_cast<int>(g.getSizeY()))
		g.setCell(cx, cy, 0.0f);
}

void clearDisk(mrpt::maps::COccupancyGridMap2D& g, double x, double y, double r)
{
	const int n = static_cast<int>(std::ceil(r / g.getResolution()));
	const int cx = g.x2idx(x), cy = g.y2idx(y);
	for (int dy = -n; dy <= n; ++dy)
		for (int dx = -n; dx <= n; ++dx)
		{
			const int ix = cx + dx, iy = cy + dy;
			if (ix < 0 || iy < 0 || ix >= static_cast<int>(g.getSizeX()) || iy >= static_cast<int>(g.getSizeY())) continue;
			if (std::hypot(g.idx2x(ix) - x, g.idx2y(iy) - y) <= r) g.setCell(ix, iy, 1.0f);
		}
}
}  // namespace

World buildWorld(const nav::Trajectory& truth, const WorldOptions& o)
{
	if (truth.size() < 2) throw std::runtime_error("world: the truth has fewer than 2 poses");
	// Cumulative distance and straight pieces (|yaw rate| small).
	std::vector<double> s_m(truth.size(), 0.0);
	for (std::size_t i = 1; i < truth.size(); ++i)
		s_m[i] = s_m[i - 1] + std::hypot(truth[i].x_m - truth[i - 1].x_m, truth[i].y_m - truth[i - 1].y_m);
	std::vector<Straight> straights;
	const double max_rate = o.straight_max_yaw_rate_dps * M_PI / 180.0;
	std::size_t begin = 0;
	for (std::size_t i = 1; i <= truth.size(); ++i)
	{
		bool straight = false;
		if (i < truth.size())
		{
			const double dt = truth[i].t_s - truth[i - 1].t_s;
			const double dyaw = std::remainder(truth[i].yaw_rad - truth[i - 1].yaw_rad, 2 * M_PI);
			straight = dt > 0 && std::abs(dyaw / dt) < max_rate;
		}
		if (!straight)
		{
			if (i - 1 > begin) straights.push_back({s_m[begin], s_m[i - 1]});
			begin = i;
		}
	}
	std::sort(straights.begin(), straights.end(), [](const Straight& a, const Straight& b) { return a.length() > b.length(); });

	// Open stretches on the longest straights (or the most turning windows), a tunnel on the
	// longest straight not used.
	std::vector<std::pair<Straight, StretchKind>> special;
	std::size_t k = 0;
	if (o.placement == FieldPlacement::Straights)
	{
		for (; k < straights.size() && static_cast<int>(special.size()) < o.open_stretches; ++k)
		{
			const Straight& st = straights[k];
			if (st.length() - 2 * o.margin_m < o.min_open_m) break;
			special.push_back({{st.s0 + o.margin_m, st.s1 - o.margin_m}, StretchKind::Open});
		}
	}
	else
	{
		// Cumulative |heading change| along the route; windows of turn_field_m every 100 m,
		// greedily the most turning ones that keep turn_field_gap_m from each other and from
		// both ends of the route.
		std::vector<double> turn(truth.size(), 0.0);
		for (std::size_t i = 1; i < truth.size(); ++i)
			turn[i] = turn[i - 1] + std::abs(std::remainder(truth[i].yaw_rad - truth[i - 1].yaw_rad, 2 * M_PI));
		auto turnAt = [&](double s) {
			auto it = std::lower_bound(s_m.begin(), s_m.end(), s);
			return turn[std::min<std::size_t>(static_cast<std::size_t>(it - s_m.begin()), turn.size() - 1)];
		};
		std::vector<std::pair<double, double>> windows;  // (turned angle, start)
		for (double s0 = o.turn_field_gap_m; s0 + o.turn_field_m + o.turn_field_gap_m <= s_m.back(); s0 += 100.0)
			windows.push_back({turnAt(s0 + o.turn_field_m) - turnAt(s0), s0});
		std::sort(windows.begin(), windows.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
		for (const auto& [angle, s0] : windows)
		{
			if (static_cast<int>(special.size()) >= o.open_stretches) break;
			bool clear = true;
			for (const auto& sp : special)
				clear = clear && (s0 + o.turn_field_m + o.turn_field_gap_m <= sp.first.s0 || s0 >= sp.first.s1 + o.turn_field_gap_m);
			if (clear) special.push_back({{s0, s0 + o.turn_field_m}, StretchKind::Open});
		}
		// The tunnel goes on the longest straight that does not overlap a field.
		for (; k < straights.size(); ++k)
		{
			bool overlaps = false;
			for (const auto& sp : special)
				overlaps = overlaps || !(straights[k].s1 <= sp.first.s0 - 200.0 || straights[k].s0 >= sp.first.s1 + 200.0);
			if (!overlaps) break;
		}
	}
	if (static_cast<int>(special.size()) < o.open_stretches)
		throw std::runtime_error("world: the route has " + std::to_string(special.size()) + " straight(s) long enough for an open stretch of " +
								 std::to_string(o.min_open_m) + " m, " + std::to_string(o.open_stretches) + " requested");
	if (o.tunnel_m > 0 && k < straights.size() && straights[k].length() >= o.tunnel_m + 2 * 200.0)
	{
		const double mid = 0.5 * (straights[k].s0 + straights[k].s1);
		special.push_back({{mid - 0.5 * o.tunnel_m, mid + 0.5 * o.tunnel_m}, StretchKind::Tunnel});
	}
	std::sort(special.begin(), special.end(), [](const auto& a, const auto& b) { return a.first.s0 < b.first.s0; });

	World w;
	w.route_length_m = s_m.back();
	double s_prev = 0;
	for (const auto& [st, kind] : special)
	{
		if (st.s0 > s_prev) w.stretches.push_back({StretchKind::Urban, 0, 0, s_prev, st.s0});
		w.stretches.push_back({kind, 0, 0, st.s0, st.s1});
		s_prev = st.s1;
	}
	if (s_prev < s_m.back()) w.stretches.push_back({StretchKind::Urban, 0, 0, s_prev, s_m.back()});
	for (auto& st : w.stretches)
	{
		st.t_begin_s = timeAt(truth, s_m, st.s_begin_m);
		st.t_end_s = timeAt(truth, s_m, st.s_end_m);
	}
	w.stretches.back().t_end_s = truth.back().t_s + 1e-6;

	// The grid: bounding box of the route + the laser range.
	double xmin = 1e300, xmax = -1e300, ymin = 1e300, ymax = -1e300;
	for (const auto& p : truth)
	{
		xmin = std::min(xmin, p.x_m);
		xmax = std::max(xmax, p.x_m);
		ymin = std::min(ymin, p.y_m);
		ymax = std::max(ymax, p.y_m);
	}
	const double pad = o.laser_range_m + 40.0;
	w.grid = std::make_shared<mrpt::maps::COccupancyGridMap2D>(xmin - pad, xmax + pad, ymin - pad, ymax + pad, o.resolution_m);
	auto& g = *w.grid;
	g.fill(1.0f);  // free space everywhere; obstacles are only what the world puts there

	// Facades along urban stretches, walls along the tunnel, every metre of the route.
	std::mt19937_64 rng(o.seed);
	auto uni = [&](double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(rng); };
	struct Side
	{
		double next_change_m = 0, setback_m = 0;
		bool building = false;
	} sides[2];
	std::size_t i = 0;
	for (double s = 0; s <= s_m.back(); s += 1.0)
	{
		while (i + 1 < s_m.size() && s_m[i + 1] < s) ++i;
		const std::size_t j = std::min(i + 1, s_m.size() - 1);
		const double f = (s_m[j] > s_m[i]) ? (s - s_m[i]) / (s_m[j] - s_m[i]) : 0.0;
		const double x = truth[i].x_m + f * (truth[j].x_m - truth[i].x_m);
		const double y = truth[i].y_m + f * (truth[j].y_m - truth[i].y_m);
		const double yaw = truth[i].yaw_rad;
		const double nx = -std::sin(yaw), ny = std::cos(yaw);  // left normal
		StretchKind kind = StretchKind::Urban;
		for (const auto& st : w.stretches)
			if (s >= st.s_begin_m && s < st.s_end_m) kind = st.kind;
		for (int side = 0; side < 2; ++side)
		{
			Side& sd = sides[side];
			const double sign = side == 0 ? 1.0 : -1.0;
			if (s >= sd.next_change_m)
			{
				sd.building = !sd.building;
				sd.next_change_m = s + (sd.building ? uni(8.0, 40.0) : uni(4.0, 20.0));
				sd.setback_m = uni(8.0, 25.0);
			}
			if (kind == StretchKind::Urban && sd.building)
				markOccupied(g, x + sign * sd.setback_m * nx, y + sign * sd.setback_m * ny);
			else if (kind == StretchKind::Tunnel)
				markOccupied(g, x + sign * 6.0 * nx, y + sign * 6.0 * ny);
		}
	}
	// Open fields: nothing within the laser range of their road (this also removes facades of
	// other stretches that come near). Then the road itself is free everywhere.
	for (const auto& st : w.stretches)
	{
		if (st.kind != StretchKind::Open) continue;
		for (std::size_t q = 0; q < truth.size(); q += 5)
			if (s_m[q] >= st.s_begin_m && s_m[q] <= st.s_end_m)
				clearDisk(g, truth[q].x_m, truth[q].y_m, o.laser_range_m + 5.0);
	}
	for (std::size_t q = 0; q < truth.size(); q += 2) clearDisk(g, truth[q].x_m, truth[q].y_m, 4.0);
	return w;
}

}  // namespace mrpt_fog::localize
