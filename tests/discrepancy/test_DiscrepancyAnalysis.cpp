/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/report/DiscrepancyOutput.h>
#include <mrpt_fog/discrepancy/EffectSelector.h>
#include <mrpt_fog/discrepancy/RunGapFigures.h>
#include "support/SyntheticChamberRun.h"

#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
std::vector<FogSeries> twoRuns(const std::map<std::string, double>& hidden)
{
	return {makeSyntheticChamberRun(20, 41, hidden).series, makeSyntheticChamberRun(20, 42, hidden).series};
}
}  // namespace

TEST(DiscrepancyAnalysis, ReportsNamedEffectGapAndSegments)
{
	const auto runs = twoRuns({{"hysteresis", 3.0}});
	const auto rep = analyseDiscrepancy(runs, {"A", "B"}, "static:3");
	ASSERT_FALSE(rep.selection.named.empty());
	EXPECT_EQ(rep.selection.named.front().id, "hysteresis");
	EXPECT_TRUE(rep.has_confirm);
	EXPECT_LT(rep.gap.after.rms_dph, rep.gap.before.rms_dph);
	EXPECT_LT(rep.gap_confirm.after.rms_dph, rep.gap_confirm.before.rms_dph);
	EXPECT_LT(rep.gap.after.stability_dph, rep.gap.before.stability_dph);
	EXPECT_FALSE(rep.gap.segments.empty());
	// per-segment figures: the top segment's RMS agrees with the ranking, and long segments
	// have a 100 s stability
	const auto& top = rep.gap.segments.front();
	EXPECT_NEAR(top.before.rms_dph, top.segment.rms_dph, 1e-12);
	bool anyStability = false;
	for (const auto& sg : rep.gap.segments) anyStability = anyStability || std::isfinite(sg.before.stability_dph);
	EXPECT_TRUE(anyStability);
	EXPECT_NE(rep.verdict().find("hysteresis"), std::string::npos);

	const std::string json = discrepancyJson(rep).dump();
	for (const char* key : {"\"named_effects\"", "\"alias_group\"", "\"confidence\"", "\"coefficient\"", "\"ci\"",
							"\"segments\"", "\"gap\"", "\"before\"", "\"after\"", "\"rms_dph\"", "\"gap_confirm\"",
							"\"stability_dph\"", "\"range_dph\"", "\"where\"",
							"\"stability_before_dph\""})
		EXPECT_NE(json.find(key), std::string::npos) << key;
	const std::string text = discrepancyText(rep);
	EXPECT_NE(text.find("Verdict: missing: hysteresis"), std::string::npos) << text;
	EXPECT_NE(text.find("confirmation run: confirmed"), std::string::npos) << text;

	const auto png = (std::filesystem::temp_directory_path() / "fog_discrepancy_test.png").string();
	std::remove(png.c_str());
	saveGapPlot(rep.gap, png, "test");
	EXPECT_TRUE(std::filesystem::exists(png));
	EXPECT_GT(std::filesystem::file_size(png), 1000u);
	std::remove(png.c_str());
}

TEST(DiscrepancyAnalysis, NoMissingEffectFound)
{
	const auto runs = twoRuns({});
	const auto rep = analyseDiscrepancy({runs[0]}, {"A"}, "static:3");
	EXPECT_EQ(rep.verdict(), "no missing effect found");
	EXPECT_FALSE(rep.has_confirm);
	const std::string json = discrepancyJson(rep).dump();
	EXPECT_NE(json.find("\"named_effects\": []"), std::string::npos) << json.substr(0, 400);
	EXPECT_EQ(json.find("\"gap_confirm\""), std::string::npos);
}

TEST(DiscrepancyAnalysis, BadInputThrows)
{
	const auto runs = twoRuns({});
	EXPECT_THROW(analyseDiscrepancy({}, {}, "static:3"), std::invalid_argument);
	EXPECT_THROW(analyseDiscrepancy({runs[0], runs[1], runs[0]}, {}, "static:3"), std::invalid_argument);
	auto other = runs[1];
	other.thermistors[0].name = "X1";
	EXPECT_THROW(analyseDiscrepancy({runs[0], other}, {}, "static:3"), std::invalid_argument);
	EXPECT_THROW(analyseDiscrepancy({runs[0]}, {}, "nope"), std::invalid_argument);
}

TEST(DiscrepancyAnalysis, GapFiguresClosedForm)
{
	// residual +-0.1 alternating every 100 s over 1000 s: RMS 0.1, 100 s averages +-0.1
	std::vector<double> t;
	Eigen::VectorXd r(1000);
	std::vector<unsigned char> rows(1000, 1);
	for (int k = 0; k < 1000; ++k)
	{
		t.push_back(k);
		r(k) = ((k / 100) % 2 ? -0.1 : 0.1);
	}
	const auto g = gapFigures(t, r, rows, 100.0);
	EXPECT_NEAR(g.rms_dph, 0.1, 1e-12);
	EXPECT_NEAR(g.range_dph, 0.2, 1e-12);
	EXPECT_NEAR(g.stability_dph, 0.1 * std::sqrt(10.0 / 9.0), 1e-9);  // N-1 std of 10 values +-0.1
}

// A run reduced to block means (io/BlockMeanReader.h) steps by fractions of the thermistors'
// quantum: the quantum of the raw readings, when given, is what the coarse-quantisation rule
// judges.
TEST(DiscrepancyAnalysis, RawQuantumGivenIsWhatTheQuantisationRuleJudges)
{
	const auto runs = twoRuns({{"hysteresis", 3.0}});
	DiscrepancyOptions opt;
	const auto plain = analyseDiscrepancy({runs[0]}, {"A"}, "static:3", opt);
	EXPECT_EQ(plain.cannot_tell.find("quantised"), std::string::npos) << plain.cannot_tell;
	opt.thermistor_quantum_C = 5.0;  // a span of tens of degrees in fewer than 30 levels
	const auto coarse = analyseDiscrepancy({runs[0]}, {"A"}, "static:3", opt);
	EXPECT_NE(coarse.cannot_tell.find("quantised to about 5 C"), std::string::npos) << coarse.cannot_tell;
	EXPECT_NE(coarse.verdict().find("cannot tell"), std::string::npos);
}

namespace
{
/** The first `rows` rows of a run. */
FogSeries firstRows(const FogSeries& run, std::size_t rows)
{
	FogSeries out = run;
	out.resize(0);
	for (std::size_t k = 0; k < rows && k < run.size(); ++k) out.appendSampleFrom(run, k);
	return out;
}
}  // namespace

// A confirmation run too short to show an effect (its expected chi-square at the coefficient
// named is below what a confirmation needs) says "cannot tell" for that effect instead of
// vetoing it, and its stability is "n/a", not nan.
TEST(DiscrepancyAnalysis, ConfirmationRunThatCannotShowTheEffectSaysCannotTell)
{
	const auto runs = twoRuns({{"hysteresis", 3.0}});
	const FogSeries shortRun = firstRows(makeSyntheticChamberRun(4, 42, {{"hysteresis", 3.0}}).series, 30);  // 2 min
	const auto rep = analyseDiscrepancy({runs[0], shortRun}, {"A", "first_2_min"}, "static:3");
	ASSERT_FALSE(rep.selection.named.empty()) << rep.verdict();
	EXPECT_EQ(rep.selection.named.front().id, "hysteresis");
	EXPECT_FALSE(rep.selection.named.front().confirm_tested);
	EXPECT_FALSE(rep.selection.named.front().confirm_cannot_tell.empty());
	EXPECT_TRUE(rep.selection.not_confirmed.empty());
	const std::string text = discrepancyText(rep);
	EXPECT_NE(text.find("confirmation run: cannot tell"), std::string::npos) << text;
	EXPECT_EQ(text.find("nan"), std::string::npos) << text;
	EXPECT_NE(text.find("stability and range n/a"), std::string::npos) << text;
	EXPECT_NE(discrepancyJson(rep).dump().find("\"confirm_cannot_tell\""), std::string::npos);
}

// The same samples given as both runs is no confirmation: refused, naming the second run.
TEST(DiscrepancyAnalysis, SameRunGivenTwiceIsRefused)
{
	const auto runs = twoRuns({});
	try
	{
		analyseDiscrepancy({runs[0], runs[0]}, {"A.csv", "A_again.csv"}, "static:3");
		FAIL() << "accepted the same run twice";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_EQ(std::string(e.what()).rfind("A_again.csv: ", 0), 0u) << e.what();
		EXPECT_NE(std::string(e.what()).find("same samples"), std::string::npos) << e.what();
	}
}

// An error about the confirmation run names the confirmation run, not the analysed one.
TEST(DiscrepancyAnalysis, ErrorNamesTheRunItIsAbout)
{
	const auto runs = twoRuns({});
	try
	{
		analyseDiscrepancy({runs[0], firstRows(runs[1], 5)}, {"chamber_B.csv", "five_rows.csv"}, "static:3");
		FAIL() << "accepted a 5-row confirmation run";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_EQ(std::string(e.what()).rfind("five_rows.csv: ", 0), 0u) << e.what();
		EXPECT_EQ(std::string(e.what()).find("chamber_B"), std::string::npos) << e.what();
	}
}
