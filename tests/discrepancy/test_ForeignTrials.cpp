/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* Hidden-effect trials on the lumped-coil second generator (ForeignTrials.h): the guard rails
 * on one tuning seed each (default suite); the per-effect table on held-out seeds is in
 * long/test_ForeignTrialsLong.cpp (label long). */
#include "ForeignTrials.h"

using namespace foreign_trials;

TEST(ForeignTrials, ClopperPearsonUpperBoundMatchesClosedForm)
{
	// k = 0: the upper bound solves (1 - p)^n = alpha / 2
	EXPECT_NEAR(clopperPearsonUpper(0, 100), 1 - std::pow(0.025, 1.0 / 100), 1e-9);
	// k = n - 1 of n: p^n + n p^(n-1) (1 - p) ... checked against the published table value
	// for 2 of 100 (0.0704, Clopper & Pearson via scipy.stats.beta.ppf(0.975, 3, 98))
	EXPECT_NEAR(clopperPearsonUpper(2, 100), 0.0704, 5e-4);
}

TEST(ForeignTrials, NullWithSlowBiasWanderNamesNothing)
{
	// one tuning seed (each trial analyses two 7.5 h runs at 1 s: the per-effect table is long)
	const auto t = runCell("", 0.0, 1, 1);
	EXPECT_EQ(t.false_naming, 0);
}

TEST(ForeignTrials, NullAt5sSamplingNamesNothing)
{
	// at 5 s the compensator's causal order-2 rate has 12 samples per 60 s window: its noise
	// left part of the true rate response in the residual and shupe_rate / radial_gradient were
	// named on nulls (16/20 tuning seeds) until the base carried the nuisance column
	// "centred minus causal rate" (BaseModelDesign.h). Tuning seeds 3-4 (seeds 1-10 were clean).
	const auto t = runCell("", 0.0, 3, 2, "lab", 5.0);
	EXPECT_EQ(t.false_naming, 0);
}

TEST(ForeignTrials, RadialGradientIsNamedWhenTheHousingThermistorCompletesIt)
{
	// the generator's I - O is 1.18 ((Ca - Cb) - 0.25 (Cb - Hs)) up to the thermistor lags: with
	// Tin - Tout alone the candidate could not reproduce it and shupe_rate / gradient_rate were
	// named (0/5, 0/5 on held-out seeds 9101-9105). Tuning seed 2 at 5 s.
	const auto t = runCell("radial_gradient", 3.0, 2, 1, "lab", 5.0);
	EXPECT_EQ(t.named, 1);
}

TEST(ForeignTrials, AddedRateTermGetsTheRateWindowTheAnalysedRunFitsBest)
{
	// gradient_rate at 5 s: the written d(Ca - Cb)/dt term on the base's 60 s order-2 causal rate
	// removed 0.22 of the hidden gap (tuning seed 1, x1); --write-cal now picks the window (1, 2
	// or 4 x 60 s) on the analysed run
	std::string line;
	const double share = compensatorGapShare("gradient_rate", 1.0, 1, &line, 5.0);
	std::printf("  %s\n", line.c_str());
	EXPECT_GE(share, 0.5);
}

TEST(ForeignTrials, HysteresisIsWrittenAsThePlayOperatorAndClosesTheGapThroughTheCompensator)
{
	// --write-cal with hysteresis named (tuning seed 9101 at 5 s, x1): the named play and width
	// become hyst(Ca,play,wC) in the calibration, refitted with the other added terms; share 0.86
	// of the hidden gap removed on the confirmation run through the compensator
	std::string line;
	const double share = compensatorGapShare("hysteresis", 1.0, 9101, &line, 5.0);
	std::printf("  %s\n", line.c_str());
	EXPECT_NE(line.find("hyst(Ca,play,"), std::string::npos);
	EXPECT_GE(share, 0.5);
}

TEST(ForeignTrials, HysteresisAtEffectNoise1IsNamedWithThePlayShapeAndTheWhitenedProfile)
{
	// the generator's hysteresis is a play operator: the exponential branch reproduced it only
	// in part, and the width chosen on the OLS residual (dominated by the 30 min bias wander) was
	// the grid's widest, so at effect/noise 1 it was not named ("nameable from 0.0186
	// deg/h RMS", hidden part 0.0141, on this seed). Tuning seed 9101 at 5 s.
	const auto t = runCell("hysteresis", 1.0, 9101, 1, "lab", 5.0);
	EXPECT_EQ(t.named, 1);
}

TEST(ForeignTrials, HysteresisOffTheWidthGridIsNamedAfterTheContinuousRefinement)
{
	// the generator's play half-width 3.2 C lies between the 1-2-5 grid's 2 and 5 C: at x1 it was
	// not named on tuning seed 9004 (5 s; 13/20 on 9001-9020) until the whitened profile was
	// refined continuously between the best grid value's neighbours (EffectSelector.cpp; 17/20).
	// The width found is not the generator's (a wide play is chosen at x1): only the naming is
	// checked.
	fogtest::LumpedCoilOptions o1, o2;
	o1.dt_s = o2.dt_s = 5.0;
	o1.seed = 2 * 9004;
	o2.seed = 2 * 9004 + 1;
	o1.hysteresis_half_width_C = o2.hysteresis_half_width_C = 3.2;
	o1.hidden["hysteresis"] = o2.hidden["hysteresis"] = 1.0;
	const auto rep = analyseDiscrepancy({makeLumpedCoilRun(o1).series, makeLumpedCoilRun(o2).series}, {"a", "b"},
										kBaseModel, trialOptions());
	ASSERT_FALSE(rep.selection.named.empty()) << rep.verdict();
	EXPECT_EQ(rep.selection.named.front().id, "hysteresis") << rep.verdict();
	std::printf("  %s; width %s\n", rep.verdict().c_str(), rep.selection.named.front().theta_meaning.c_str());
}

TEST(ForeignTrials, HeldOutAliasGroupTakesTheRankOfItsFirstNamedMember)
{
	// radial_gradient x3 (tuning seed 9075 at 5 s): shupe_rate is named in the first round,
	// gradient_rate and radial_gradient after it; the held-out rail finds that the other run
	// cannot tell shupe_rate from radial_gradient and moves it into radial_gradient's alias
	// group. The list is "strongest first": the group takes the rank of its member named first,
	// so it is listed before gradient_rate (named before radial_gradient). The case first used
	// here (gradient_rate x3, seed 9072) no longer exercises the rule since gradient_rate has a
	// lag: it is told apart on the other run; the preconditions below keep the case honest.
	const auto [r1, r2] = fogtest::makeLumpedCoilRunPair("radial_gradient", 3.0, 2 * 9075, 5.0);
	// the case was found with the rail on the per-row RMS of the 5 s rows as given; at the
	// default (100 s stability, rows from the data's timescale) the held-out alias is not
	// exercised: the rail is judged here at the rows' own 5 s
	auto opt = trialOptions();
	opt.analysis_block_s = -1.0;
	opt.tau_s = 5.0;
	const auto rep = analyseDiscrepancy({r1.series, r2.series}, {"a", "b"}, kBaseModel, opt);
	std::string moved;
	for (const auto& rj : rep.rejected)
		if (rj.reason.find("alias group") != std::string::npos) moved = rj.id;
	ASSERT_FALSE(moved.empty()) << rep.verdict();  // the case exercises the held-out alias
	ASSERT_GE(rep.selection.named.size(), 2u) << rep.verdict();
	// the moved effect was named in the first round (the significant, unexplained candidate
	// with the largest BIC gain), its group's owner in a later one
	ASSERT_FALSE(rep.selection.rounds.empty());
	std::string firstNamed;
	double bic = -INFINITY;
	for (const auto& t : rep.selection.rounds.front())
		if (t.significant && t.note.empty() && t.delta_bic > bic)
		{
			bic = t.delta_bic;
			firstNamed = t.id;
		}
	ASSERT_EQ(firstNamed, moved) << rep.verdict();
	ASSERT_NE(rep.selection.named.front().id, moved) << rep.verdict();
	const auto& g = rep.selection.named.front().alias_group;
	EXPECT_NE(std::find(g.begin(), g.end(), moved), g.end()) << rep.verdict();
}

TEST(ForeignTrials, MonotonicCoolingNeverNamesHysteresis)
{
	for (std::uint64_t seed = 1; seed <= 1; ++seed)
	{
		fogtest::LumpedCoilOptions o1, o2;
		o1.profile = o2.profile = "cooling";
		o1.seed = 2 * seed;
		o2.seed = 2 * seed + 1;
		o1.hidden["hysteresis"] = o2.hidden["hysteresis"] = 3.0;  // present, but not identifiable
		const auto rep = analyseDiscrepancy({makeLumpedCoilRun(o1).series, makeLumpedCoilRun(o2).series}, {"a", "b"},
											kBaseModel);
		for (const auto& ne : rep.selection.named)
		{
			EXPECT_NE(ne.id, "hysteresis");
			for (const auto& a : ne.alias_group) EXPECT_NE(a, "hysteresis");
		}
		bool untestable = false;
		for (const auto& c : rep.selection.rounds.front())
			if (c.id == "hysteresis") untestable = c.status == CandidateStatus::Untestable;
		EXPECT_TRUE(untestable);
	}
}

TEST(ForeignTrials, TooLittleInformationEndsInCannotTell)
{
	fogtest::LumpedCoilOptions o1, o2;
	o1.profile = o2.profile = "short";
	o2.seed = 2;
	o1.hidden["radial_gradient"] = o2.hidden["radial_gradient"] = 3.0;
	const auto rep = analyseDiscrepancy({makeLumpedCoilRun(o1).series, makeLumpedCoilRun(o2).series}, {"a", "b"},
										kBaseModel);
	EXPECT_TRUE(rep.selection.named.empty());
	EXPECT_NE(rep.verdict().find("cannot tell"), std::string::npos) << rep.verdict();
	EXPECT_NE(rep.cannot_tell.find("min of usable data"), std::string::npos) << rep.cannot_tell;
}

TEST(ForeignTrials, RateEstimatorGapIsReportedApart)
{
	// a hidden radial gradient on the lumped coil is mostly -150 s x the inner node's rate, so
	// the model's rate term carries a large coefficient; at 5 s sampling the compensator's
	// causal order-2 rate (12 samples per 60 s window) is noisy and that term leaves a large
	// residual, which the centred rate does not: reported as the rate estimator's gap, apart
	// from the named effects (tuning seeds 2/3: causal 0.221, centred 0.035 deg/h)
	const auto [r1, r2] = fogtest::makeLumpedCoilRunPair("radial_gradient", 3.0, 2, 5.0);
	const auto rep = analyseDiscrepancy({r1.series, r2.series}, {"a", "b"}, kBaseModel, trialOptions());
	const auto& g = rep.rate_estimator_gap;
	ASSERT_TRUE(g.tested);
	EXPECT_EQ(g.run_label, "b");
	EXPECT_TRUE(g.material);
	EXPECT_GT(g.rms_causal_dph, 3.0 * g.rms_centred_dph);
	EXPECT_NEAR(g.ratio, std::sqrt(g.rms_causal_dph * g.rms_causal_dph / (g.rms_centred_dph * g.rms_centred_dph) - 1), 1e-9);
}
