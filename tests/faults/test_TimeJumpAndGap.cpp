/* mrpt_fog: fault injection: a gap in the log and a jump of the time stamps. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>

#include <iostream>
#include <regex>

#include "FaultRun.h"

using namespace mrpt_fog;

namespace
{
/** The validation run without the samples in [t0, t1). */
FogSeries withGap(double t0, double t1)
{
	const FogSeries& r = faulttest::validationRun();
	FogSeries out = faulttest::head(r, 0);
	for (std::size_t k = 0; k < r.size(); k++)
		if (r.time_s[k] < t0 || r.time_s[k] >= t1) out.appendSampleFrom(r, k);
	return out;
}
}  // namespace

// Bound: a 10 min gap in the log is compensated without error: the rate windows restart (the
// rate-free start-up model right after the gap, flag RateFree), every output is finite, and the 100 s stability of what is
// left stays within 1.5x the gap-free run. Written and read back through CSV and rawlog, the gap
// survives unchanged.
TEST(TimeJumpAndGap, GapIsCompensatedAndRoundTrips)
{
	const Calibration& cal = faulttest::calibration();
	const double s_clean = faulttest::stability100_dph(compensate(cal, faulttest::validationRun()));
	const FogSeries g = withGap(4000.0, 4600.0);
	ASSERT_NO_THROW(g.validate());
	const CompensatedSeries c = compensate(cal, g);
	const std::size_t k_after = faulttest::sampleAt(g, 4600.0);
	// after the gap: no rate yet, then a window shorter than half: the rate-free start-up model
	// (flag RateFree), neither the mean bias nor the main model with a rate from a few samples
	ASSERT_TRUE(cal.startup.has_value());
	const std::uint8_t old_flags = CompensationFlag::NoModel | CompensationFlag::RateWarmup | CompensationFlag::Fallback;
	for (std::size_t k : {k_after, k_after + 1})
	{
		EXPECT_TRUE(c.flags[k] & CompensationFlag::RateFree) << k;
		EXPECT_FALSE(c.flags[k] & old_flags) << k;
	}
	EXPECT_FALSE(c.flags[k_after - 1] & (old_flags | CompensationFlag::RateFree));
	// a calibration without the start-up model (a file written before it): as before, no rate
	// yet (mean bias, NoModel), then RateWarmup for a while
	Calibration old = cal;
	old.startup.reset();
	const CompensatedSeries c_old = compensate(old, g);
	EXPECT_TRUE(c_old.flags[k_after] & CompensationFlag::NoModel);
	EXPECT_TRUE(c_old.flags[k_after + 1] & CompensationFlag::RateWarmup);
	EXPECT_FALSE(c_old.flags[k_after - 1] & (CompensationFlag::RateWarmup | CompensationFlag::NoModel));
	for (double v : c.compensated_dph) ASSERT_TRUE(std::isfinite(v));
	const double s = faulttest::stability100_dph(c);
	std::cout << "10 min gap: stability " << s << " deg/h (" << s / s_clean << " x the gap-free " << s_clean << ")\n";
	EXPECT_LE(s, 1.5 * s_clean);

	faulttest::ScratchDir dir;
	for (const char* name : {"gap.csv", "gap.rawlog"})
	{
		writeFogLog(dir.path(name), g);
		const FogSeries back = readFogLog(dir.path(name));
		ASSERT_EQ(back.size(), g.size()) << name;
		for (std::size_t k = 0; k < g.size(); k++) ASSERT_NEAR(back.time_s[k], g.time_s[k], 1e-6) << name << " " << k;
	}
}

// A forward clock jump (+1 h from the middle on) is a gap to the compensator: no error, finite
// output, the rates restart after the jump (the rate-free start-up model meanwhile), and the
// output before the jump is the untouched one.
TEST(TimeJumpAndGap, ForwardJumpIsAGap)
{
	const Calibration& cal = faulttest::calibration();
	const FogSeries& r = faulttest::validationRun();
	FogSeries j = r;
	const std::size_t k_jump = r.size() / 2;
	for (std::size_t k = k_jump; k < j.size(); k++) j.time_s[k] += 3600.0;
	const CompensatedSeries c = compensate(cal, j), c0 = compensate(cal, r);
	EXPECT_TRUE(c.flags[k_jump] & CompensationFlag::RateFree);  // the rate-free start-up model
	EXPECT_TRUE(c.flags[k_jump + 1] & CompensationFlag::RateFree);
	for (std::size_t k = 0; k < k_jump; k++) ASSERT_EQ(c.compensated_dph[k], c0.compensated_dph[k]);
	for (double v : c.compensated_dph) ASSERT_TRUE(std::isfinite(v));
}

// A backward clock jump is refused everywhere with the sample named: FogSeries::validate,
// the compensator, the writers, and the CSV reader (file and line).
TEST(TimeJumpAndGap, BackwardJumpIsRefused)
{
	const Calibration& cal = faulttest::calibration();
	FogSeries j = faulttest::head(faulttest::validationRun(), 200);
	for (std::size_t k = 100; k < j.size(); k++) j.time_s[k] -= 50.0;
	const std::string v = faulttest::errorOf<std::invalid_argument>([&] { j.validate(); });
	EXPECT_NE(v.find("100"), std::string::npos) << v;
	EXPECT_THROW(compensate(cal, j), std::invalid_argument);
	faulttest::ScratchDir dir;
	EXPECT_THROW(writeFogCsv(dir.path("j.csv"), j), FogIoError);
	EXPECT_FALSE(std::filesystem::exists(dir.path("j.csv")));
	EXPECT_THROW(writeFogRawlog(dir.path("j.rawlog"), j), FogIoError);
	EXPECT_FALSE(std::filesystem::exists(dir.path("j.rawlog")));

	// the same jump in a CSV file: the reader names the file and the line
	const FogSeries ok = faulttest::head(faulttest::validationRun(), 200);
	writeFogCsv(dir.path("ok.csv"), ok);
	std::string text = faulttest::readBytes(dir.path("ok.csv"));
	// data line of sample 100: time 100 -> 40
	const std::string needle = "\n100,";
	const auto pos = text.find(needle);
	ASSERT_NE(pos, std::string::npos);
	text.replace(pos, needle.size(), "\n40,");
	faulttest::writeBytes(dir.path("back.csv"), text);
	const std::string e = faulttest::errorOf<FogIoError>([&] { readFogCsv(dir.path("back.csv")); });
	EXPECT_NE(e.find("back.csv"), std::string::npos) << e;
	EXPECT_NE(e.find("goes backwards"), std::string::npos) << e;
	EXPECT_TRUE(std::regex_search(e, std::regex("back\\.csv:[0-9]+:"))) << e;  // file:line:
}
