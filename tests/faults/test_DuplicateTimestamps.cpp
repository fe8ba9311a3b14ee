/* mrpt_fog: fault injection: duplicate timestamps in CSV and rawlog files. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>

#include <regex>

#include "FaultRun.h"

using namespace mrpt_fog;

// A CSV data line repeated (a logger writing the same sample twice): the reader refuses the
// file naming it, the line and "duplicates"; nothing half-read is returned.
TEST(DuplicateTimestamps, CsvRepeatedLineIsRefused)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 50);
	writeFogCsv(dir.path("ok.csv"), s);
	std::string text = faulttest::readBytes(dir.path("ok.csv"));
	const auto a = text.find("\n20,");
	ASSERT_NE(a, std::string::npos);
	const auto b = text.find('\n', a + 1);
	text.insert(b, text.substr(a, b - a));  // line of t = 20 s twice
	faulttest::writeBytes(dir.path("dup.csv"), text);
	const std::string e = faulttest::errorOf<FogIoError>([&] { readFogCsv(dir.path("dup.csv")); });
	EXPECT_NE(e.find("dup.csv"), std::string::npos) << e;
	EXPECT_NE(e.find("duplicates"), std::string::npos) << e;
	EXPECT_TRUE(std::regex_search(e, std::regex("dup\\.csv:[0-9]+:"))) << e;  // file:line:
}

// The same in a rawlog: two CObservationFOG with one timestamp. The reader refuses it with the
// file named; the in-memory series is refused by validate() and by the compensator.
TEST(DuplicateTimestamps, RawlogDuplicateIsRefused)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 50);
	auto objs = fogObservationsForRawlog(s);
	ASSERT_GT(objs.size(), 30u);
	objs[30]->timestamp = objs[29]->timestamp;
	writeRawlogObservations(dir.path("dup.rawlog"), objs);
	const std::string e = faulttest::errorOf<FogIoError>([&] { readFogRawlog(dir.path("dup.rawlog")); });
	EXPECT_NE(e.find("dup.rawlog"), std::string::npos) << e;

	FogSeries d = s;
	d.time_s[30] = d.time_s[29];
	EXPECT_THROW(d.validate(), std::invalid_argument);
	EXPECT_THROW(compensate(faulttest::calibration(), d), std::invalid_argument);
	EXPECT_THROW(writeFogCsv(dir.path("d.csv"), d), FogIoError);
	EXPECT_FALSE(std::filesystem::exists(dir.path("d.csv")));
}
