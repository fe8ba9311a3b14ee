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
		const auto t = runSeeds(hiddenSpec({GetParam()}, {ratio}), 100, 10000);
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

// --- On the real simulator (SimEffectTrial.h): 100 seeds per effect and ratio at the default
// suite's 0.05 Hz, 500 null trials, and the same at 0.1 Hz with 20 seeds / 100 nulls.
//   build/tests/test_discrepancy_long --gtest_filter='*Simulator*' | grep -A3 TRIALS
class ProofTrialsSimulatorLong : public ::testing::TestWithParam<std::string>
{
};

TEST_P(ProofTrialsSimulatorLong, HiddenEffectNamedAtRatios1And3)
{
	for (double rate_hz : {0.05, 0.1})
		for (double ratio : {1.0, 3.0})
		{
			SimTrialSpec spec;
			spec.hidden = GetParam();
			spec.ratio = ratio;
			spec.rate_hz = rate_hz;
			const int seeds = rate_hz < 0.075 ? 100 : 20;
			const auto t = runSimSeeds(spec, seeds, 20000);
			print("sim " + GetParam() + " @" + std::to_string(int(ratio)) + (rate_hz < 0.075 ? " 0.05Hz" : " 0.1Hz"), t);
			EXPECT_GE(t.named, 0.95 * seeds) << GetParam() << " ratio " << ratio << " at " << rate_hz << " Hz";
			EXPECT_GE(t.gap_ok, 0.95 * seeds) << GetParam() << " ratio " << ratio << " at " << rate_hz << " Hz";
		}
}

INSTANTIATE_TEST_SUITE_P(Effects, ProofTrialsSimulatorLong, ::testing::ValuesIn(simTrialEffects()),
						 [](const auto& info) { return info.param; });

class ProofTrialsSimulatorLongNull : public ::testing::TestWithParam<double>
{
};

TEST_P(ProofTrialsSimulatorLongNull, FalseNamingAtMostTwoPercent)
{
	SimTrialSpec spec;
	spec.rate_hz = GetParam();
	const int n = GetParam() < 0.075 ? 500 : 100;
	const auto t = runSimSeeds(spec, n, 60000);
	print("sim none at " + std::to_string(GetParam()) + " Hz", t);
	EXPECT_LE(t.false_naming, 0.02 * n) << t.false_naming << "/" << t.trials;
}

INSTANTIATE_TEST_SUITE_P(Rates, ProofTrialsSimulatorLongNull, ::testing::Values(0.05, 0.1),
						 [](const auto& info) { return info.param < 0.075 ? std::string("at0p05Hz") : std::string("at0p1Hz"); });
