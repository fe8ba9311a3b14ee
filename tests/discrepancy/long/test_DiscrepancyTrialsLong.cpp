/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** Long proof trials (label "long"): 100 seeds per effect and ratio, 200 null trials, 20 seeds
 * per confounder scenario. Regenerate the table with
 *   ./build-disc/tests/test_discrepancy_long | grep -A1 TRIALS
 * (or ctest --test-dir build-disc -L long -R Discrepancy -V). */
#include <gtest/gtest.h>

#include "../TrialSuite.h"

using namespace trial_suite;

class ProofTrialsLong : public ::testing::TestWithParam<std::string>
{
};

TEST_P(ProofTrialsLong, HiddenEffectNamedAtRatios1And3)
{
	for (double ratio : {1.0, 3.0})
	{
		TrialSpec spec;
		spec.hidden = {GetParam()};
		spec.ratios = {ratio};
		const auto t = runSeeds(spec, 100, 10000);
		print(GetParam() + " @" + std::to_string(int(ratio)), t);
		EXPECT_GE(t.named, 95) << GetParam() << " ratio " << ratio;
		EXPECT_GE(t.gap_ok, 95) << GetParam() << " ratio " << ratio;
	}
}

INSTANTIATE_TEST_SUITE_P(Effects, ProofTrialsLong, ::testing::ValuesIn(biasEffects()),
						 [](const auto& info) { return info.param; });

TEST(ProofTrialsLongNull, FalseNamingAtMostTwoPercent)
{
	const auto t = nullTrials(200, 50000);
	print("none (confounders mixed in)", t);
	EXPECT_LE(t.false_naming, 4) << t.false_naming << "/" << t.trials;
}

TEST(ProofTrialsLongConfounders, NamedDespiteConfounders)
{
	for (const auto& [what, spec] : confounderScenarios())
	{
		const auto t = runSeeds(spec, 20, 30000);
		print(what, t);
		EXPECT_GE(t.named, 19) << what;
	}
}
