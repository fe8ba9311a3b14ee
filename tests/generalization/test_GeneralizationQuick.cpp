/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "DeviceEnsemble.h"
#include "GeneralizationBench.h"
#include "SectorCoilGenerator.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

using namespace fogtest;

TEST(SectorCoilGenerator, NoiseOnlyRunHasTheNoiseOfItsArw)
{
	SectorCoilParams p = drawSectorCoil(3);
	p.rate_hz = 2.0;
	const auto prof = mrpt_fog::sim::ChamberProfile::preset("warmup");
	const auto s = simulateSectorCoil(p, prof, 5, true);
	ASSERT_GT(s.size(), 1000u);
	// White part: sigma = 60 N sqrt(fs) deg/h (PHYSICS.md); first differences remove the slow part.
	double sum2 = 0;
	for (std::size_t k = 1; k < s.size(); k++)
	{
		const double d = s.rate_dph[2][k] - s.rate_dph[2][k - 1];
		sum2 += d * d;
	}
	const double sigma = std::sqrt(sum2 / static_cast<double>(s.size() - 1) / 2.0);
	EXPECT_NEAR(sigma, 60.0 * p.arw_deg_rt_h * std::sqrt(2.0), 0.05 * 60.0 * p.arw_deg_rt_h * std::sqrt(2.0));
}

namespace
{
/** The quick subset (fixed before any result was seen): fog-sim devices 1..4 of the tuning
 * seeds and sector-coil device 1, sample rate capped at 2 Hz; presets: the default, the fixed
 * multipoint@3/1 and @1/1 (selection none), and the default with clamping. */
struct QuickBench
{
	std::vector<BenchPreset> presets;
	std::vector<CaseResult> results;
	std::vector<PresetSummary> summary;
	QuickBench()
	{
		for (const auto& p : benchPresets())
			if (p.label == "default (multipoint)" || p.label == "multipoint@3/1 none" || p.label == "multipoint@1/1 none")
				presets.push_back(p);
		BenchPreset clamp = presets.front();
		clamp.label = "default, clamp";
		clamp.options.extrapolation = mrpt_fog::ExtrapolationPolicy::Clamp;
		presets.push_back(clamp);
		const auto profiles = evaluationProfiles();
		std::vector<BenchCase> cases;
		for (std::uint64_t s = 1; s <= 4; s++) cases.push_back({Generator::FogSim, s, 2.0});
		cases.push_back({Generator::SectorCoil, 1, 2.0});
		for (const auto& c : cases)
		{
			const auto r = runBenchCase(c, presets, profiles);
			results.insert(results.end(), r.begin(), r.end());
		}
		summary = summarise(results, presets);
		for (const auto& s : summary)
			std::printf("  %-22s median %.2f p90 %.2f (held-out stability / noise floor, %zu cases), out of range "
						"raw/comp %.2f\n",
						s.preset.c_str(), s.median_ratio, s.p90_ratio, s.cases, s.oor_median_raw_over_comp);
	}
	const PresetSummary& of(const std::string& label) const
	{
		for (const auto& s : summary)
			if (s.preset == label) return s;
		throw std::out_of_range(label);
	}
};
const QuickBench& quick()
{
	static const QuickBench q;
	return q;
}
}  // namespace

// One test (gtest runs each test in its own process here: the subset is simulated once).
TEST(GeneralizationBench, QuickSubsetMeetsTheIssueTargetsItCan)
{
	for (const auto& r : quick().results)
	{
		EXPECT_TRUE(r.ok) << toString(r.generator) << " " << r.seed << " " << r.profile << " " << r.preset << ": " << r.error;
		// the floor is a floor: no model beats the noise of its own device by more than chance
		if (r.ok) EXPECT_GT(r.ratio, 0.7) << r.seed << " " << r.profile << " " << r.preset;
	}
	// Target: in median the default is never more than 10 % worse than the best fixed preset.
	const double best_fixed =
		std::min(quick().of("multipoint@3/1 none").median_ratio, quick().of("multipoint@1/1 none").median_ratio);
	EXPECT_LE(quick().of("default (multipoint)").median_ratio, 1.10 * best_fixed);
	// Outside the calibrated range (-55..75 C after -40..60 C): the default extrapolation is at
	// least 3x better than raw ( target) and better than clamping.
	EXPECT_GE(quick().of("default (multipoint)").oor_median_raw_over_comp, 3.0);
	EXPECT_GT(quick().of("default (multipoint)").oor_median_raw_over_comp,
			  quick().of("default, clamp").oor_median_raw_over_comp);
}

TEST(GeneralizationBench, SecondCalibrationRunKeepsTheEvaluationRuns)
{
	// fog-sim device 1 at 0.5 Hz, the fixed multipoint@3/1, and the same preset fitted on the
	// seed run alone in the same case (seed_run_only): the second calibration run and the turn-on
	// run are simulated with their own noise seeds, so the evaluation runs, and the seed-run fit's
	// ratios, are those of the plain case exactly.
	BenchPreset fixed;
	for (const auto& p : benchPresets())
		if (p.label == "multipoint@3/1 none") fixed = p;
	ASSERT_EQ(fixed.label, "multipoint@3/1 none");
	BenchPreset alone = fixed;
	alone.label += " 1run";
	alone.seed_run_only = true;
	const auto profiles = evaluationProfiles();
	BenchCase plain{Generator::FogSim, 1, 0.5};
	BenchCase two = plain;
	two.second_calibration = "cal_sine";
	two.warmup_calibration = true;
	const auto r0 = runBenchCase(plain, {fixed}, profiles);
	const auto r2 = runBenchCase(two, {fixed, alone}, profiles);
	ASSERT_EQ(r0.size(), profiles.size());
	ASSERT_EQ(r2.size(), 2 * profiles.size());  // cal_sine is no evaluation profile: all evaluated
	bool any_differs = false;
	for (std::size_t i = 0; i < profiles.size(); i++)
	{
		ASSERT_TRUE(r0[i].ok && r2[i].ok && r2[profiles.size() + i].ok) << profiles[i].name;
		EXPECT_EQ(r2[profiles.size() + i].profile, r0[i].profile);
		EXPECT_EQ(r2[profiles.size() + i].ratio, r0[i].ratio) << profiles[i].name;
		any_differs |= r2[i].ratio != r0[i].ratio;
	}
	EXPECT_TRUE(any_differs);  // the two-run fit is another model
	// an evaluation profile named as the second run joins the calibration and is not evaluated
	BenchCase legacy = plain;
	legacy.second_calibration = "sine_soaks";
	const auto r1 = runBenchCase(legacy, {fixed}, profiles);
	ASSERT_EQ(r1.size(), profiles.size() - 1);
	for (const auto& r : r1) EXPECT_NE(r.profile, "sine_soaks");
	EXPECT_THROW(runBenchCase(BenchCase{Generator::FogSim, 1, 0.5, mrpt_fog::sim::defaultEffects(), false, "no_such"}, {fixed}, profiles),
				 std::invalid_argument);
}

TEST(GeneralizationBench, OneCalibrationRunFitsTheWarmupWhenTheTurnOnStaysOut)
{
	// fog-sim devices 1..4 at 2 Hz calibrated on fog-sim's `calibration` profile alone (a turn-on,
	// the seed ramps, a sine, fast ramps), the default preset: with the first hour after the
	// turn-on out of the bias fit (kSuggestedTurnOnExclusion_s) the same run fits the warm-up term
	// and the held-out cold start is near the noise floor; with the turn-on in the bias fit (0) it
	// is not. Tuning devices: 1.05 / 3.71 / 1.24 / 1.06 against 2.40 / 3.66 / 5.12 / 1.84
	// (docs/validation/generalization.md, "One calibration run").
	BenchPreset def;
	for (const auto& p : benchPresets())
		if (p.label == "default (multipoint)") def = p;
	ASSERT_EQ(def.label, "default (multipoint)");
	const auto profiles = evaluationProfiles();
	std::vector<double> with, without;
	int with_term = 0;
	for (std::uint64_t s = 1; s <= 4; s++)
	{
		BenchCase c{Generator::FogSim, s, 2.0};
		c.calibration_profile = "cal_single";
		for (double excl : {kBenchTurnOnExclusion_s, 0.0})
		{
			c.turn_on_exclusion_s = excl;
			for (const auto& r : runBenchCase(c, {def}, profiles))
			{
				ASSERT_TRUE(r.ok) << s << " " << r.profile << ": " << r.error;
				if (excl > 0 && r.profile == "cold_start")
				{
					// a term, or the reason there is none (device 2: one 1/16 C thermistor, amplitude under 3 SE)
					const bool none = r.model_terms.find("no warm-up term") != std::string::npos;
					if (none) EXPECT_NE(r.model_terms.find("no turn-on transient resolved"), std::string::npos) << r.model_terms;
					with_term += !none;
				}
				if (r.profile == "cold_start") (excl > 0 ? with : without).push_back(r.ratio);
			}
		}
	}
	ASSERT_EQ(with.size(), 4u);
	ASSERT_EQ(without.size(), 4u);
	EXPECT_GE(with_term, 3);
	std::sort(with.begin(), with.end());
	std::sort(without.begin(), without.end());
	const double med_with = 0.5 * (with[1] + with[2]), med_without = 0.5 * (without[1] + without[2]);
	std::printf("cold start, median of devices 1..4: %.2f with the turn-on out of the bias fit, %.2f with it in\n",
				med_with, med_without);
	EXPECT_LE(med_with, 1.3);
	EXPECT_LT(med_with, 0.75 * med_without);
}
