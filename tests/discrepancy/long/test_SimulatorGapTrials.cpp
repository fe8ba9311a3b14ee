/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** Long proof of `fog-discrepancy --sim` (label long): every effect the simulator can hide from
 * the configuration, at effect-to-noise ratios 1 and 3, FOG_SIMGAP_LONG_SEEDS seeds per cell
 * (default 10, seeds 1000..), and 100 null trials (seeds 5000..). Targets: the right
 * effect (or its alias group) named in >= 95 % of trials, the gap target met in >= 95 %, false
 * naming with nothing hidden <= 2 %. Setup and scoring: ../SimulatorGapTrialSuite.h.
 * Regenerate the table: build-disc/tests/test_discrepancy_long --gtest_filter='SimulatorGapTrials*' | grep SIMGAP */
#include <gtest/gtest.h>

#include "../SimulatorGapTrialSuite.h"

#include <cstdlib>

using namespace simgap_trials;

namespace
{
int seedsPerCell()
{
	const char* e = std::getenv("FOG_SIMGAP_LONG_SEEDS");
	return e ? std::max(1, std::atoi(e)) : 10;
}

void cell(const std::string& id)
{
	const int n = seedsPerCell();
	const int need = static_cast<int>(std::ceil(0.95 * n));
	for (double ratio : {1.0, 3.0})
	{
		const Tally t = runSeeds(id, ratio, n, 1000);
		print(id, ratio, t);
		EXPECT_GE(t.named, need) << id << " at ratio " << ratio;
		EXPECT_GE(t.gap_ok, need) << id << " at ratio " << ratio;
	}
}
}  // namespace

TEST(SimulatorGapTrials, HeatSource) { cell("heat_source"); }
TEST(SimulatorGapTrials, ShupeRate) { cell("shupe_rate"); }
TEST(SimulatorGapTrials, RadialGradient) { cell("radial_gradient"); }
TEST(SimulatorGapTrials, GradientRate) { cell("gradient_rate"); }
TEST(SimulatorGapTrials, Hysteresis) { cell("hysteresis"); }
TEST(SimulatorGapTrials, Warmup) { cell("warmup"); }
TEST(SimulatorGapTrials, ScaleFactorTemp) { cell("scale_factor_temp"); }
TEST(SimulatorGapTrials, Magnetic) { cell("magnetic"); }
TEST(SimulatorGapTrials, TempPolyOrder) { cell("temp_poly_order"); }

TEST(SimulatorGapTrials, NullHundredTrials)
{
	const Tally t = runSeeds("", 0, 100, 5000);
	print("", 0, t);
	EXPECT_LE(t.false_naming, 2) << "target: false naming <= 2 % with nothing hidden";
}
