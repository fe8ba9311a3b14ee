/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/report/SimDiscrepancyOutput.h>

#include "LumpedCoilGenerator.h"
#include "SimulatorGapTrialSuite.h"
#include "TrialSubset.h"
#include <mrpt_fog/sim/ChamberRun.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
/** Effects of the "true" gyro in the trials (fog-sim's library, default device). */
const sim::EffectSet kTruth = {"shupe_rate", "radial_gradient", "heat_source", "magnetic",
							   "scale_factor_temp", "warmup", "earth_rate", "thermistor_lag"};

/** Runs A (seed 2s+1) and B (2s+2) of the rich profile at 0.05 Hz with every kTruth effect on. */
std::vector<FogSeries> truthRuns(std::uint64_t seed)
{
	sim::SimSettings st;
	st.rate_hz = 0.05;
	st.effects = kTruth;
	st.profile_source = "rich";
	const auto profile = sim::ChamberProfile::preset("rich");
	const auto dev = sim::FogDevice::defaultDevice();
	st.seed = 2 * seed + 1;
	auto a = sim::simulateChamber(profile, dev, st);
	st.seed = 2 * seed + 2;
	auto b = sim::simulateChamber(profile, dev, st);
	return {a, b};
}

/** The configuration under test: the truth minus `hidden`, with wrong starting values of the
 * free parameters (calibration has to find them): elasto-optic 0.7 x the truth (the default
 * device's), winding asymmetry 0.75 x the truth, magnetic 1e-4 (2e-4), SF 10 ppm/C (20), warm-up 0.05 deg/h (0.1),
 * electronics 2.0 W (2.5), every heat capacity x 1.1, thermistor offsets 0 (+-0.03..0.08). */
SimulatorConfig configWithout(const std::string& hidden)
{
	SimulatorConfig c;
	c.source = "trial config (truth minus " + (hidden.empty() ? std::string("nothing") : hidden) + ")";
	c.effects = kTruth;
	if (!hidden.empty()) c.effects.erase(hidden);
	auto& d = c.device;
	const sim::FogDevice truth = sim::FogDevice::defaultDevice();
	d.errors.radial_gradient_dph_per_C() = 0.7 * truth.errors.radial_gradient_dph_per_C();
	d.winding.midpoint_offset_m = 0.75 * truth.winding.midpoint_offset_m;
	d.errors.magnetic_dph_per_uT() = 1e-4;
	d.errors.sf_ppm_per_C() = 10;
	d.errors.warmup_dph() = 0.05;
	d.thermal.electronics_power_W = 2.0;
	d.thermal.scaleHeatCapacities(1.1);
	for (auto& t : d.thermistors) t.offset_C = 0;
	c.free = defaultFreeParameters(c.effects);
	return c;
}

int seedsPerCell()
{
	const char* e = std::getenv("FOG_SIMGAP_SEEDS");
	return e ? std::max(1, std::atoi(e)) : 1;
}

struct Cell
{
	int trials = 0, named = 0, gap_ok = 0;
	std::string seeds;
};

void runCell(const std::string& hidden, Cell& cell)
{
	for (int s = 1; s <= seedsPerCell(); ++s)
	{
		const auto runs = truthRuns(static_cast<std::uint64_t>(s));
		const auto rep = analyseSimulatorDiscrepancy(runs, {"A", "B"}, configWithout(hidden));
		const auto& named = rep.report.selection.named;
		const auto& r = rep.report;
		bool ok = false, gap = false;
		if (hidden.empty())
		{
			ok = named.empty();
			gap = std::abs(r.gap_confirm.after.rms_dph - r.gap_confirm.before.rms_dph) < 1e-12;
		}
		else
		{
			ok = !named.empty() && named.front().id == hidden;
			if (hidden == "heat_source")
				gap = rep.temp_gap_confirm.rms_after_C < 0.5 * rep.temp_gap_confirm.rms_before_C;
			else
				gap = r.gap_confirm.after.rms_dph < r.gap_confirm.before.rms_dph;
		}
		++cell.trials;
		cell.named += ok;
		cell.gap_ok += gap;
		cell.seeds += (cell.seeds.empty() ? "" : ",") + std::to_string(s);
		std::string ids;
		for (const auto& n : named) ids += (ids.empty() ? "" : " ") + n.id;
		std::printf("  [%s seed %d] named {%s}; bias RMS B %.4g -> %.4g deg/h; temp RMS B %.4g -> %.4g C; %s\n",
					hidden.empty() ? "none" : hidden.c_str(), s, ids.c_str(), r.gap_confirm.before.rms_dph,
					r.gap_confirm.after.rms_dph, rep.temp_gap_confirm.rms_before_C, rep.temp_gap_confirm.rms_after_C,
					rep.heat.sentence.c_str());
		EXPECT_TRUE(ok) << hidden << " seed " << s << ": named " << ids;
		EXPECT_TRUE(gap) << hidden << " seed " << s;
		if (hidden == "heat_source" && !named.empty())
		{
			EXPECT_EQ(rep.heat.nearest.back(), '2') << "the electronics sit at 180 deg (Ti2/To2): " << rep.heat.nearest;
			EXPECT_TRUE(named.front().confirmed);
		}
	}
}

std::map<std::string, Cell>& table()
{
	static std::map<std::string, Cell> t;
	return t;
}
}  // namespace

TEST(SimulatorGap, CalibrationRecoversStartingValueErrors)
{
	const auto runs = truthRuns(1);
	const auto cfg = configWithout("");
	const auto drive = chamberDriveForRun(runs[0], cfg);
	EXPECT_NE(drive.how.find("rich"), std::string::npos);
	const auto sig = computeRunSignals(runs[0]);
	const auto cal = calibrateSimulator(simModelFromConfig(cfg), cfg.free, runs[0], drive, sig.bias_dph, sig.usable);
	const auto& d = cal.model.device;
	EXPECT_NEAR(cal.model.thermal_time_scale, 1 / 1.1, 0.01);
	EXPECT_NEAR(d.thermal.electronics_power_W, 2.5, 0.1);
	// truth: the default device's; tolerances 5.7 % and 5 % of it (set when the truth was 0.07 / 2 m)
	const sim::FogDevice truth = sim::FogDevice::defaultDevice();
	EXPECT_NEAR(d.errors.radial_gradient_dph_per_C(), truth.errors.radial_gradient_dph_per_C(),
				0.004 / 0.07 * truth.errors.radial_gradient_dph_per_C());
	EXPECT_NEAR(d.winding.midpoint_offset_m, truth.winding.midpoint_offset_m, 0.05 * truth.winding.midpoint_offset_m);
	EXPECT_NEAR(d.errors.magnetic_dph_per_uT(), 2e-4, 1e-5);
	EXPECT_NEAR(d.errors.sf_ppm_per_C(), 20, 0.1);
	EXPECT_NEAR(d.errors.warmup_dph(), 0.1, 0.03);
	EXPECT_NEAR(d.thermistors[0].offset_C, 0.05, 0.01);
	EXPECT_NEAR(d.thermistors[1].offset_C, -0.08, 0.01);
	// 95 % intervals (block-averaged residual variance): finite, positive, printed with the truth
	ASSERT_EQ(cal.bias_ci95_half.size(), cal.bias_slots.size());
	ASSERT_EQ(cal.temp_ci95_half.size(), cal.temp_slots.size());
	for (std::size_t j = 0; j < cal.temp_slots.size(); ++j)
	{
		EXPECT_GT(cal.temp_ci95_half[j], 0) << cal.temp_slots[j].label();
		std::printf("  CI %-34s %.5g +- %.2g\n", cal.temp_slots[j].label().c_str(), getParam(cal.model, cal.temp_slots[j]),
					cal.temp_ci95_half[j]);
	}
	for (std::size_t j = 0; j < cal.bias_slots.size(); ++j)
	{
		EXPECT_GT(cal.bias_ci95_half[j], 0) << cal.bias_slots[j].label();
		std::printf("  CI %-34s %.5g +- %.2g\n", cal.bias_slots[j].label().c_str(), getParam(cal.model, cal.bias_slots[j]),
					cal.bias_ci95_half[j]);
	}
	// residuals at the noise floor: thermistors 0.003 C white + 0.01 C quantisation
	EXPECT_LT(cal.temp_rms_C, 0.006);
	EXPECT_LT(cal.bias_rms_dph, 0.02);
}

TEST(SimulatorGap, HeatSourceHiddenIsNamedFromTemperatures) { runCell("heat_source", table()["heat_source"]); }
TEST(SimulatorGap, RadialGradientHiddenIsNamed) { runCell("radial_gradient", table()["radial_gradient"]); }
TEST(SimulatorGap, MagneticHiddenIsNamed) { runCell("magnetic", table()["magnetic"]); }
TEST(SimulatorGap, ScaleFactorTempHiddenIsNamed) { runCell("scale_factor_temp", table()["scale_factor_temp"]); }
TEST(SimulatorGap, NothingHiddenGivesNoMissingEffect) { runCell("", table()["(none)"]); }

TEST(SimulatorGap, PrintsSuccessTable)
{
	std::printf("| hidden effect | named / trials | gap shrank on run B | seeds |\n|---|---|---|---|\n");
	for (const auto& [id, c] : table())
		std::printf("| %s | %d/%d | %d/%d | %s |\n", id.c_str(), c.named, c.trials, c.gap_ok, c.trials, c.seeds.c_str());
}

TEST(SimulatorGap, JsonHasContractAndTemperatureKeys)
{
	const auto runs = truthRuns(1);
	const auto rep = analyseSimulatorDiscrepancy({runs[0]}, {"A"}, configWithout("magnetic"));
	const std::string j = simDiscrepancyJson(rep).dump();
	for (const char* key : {"\"named_effects\"", "\"segments\"", "\"gap\"", "\"rms_dph\"", "\"temperature_gap\"",
							"\"rms_C\"", "\"heat_source_test\"", "\"simulator\"", "\"driving_input\"",
							"\"calibrated_after\"", "\"calibrated_after_ci95\"", "\"model_kind\""})
		EXPECT_NE(j.find(key), std::string::npos) << key;
	EXPECT_EQ(j.find("\"gap_confirm\""), std::string::npos);
	EXPECT_NE(simDiscrepancyText(rep).find("missing: magnetic"), std::string::npos);
}

TEST(SimulatorGap, WrongProfileIsAClearError)
{
	auto runs = truthRuns(1);
	auto cfg = configWithout("");
	cfg.profile = "seed";  // wrong profile: the power column disagrees (rich has power cycles)
	EXPECT_THROW(analyseSimulatorDiscrepancy({runs[1]}, {"B"}, cfg), std::invalid_argument);
}

// Target: a run whose chamber program is not given (metadata cleared, no `profile:`):
// the drive comes from the log alone (power, table, field columns; air reconstructed from the
// thermistors) and the hidden effect is still named, with the truth inside its 95 % interval
// (as with the profile given: docs/guide/model-gap-simulator.md). Truth: magnetic 2e-4 deg/h/uT,
// scale factor 20 ppm/C (FogDevice defaults, kTruth). Seed 1 of truthRuns, one run each. The
// interval judged is the recalibrated simulator parameter's (SimulatorCalibration.h); for the
// scale factor the named candidate's own coefficient is a proxy (thermistor mean x table rate,
// the simulator uses the coil mean) and is not the simulator's parameter. Asserted for both:
// the recalibrated simulator parameter's interval holds the truth. For the scale factor this
// needs the reference temperature sf_ref_C free with the slope (SimulatorGap.cpp): with it fixed
// at 25 C the thermistors' common offset (mean -0.01 C, absorbed by the reconstructed air) biased
// the slope to 19.94 +- 0.059 (table segments at T - 25 ~ -2.5 C; closed form -d / (T - 25)
// predicts 19.93; docs/guide/model-gap-simulator.md).
// Nothing else may be named: before the candidates were built on the simulated thermistors with
// the unresolved thermal content taken out (SimulatorGap.cpp), a spurious gradient_rate was
// named on these seeds (the smoothed air's error; docs/guide/model-gap-simulator.md).
namespace
{
void logDriveCell(const std::string& hidden, const std::string& param, double truth)
{
	auto runs = truthRuns(1);
	runs[0].metadata.clear();
	runs[1].metadata.clear();
	const auto rep = analyseSimulatorDiscrepancy(runs, {"A", "B"}, configWithout(hidden));
	EXPECT_NE(rep.drive.find("reconstructed from the thermistors"), std::string::npos) << rep.drive;
	EXPECT_FALSE(rep.thermal.misfit) << rep.thermal.sentence;
	const auto& named = rep.report.selection.named;
	std::string ids;
	for (const auto& n : named) ids += " " + n.id;
	std::printf("  [log drive, hidden %s] %s\n  %s\n  named:%s\n", hidden.c_str(), rep.drive.c_str(),
				rep.thermal.sentence.c_str(), ids.c_str());
	const auto it = std::find_if(named.begin(), named.end(), [&](const NamedEffect& n) { return n.id == hidden; });
	ASSERT_NE(it, named.end()) << "named:" << ids;
	EXPECT_EQ(named.size(), 1u) << "named:" << ids;
	EXPECT_GT(rep.unresolved_share, 0.0);
	if (hidden == "magnetic")
	{
		// the candidate's coefficient is the simulator's (field x coefficient in both)
		EXPECT_LE(it->ci_low, truth) << hidden;
		EXPECT_GE(it->ci_high, truth) << hidden;
	}
	double v = NAN, h = NAN;
	for (const auto& [k, x] : rep.calibrated_after)
		if (k == param) v = x;
	for (const auto& [k, x] : rep.calibrated_after_ci95_half)
		if (k == param) h = x;
	std::printf("  named %s CI [%.4g, %.4g]; recalibrated %s = %.4g +- %.2g (truth %.4g)\n", hidden.c_str(), it->ci_low,
				it->ci_high, param.c_str(), v, h, truth);
	EXPECT_LE(std::abs(v - truth), h) << param << " = " << v << " +- " << h;
}
}  // namespace

TEST(SimulatorGap, MeasuredLogDriveRecoversHiddenMagnetic) { logDriveCell("magnetic", "magnetic_dph_per_uT", 2e-4); }
TEST(SimulatorGap, MeasuredLogDriveRecoversHiddenScaleFactor) { logDriveCell("scale_factor_temp", "sf_ppm_per_C", 20.0); }

// From the log alone with nothing hidden (every truth effect configured, wrong starting values):
// nothing is named. Seeds 3/4 (truthRuns(1)) are the ones on which the spurious gradient_rate was
// diagnosed (chi2 336 with every truth effect on; docs/guide/model-gap-simulator.md), so this is a tuning
// case; held-out seed pairs are in the docs.
TEST(SimulatorGap, MeasuredLogDriveNothingHiddenNamesNothing)
{
	auto runs = truthRuns(1);
	runs[0].metadata.clear();
	runs[1].metadata.clear();
	const auto rep = analyseSimulatorDiscrepancy(runs, {"A", "B"}, configWithout(""));
	EXPECT_NE(rep.drive.find("reconstructed from the thermistors"), std::string::npos) << rep.drive;
	EXPECT_FALSE(rep.thermal.misfit) << rep.thermal.sentence;
	std::string ids;
	for (const auto& n : rep.report.selection.named) ids += " " + n.id;
	std::printf("  [log drive, nothing hidden] unresolved share %.2f; named:%s\n", rep.unresolved_share, ids.c_str());
	EXPECT_TRUE(rep.report.selection.named.empty()) << "named:" << ids;
	const std::string text = simDiscrepancyText(rep);
	EXPECT_NE(text.find("Unresolved thermal content:"), std::string::npos) << text;
	EXPECT_NE(simDiscrepancyJson(rep).dump().find("\"unresolved_share\""), std::string::npos);
}

// Target: a run of ANOTHER simulator (tests/support/LumpedCoilGenerator: 3 lumped
// nodes, a housing thermistor, its own air lag and self-heating) is reported as a thermal misfit,
// with its size, and no bias effect is named on top of it. The configuration declares the
// generator's thermistors (Hs, on the housing there, is placed on the outer coil surface: the
// simulator has no housing thermistor). No profile: the drive is the log's own.
TEST(SimulatorGap, AnotherSimulatorsRunIsAThermalMisfitAndNamesNoBiasEffect)
{
	fogtest::LumpedCoilOptions o;
	o.seed = 3;
	const FogSeries run = fogtest::makeLumpedCoilRun(o).series;
	SimulatorConfig cfg;
	cfg.source = "lumped.yaml";
	cfg.device.latitude_deg = 0;
	cfg.device.thermistors = {{{"Ca", CoilSide::Inner, 30.0}, 5.0, 0.0},
							  {{"Cb", CoilSide::Outer, 210.0}, 5.0, 0.0},
							  {{"Hs", CoilSide::Outer, 0.0}, 5.0, 0.0}};
	cfg.free = defaultFreeParameters(cfg.effects);
	const auto rep = analyseSimulatorDiscrepancy({run}, {"lumped"}, cfg);
	std::printf("  %s\n", rep.thermal.sentence.c_str());
	EXPECT_TRUE(rep.thermal.misfit);
	EXPECT_GT(rep.thermal.rms_C, rep.thermal.threshold_C);
	EXPECT_EQ(rep.thermal.names.size(), 3u);
	EXPECT_FALSE(rep.thermal.worst_thermistor.empty());
	EXPECT_NE(rep.thermal.fix, ThermalFix::None);
	EXPECT_TRUE(rep.report.selection.named.empty());
	const std::string text = simDiscrepancyText(rep);
	EXPECT_NE(text.find("Verdict: thermal model misfit"), std::string::npos) << text;
	EXPECT_NE(text.find("THE THERMAL MODEL IS THE FIRST DISAGREEMENT"), std::string::npos);
	const std::string j = simDiscrepancyJson(rep).dump();
	EXPECT_NE(j.find("\"thermal_fit\""), std::string::npos);
	EXPECT_NE(j.find("\"reconstructed_air\""), std::string::npos);
}

// Effect-to-noise ratio trials (SimulatorGapTrialSuite.h): every effect --sim can name, at
// ratios 1 and 3, one seed each here (10 seeds and 100 null trials: long/test_SimulatorGapTrials.cpp).
// Under the sanitizers (FOG_TRIAL_SEEDS subset, TrialSubset.h) ratio 3 only: the two ratios run
// the same code with the hidden effect scaled; the Release run checks both.
namespace
{
void ratioCell(const std::string& id)
{
	const std::vector<double> ratios = trial_subset::subsetRun() ? std::vector<double>{3.0} : std::vector<double>{1.0, 3.0};
	for (double ratio : ratios)
	{
		const auto t = simgap_trials::runSeeds(id, ratio, 1, 1, true);
		simgap_trials::print(id, ratio, t);
		EXPECT_EQ(t.named, 1) << id << " at ratio " << ratio;
		EXPECT_EQ(t.gap_ok, 1) << id << " at ratio " << ratio;
	}
}

}  // namespace

TEST(SimulatorGapRatioTrials, HeatSource) { ratioCell("heat_source"); }
TEST(SimulatorGapRatioTrials, ShupeRate) { ratioCell("shupe_rate"); }
TEST(SimulatorGapRatioTrials, RadialGradient) { ratioCell("radial_gradient"); }
TEST(SimulatorGapRatioTrials, GradientRate) { ratioCell("gradient_rate"); }
TEST(SimulatorGapRatioTrials, Hysteresis) { ratioCell("hysteresis"); }
TEST(SimulatorGapRatioTrials, Warmup) { ratioCell("warmup"); }
TEST(SimulatorGapRatioTrials, ScaleFactorTemp) { ratioCell("scale_factor_temp"); }
TEST(SimulatorGapRatioTrials, Magnetic) { ratioCell("magnetic"); }
TEST(SimulatorGapRatioTrials, TempPolyOrder) { ratioCell("temp_poly_order"); }

TEST(SimulatorGapRatioTrials, NothingHiddenTwoSeeds)
{
	const auto t = simgap_trials::runSeeds("", 0, 2, 1, true);
	simgap_trials::print("", 0, t);
	EXPECT_EQ(t.false_naming, 0);
}

TEST(SimulatorGapRatioTrials, ClopperPearsonInterval)
{
	// reference values (R: binom.test(2, 100)$conf.int, binom.test(0, 10)$conf.int)
	const auto [lo, hi] = simgap_trials::clopperPearson95(2, 100);
	EXPECT_NEAR(lo, 0.002431337, 1e-6);
	EXPECT_NEAR(hi, 0.070383342, 1e-6);
	const auto [lo0, hi0] = simgap_trials::clopperPearson95(0, 10);
	EXPECT_EQ(lo0, 0.0);
	EXPECT_NEAR(hi0, 0.3084971, 1e-6);
}
