/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The success table on the third generator (tests/support/ShellCoilGenerator.h), label "long",
 * analysed at fog-discrepancy's defaults (ShellCoilTrials.h). Knobs: SHELL_DT_S (sample period,
 * default 1 s), SHELL_SEEDS (trials per cell, default 10; nulls 5x), SHELL_FIRST_SEED (default the
 * held-out block fogtest::kShellCoilHeldOutSeedFirst = 9001; tuning and diagnosis used 1..10,
 * 5001..5005 and 7001..: ShellCoilGenerator.h), SHELL_EFFECTS=a,b.
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

/* The same physics at 10 Hz and averaged to 1 Hz gets the same verdict: one 10 Hz run pair per
 * hidden effect (x3, trial seeds kShellCoilResampleSeedFirst.., one per effect, outside every
 * tuning block), analysed as fog-discrepancy reads the 10 Hz files (the reader's 1 s block means)
 * and as it reads the same runs written as 1 s averages by a logger (averagedShellCoilSeries).
 * The named ids (strongest first) must be equal; the rows differ only where power and table rate
 * change inside a second. Printed with "RESAMPLE". */
TEST(ShellCoilTrialsLong, ResampledFrom10HzTo1HzNamesTheSameEffects)
{
	const std::uint64_t first = static_cast<std::uint64_t>(envDouble("SHELL_RESAMPLE_FIRST_SEED", 8101));
	std::uint64_t seed = first;
	for (const auto& id : fogtest::shellCoilEffects())
	{
		if (!effectSelected(id)) continue;
		fogtest::ShellCoilOptions o1, o2;
		o1.dt_s = o2.dt_s = 0.1;
		o1.seed = 2 * seed;
		o2.seed = 2 * seed + 1;
		o1.hidden[id] = o2.hidden[id] = 3.0;
		const auto s1 = fogtest::makeShellCoilRun(o1).series, s2 = fogtest::makeShellCoilRun(o2).series;
		const auto at10 = analyseDiscrepancy({asRead(s1), asRead(s2)}, {"run1", "run2"}, kBaseModel, trialOptions());
		const auto at1 = analyseDiscrepancy({asRead(fogtest::averagedShellCoilSeries(s1, 0.1, 1.0)),
											 asRead(fogtest::averagedShellCoilSeries(s2, 0.1, 1.0))},
											{"run1", "run2"}, kBaseModel, trialOptions());
		std::vector<std::string> n10, n1;
		for (const auto& ne : at10.selection.named) n10.push_back(ne.id);
		for (const auto& ne : at1.selection.named) n1.push_back(ne.id);
		std::printf("RESAMPLE seed %llu %s x3: 10 Hz (1 s means) \"%s\", block %.3g s | 1 Hz averages \"%s\", block %.3g s\n",
					static_cast<unsigned long long>(seed), id.c_str(), at10.verdict().c_str(), at10.timescale.block_s,
					at1.verdict().c_str(), at1.timescale.block_s);
		std::fflush(stdout);
		EXPECT_EQ(n10, n1) << id << " seed " << seed;
		EXPECT_EQ(at10.timescale.block_s, at1.timescale.block_s) << id;
		++seed;
	}
}
