/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The success table on the lumped-coil second generator, on seeds kept out of tuning
 * (fogtest::kHeldOutSeedFirst.. = 9101..; FOG_FOREIGN_FIRST_SEED=1 runs the tuning seeds), label "long". Per effect: FOG_FOREIGN_SEEDS trials
 * (default 20) at effect/noise 3 and 1; nulls: 5 x that many. Targets: named in
 * >= 95 % at 3 and >= 80 % at 1; false naming on nulls <= 2 % (Clopper-Pearson upper bound
 * printed); gap share >= 0.5. Regenerate: test_discrepancy_long --gtest_filter='ForeignTrialsLong*' | grep -A3 FOREIGN
 * Other knobs (ForeignTrials.h): FOG_FOREIGN_DT_S (sample period), FOG_FOREIGN_EFFECTS=a,b,
 * FOG_FOREIGN_DEBUG=1 (per-round chi-squares, confirmation, guard-rail rejections per trial),
 * FOG_FOREIGN_HYST_HALF_WIDTH_C (the generator's play half-width, default 2 C: how the
 * hysteresis candidate's grid fares off its grid points). */
#include <algorithm>
#include <cstdlib>

#include "../ForeignTrials.h"

using namespace foreign_trials;

namespace
{
int seedsPerCell()
{
	const char* e = std::getenv("FOG_FOREIGN_SEEDS");
	const int n = e ? std::atoi(e) : 0;
	return n > 0 ? n : 20;
}
/** First trial seed: the held-out block, or FOG_FOREIGN_FIRST_SEED (tuning runs). */
std::uint64_t firstSeed()
{
	const char* e = std::getenv("FOG_FOREIGN_FIRST_SEED");
	const long long v = e ? std::atoll(e) : 0;
	return v > 0 ? static_cast<std::uint64_t>(v) : fogtest::kHeldOutSeedFirst;
}

/** FOG_FOREIGN_EFFECTS=a,b: only these effects (default: all). */
bool effectSelected(const std::string& id)
{
	const char* e = std::getenv("FOG_FOREIGN_EFFECTS");
	if (!e || !*e) return true;
	const std::string list = std::string(",") + e + ",";
	return list.find("," + id + ",") != std::string::npos;
}
}  // namespace

TEST(ForeignTrialsLong, EffectsNamedOnHeldOutSeeds)
{
	const int n = seedsPerCell();
	for (const auto& id : fogtest::lumpedCoilEffects())
		for (double ratio : {3.0, 1.0})
		{
			if (!effectSelected(id)) continue;
			const auto t = runCell(id, ratio, firstSeed(), n);
			EXPECT_GE(t.named, static_cast<int>(std::ceil((ratio >= 3 ? 0.95 : 0.80) * n))) << id << " x" << ratio;
		}
}

TEST(ForeignTrialsLong, NullFalseNamingOnHeldOutSeeds)
{
	const int n = 5 * seedsPerCell();
	const auto t = runCell("", 0.0, firstSeed(), n);
	std::printf("FOREIGN null false naming %d/%d = %.1f %%, Clopper-Pearson 95 %% upper bound %.1f %%\n",
				t.false_naming, t.trials, 100.0 * t.false_naming / t.trials,
				100.0 * clopperPearsonUpper(t.false_naming, t.trials));
	EXPECT_LE(t.false_naming, static_cast<int>(std::floor(0.02 * n)));
}

TEST(ForeignTrialsLong, GapThroughTheCompensatorOnHeldOutSeeds)
{
	// the effects the compensator can run (thermal terms, scale factor, magnetic field): share of
	// the hidden gap removed on the confirmation run by the calibration --write-cal writes
	// (target >= 0.5)
	const int n = seedsPerCell();
	for (const char* id : {"temp_poly_order", "radial_gradient", "gradient_rate", "scale_factor_temp", "warmup",
						   "magnetic", "hysteresis"})
		for (double ratio : {3.0, 1.0})
		{
			if (!effectSelected(id)) continue;
			int ok = 0;
			std::vector<double> shares;
			for (int i = 0; i < n; ++i)
			{
				std::string line;
				const double sh = compensatorGapShare(id, ratio, firstSeed() + static_cast<std::uint64_t>(i), &line);
				shares.push_back(sh);
				ok += sh >= 0.5;
				std::printf("  %s\n", line.c_str());
			}
			std::sort(shares.begin(), shares.end());
			std::printf("FOREIGN dt %gs compensator gap %s x%g: share >= 0.5 in %d/%d (median %.2f)\n",
						trialSamplePeriod_s(), id, ratio, ok, n, shares[shares.size() / 2]);
			std::fflush(stdout);
			EXPECT_GE(ok, static_cast<int>(std::ceil(0.8 * n))) << id << " x" << ratio;
		}
}
