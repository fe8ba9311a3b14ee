/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// The full generalization bench (label "long"): 24 fog-sim devices (tuning seeds 1..16, held-out
// seeds 17..24 never used in any tuning decision) at their drawn sample rates (1..100 Hz) and 8
// sector-coil devices (independent generator), every bench preset. Prints the table the issue asks
// for; asserts the targets the default meets. Calibrated on the seed profile alone, the
// noise-floor targets 1.3x / 2x are missed (printed, documented in docs/validation/generalization.md, not
// asserted); calibrated on one run of fog-sim's `calibration` profile they are asserted (last test).
#include "DeviceEnsemble.h"
#include "GeneralizationBench.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdio>

using namespace fogtest;

namespace
{
std::vector<PresetSummary> runSet(const std::vector<BenchCase>& cases, const char* title)
{
	const auto presets = benchPresets();
	const auto profiles = evaluationProfiles();
	std::vector<CaseResult> all;
	for (const auto& c : cases)
	{
		const auto r = runBenchCase(c, presets, profiles);
		all.insert(all.end(), r.begin(), r.end());
	}
	const auto sum = summarise(all, presets);
	std::printf("%s\n  %-24s %6s %5s %8s %8s %14s\n", title, "preset", "cases", "fail", "median", "p90", "oor raw/comp");
	for (const auto& s : sum)
		std::printf("  %-24s %6zu %5zu %8.2f %8.2f %14.2f\n", s.preset.c_str(), s.cases, s.failures, s.median_ratio,
					s.p90_ratio, s.oor_median_raw_over_comp);
	return sum;
}

void checkTargets(const std::vector<PresetSummary>& sum)
{
	double best_fixed = 1e300, def = 0, def_oor = 0;
	const auto presets = benchPresets();
	for (std::size_t i = 0; i < sum.size(); i++)
	{
		if (presets[i].fixed) best_fixed = std::min(best_fixed, sum[i].median_ratio);
		if (presets[i].label == "default (multipoint)")
		{
			def = sum[i].median_ratio;
			def_oor = sum[i].oor_median_raw_over_comp;
		}
	}
	EXPECT_LE(def, 1.10 * best_fixed);
	EXPECT_GE(def_oor, 3.0);
}
}  // namespace

TEST(GeneralizationBenchFull, FogSimHeldOutSeeds)
{
	std::vector<BenchCase> cases;
	for (auto s : heldOutSeeds()) cases.push_back({Generator::FogSim, s});
	checkTargets(runSet(cases, "fog-sim devices, held-out seeds 17..24 (never tuned on)"));
}

TEST(GeneralizationBenchFull, FogSimTuningSeeds)
{
	std::vector<BenchCase> cases;
	for (auto s : tuningSeeds()) cases.push_back({Generator::FogSim, s});
	checkTargets(runSet(cases, "fog-sim devices, tuning seeds 1..16"));
}

TEST(GeneralizationBenchFull, SectorCoilIndependentGenerator)
{
	std::vector<BenchCase> cases;
	for (std::uint64_t s = 1; s <= 8; s++) cases.push_back({Generator::SectorCoil, s});
	checkTargets(runSet(cases, "sector-coil devices 1..8 (independent generator)"));
}

// One calibration run of fog-sim's `calibration` profile (a turn-on, the seed ramps, a sine and
// fast ramps; the first hour after the turn-on out of the bias fit, the warm-up fitted on the same
// run), seeds 105..120 at their drawn rates: the set first run after every choice (quantum window
// 0.02 degC, one-run profile) was fixed, once. Measured: default median 1.13, p90 1.71, 4.6 %
// behind multipoint@3/1, out of range 4.89. The same code on seeds 73..88 / 89..104: 1.17 / 1.66
// and 1.21 / 2.07 (the p90 misses there by 0.07), on the tuning seeds 1..16: 1.22 / 2.70
// (docs/validation/generalization.md, "One calibration run"). Asserted: the four bench targets.
TEST(GeneralizationBenchFull, OneCalibrationRunFreshSeeds)
{
	std::vector<BenchCase> cases;
	for (std::uint64_t s = 105; s <= 120; s++)
	{
		BenchCase c{Generator::FogSim, s};
		c.calibration_profile = "cal_single";
		cases.push_back(c);
	}
	const auto sum = runSet(cases, "fog-sim devices 105..120, one `calibration` run each");
	checkTargets(sum);
	const auto presets = benchPresets();
	for (std::size_t i = 0; i < sum.size(); i++)
		if (presets[i].label == "default (multipoint)")
		{
			EXPECT_LE(sum[i].median_ratio, 1.3);
			EXPECT_LE(sum[i].p90_ratio, 2.0);
		}
}
