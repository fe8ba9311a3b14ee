/* mrpt_fog: piecewise-linear temperature histories for the tests of the lag and hysteresis
 * signals (closed-form inputs, not made by the code under test). */
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace fogtest
{
/** The value at time t of the piecewise-linear history through (time [s], value) knots, held
 * at the last knot's value after it. */
inline double piecewise(const std::vector<std::pair<double, double>>& knots, double t)
{
	for (std::size_t i = 1; i < knots.size(); i++)
		if (t <= knots[i].first)
		{
			const auto& [t0, x0] = knots[i - 1];
			const auto& [t1, x1] = knots[i];
			return x0 + (x1 - x0) * (t - t0) / (t1 - t0);
		}
	return knots.back().second;
}
}  // namespace fogtest
