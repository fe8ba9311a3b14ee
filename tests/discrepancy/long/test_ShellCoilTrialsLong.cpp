/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The success table on the third generator (tests/support/ShellCoilGenerator.h), label "long",
 * analysed at fog-discrepancy's defaults (ShellCoilTrials.h). Knobs: SHELL_DT_S (sample period,
 * default 1 s), SHELL_SEEDS (trials per cell, default 10; nulls 5x), SHELL_FIRST_SEED (default the
 * held-out block fogtest::kShellCoilHeldOutSeedFirst = 5001; tuning used 1..10), SHELL_EFFECTS=a,b.
 * Targets: named in >= 95 % at effect/noise 3 and >= 80 % at 1; false naming on nulls <= 2 %.
 * Regenerate: test_discrepancy_long --gtest_filter='ShellCoilTrialsLong*' | grep -A3 SHELL */
#include <gtest/gtest.h>

#include <cstdlib>

#include "../ShellCoilTrials.h"

using namespace shell_trials;

namespace
{
double envDouble(const char* name, double fallback)
{
	const char* e = std::getenv(name);
	return e && *e ? std::atof(e) : fallback;
}
int seedsPerCell() { return static_cast<int>(envDouble("SHELL_SEEDS", 10)); }
std::uint64_t firstSeed()
{
	return static_cast<std::uint64_t>(envDouble("SHELL_FIRST_SEED", double(fogtest::kShellCoilHeldOutSeedFirst)));
}
bool effectSelected(const std::string& id)
{
	const char* e = std::getenv("SHELL_EFFECTS");
	if (!e || !*e) return true;
	return (std::string(",") + e + ",").find("," + id + ",") != std::string::npos;
}
/** Clopper-Pearson two-sided 95 % bound of k/n: the upper (upper = true) or lower one. */
double clopperPearson(int k, int n, bool upper)
{
	auto cdf = [&](double p, int kk) {  // P(X <= kk | p)
		if (kk < 0) return 0.0;
		double term = std::pow(1 - p, n), sum = term;
		for (int i = 1; i <= kk; ++i)
		{
			term *= (double(n - i + 1) / i) * (p / (1 - p));
			sum += term;
		}
		return sum;
	};
	if (upper && k >= n) return 1.0;
	if (!upper && k <= 0) return 0.0;
	double lo = 0, hi = 1;
	for (int it = 0; it < 100; ++it)
	{
		const double mid = 0.5 * (lo + hi);
		const bool above = upper ? cdf(mid, k) < 0.025 : 1.0 - cdf(mid, k - 1) > 0.025;
		(above ? hi : lo) = mid;
	}
	return 0.5 * (lo + hi);
}
}  // namespace

TEST(ShellCoilTrialsLong, EffectsNamedOnHeldOutSeeds)
{
	const int n = seedsPerCell();
	const double dt = envDouble("SHELL_DT_S", 1.0);
	int named3 = 0, trials3 = 0, named1 = 0, trials1 = 0;
	for (const auto& id : fogtest::shellCoilEffects())
		for (double ratio : {3.0, 1.0})
		{
			if (!effectSelected(id)) continue;
			const auto t = runShellCell(id, ratio, firstSeed(), n, dt);
			(ratio >= 3 ? named3 : named1) += t.named;
			(ratio >= 3 ? trials3 : trials1) += t.trials;
			EXPECT_GE(t.named, static_cast<int>(std::ceil((ratio >= 3 ? 0.95 : 0.80) * n))) << id << " x" << ratio;
		}
	std::printf("SHELL dt %gs pooled: x3 named %d/%d (Clopper-Pearson 95 %% lower %.1f %%), x1 named %d/%d (lower %.1f %%)\n",
				dt, named3, trials3, 100 * clopperPearson(named3, trials3, false), named1, trials1,
				100 * clopperPearson(named1, trials1, false));
}

TEST(ShellCoilTrialsLong, NullFalseNamingOnHeldOutSeeds)
{
	const int n = 5 * seedsPerCell();
	const double dt = envDouble("SHELL_DT_S", 1.0);
	const auto t = runShellCell("", 0.0, firstSeed(), n, dt);
	std::printf("SHELL dt %gs null false naming %d/%d, Clopper-Pearson 95 %% upper bound %.1f %%\n", dt, t.false_naming,
				t.trials, 100 * clopperPearson(t.false_naming, t.trials, true));
	EXPECT_LE(t.false_naming, static_cast<int>(std::floor(0.02 * n)));
}
