/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// Target: two calibrations that differ only in the noise seed choose the same model, or
// the calibration says it is unstable and lists the alternatives with their held-out figures.
// The default device on the seed profile at 2 Hz, noise seeds 101..106 (pairs 101/102, 103/104,
// 105/106). With "stable" at 60 % of refits, pair 101/102 failed (two different models, each
// "stable" at 70 % / 60 %); the threshold is now 90 % (a toss-up reaches it with p = 1.1 %, see
// FitOptions::stable_share), and pair 105/106 was added after that change.
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <cstdio>

using namespace mrpt_fog;

namespace
{
std::string termsOf(const Calibration& c)
{
	std::string s;
	for (const auto& n : c.model.features.termNames())
		if (n != "1") s += (s.empty() ? "" : " + ") + n;
	return s;
}
Calibration fitSeed(std::uint64_t seed)
{
	sim::SimSettings st;
	st.rate_hz = 2.0;
	st.seed = seed;
	const FogSeries A = sim::simulateChamber(sim::ChamberProfile::preset("seed"), sim::FogDevice::defaultDevice(), st);
	return fitCalibration({A}, "multipoint");
}
}  // namespace

TEST(SelectionStability, NoiseSeedsChooseTheSameModelOrSayUnstable)
{
	for (std::uint64_t s : {101u, 103u, 105u})
	{
		const Calibration a = fitSeed(s), b = fitSeed(s + 1);
		const std::string ta = termsOf(a), tb = termsOf(b);
		std::printf("  seed %llu: %s (chosen in %.0f %% of refits%s)\n  seed %llu: %s (%.0f %%%s)\n",
					static_cast<unsigned long long>(s), ta.c_str(), 100 * a.selection_stability.chosen_share,
					a.selection_stability.stable ? "" : ", unstable", static_cast<unsigned long long>(s + 1), tb.c_str(),
					100 * b.selection_stability.chosen_share, b.selection_stability.stable ? "" : ", unstable");
		ASSERT_GT(a.selection_stability.resamples, 0u);
		if (ta == tb) continue;
		// different choices: each calibration must call itself unstable, with alternatives that carry
		// their held-out figures
		for (const Calibration* c : {&a, &b})
		{
			EXPECT_FALSE(c->selection_stability.stable) << termsOf(*c);
			EXPECT_FALSE(c->selection_stability.alternatives.empty());
			for (const auto& alt : c->selection_stability.alternatives) EXPECT_GT(alt.held_out_rms_dph, 0.0);
		}
	}
}
