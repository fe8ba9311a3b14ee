/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/** \file BlockAveraging.h
 * Test support (not part of the library): an independent estimate of the standard error of a
 * serially correlated mean, used by the model tests to judge held-out figures. */

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

namespace fogtest
{
/** Standard error of the mean of a serially correlated series by block averaging (Flyvbjerg &
 * Petersen 1989): non-finite samples are dropped, the series is cut into blocks of L = 1, 2, 4,
 * ... samples while at least 16 blocks remain (a trailing partial block is dropped), the standard
 * error sd(block means) / sqrt(blocks) is computed for each L, and the largest is returned (the
 * plateau, or the longest blocks allowed when the correlation outlasts them: then an
 * underestimate, flagged by *plateau = false). Throws std::invalid_argument for fewer than 32
 * finite samples. block_len (optional) receives the L of the returned value. */
inline double blockAveragedStandardError(const std::vector<double>& x_in, std::size_t* block_len = nullptr,
										 bool* plateau = nullptr)
{
	constexpr std::size_t kMinBlocks = 16;
	std::vector<double> x;
	for (double v : x_in)
		if (std::isfinite(v)) x.push_back(v);
	if (x.size() < 2 * kMinBlocks)
		throw std::invalid_argument("block averaging: " + std::to_string(x.size()) + " finite samples, need at least " +
									std::to_string(2 * kMinBlocks));
	double best = -1, prev = -1;
	std::size_t best_len = 1;
	bool rising_at_end = false;
	for (std::size_t len = 1; x.size() / len >= kMinBlocks; len *= 2)
	{
		const std::size_t nb = x.size() / len;
		std::vector<double> means(nb, 0.0);
		for (std::size_t b = 0; b < nb; b++)
		{
			for (std::size_t i = 0; i < len; i++) means[b] += x[b * len + i];
			means[b] /= static_cast<double>(len);
		}
		double mu = 0, var = 0;
		for (double m : means) mu += m;
		mu /= static_cast<double>(nb);
		for (double m : means) var += (m - mu) * (m - mu);
		var /= static_cast<double>(nb - 1);
		const double se = std::sqrt(var / static_cast<double>(nb));
		rising_at_end = prev >= 0 && se > 1.05 * prev;  // still growing by > 5 % per doubling
		prev = se;
		if (se > best)
		{
			best = se;
			best_len = len;
		}
	}
	if (block_len) *block_len = best_len;
	if (plateau) *plateau = !rising_at_end;
	return best;
}

}  // namespace fogtest
