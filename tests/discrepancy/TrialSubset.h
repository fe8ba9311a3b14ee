/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/** The sanitizer run's subset of the trials (FOG_TRIAL_SEEDS), read in one place. */
#include <algorithm>
#include <cstdlib>

namespace trial_subset
{
/** Seeds to run of a cell whose full count is `full` (10 or 100): all of them, unless
 * FOG_TRIAL_SEEDS = n (1..9) is set -- only scripts/run-sanitizers.sh sets it, where the trials
 * run 20-35x slower and the point is memory/UB checking, not the success table. The first
 * full * n / 10 seeds of the same list are run, and the table line says it is a subset. */
inline int trialSeeds(int full)
{
	const char* e = std::getenv("FOG_TRIAL_SEEDS");
	const int n = e ? std::atoi(e) : 0;
	return (n >= 1 && n < 10) ? std::max(1, full * n / 10) : full;
}

/** Whether the trials run as the sanitizer run's subset (FOG_TRIAL_SEEDS 1..9). */
inline bool subsetRun() { return trialSeeds(10) < 10; }

}  // namespace trial_subset
