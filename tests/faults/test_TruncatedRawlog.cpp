/* mrpt_fog: fault injection: a rawlog (and a CSV) cut short, e.g. by a full disk or a killed logger. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>

#include <regex>

#include "FaultRun.h"

using namespace mrpt_fog;

// Cut at 5 points (from the gzip header to the last byte): every read throws FogIoError naming
// the file and saying it is truncated/corrupt; never a crash, never a silently shorter series.
TEST(TruncatedRawlog, EveryCutIsAClearError)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 600);
	writeFogRawlog(dir.path("full.rawlog"), s);
	const std::string bytes = faulttest::readBytes(dir.path("full.rawlog"));
	ASSERT_GT(bytes.size(), 100u);
	ASSERT_EQ(readFogRawlog(dir.path("full.rawlog")).fog.size(), s.size());
	for (double frac : {0.0, 0.05, 0.5, 0.9})
		for (std::size_t cut : {static_cast<std::size_t>(frac * bytes.size()), bytes.size() - 1})
		{
			faulttest::writeBytes(dir.path("cut.rawlog"), bytes.substr(0, cut));
			const std::string e = faulttest::errorOf<FogIoError>([&] { readFogRawlog(dir.path("cut.rawlog")); });
			EXPECT_NE(e.find("cut.rawlog"), std::string::npos) << cut << ": " << e;
			EXPECT_TRUE(e.find("truncated") != std::string::npos || e.find("corrupt") != std::string::npos ||
						(cut == 0 && e.find("empty") != std::string::npos))
				<< cut << ": " << e;
		}
}

// A CSV cut in the middle of a line: the last line has too few cells: error naming file and line.
TEST(TruncatedRawlog, CsvCutMidLineIsAClearError)
{
	faulttest::ScratchDir dir;
	const FogSeries s = faulttest::head(faulttest::validationRun(), 100);
	writeFogCsv(dir.path("full.csv"), s);
	std::string text = faulttest::readBytes(dir.path("full.csv"));
	text.resize(text.rfind(',', text.size() - 2));  // drop the last cells of the last line
	faulttest::writeBytes(dir.path("cut.csv"), text);
	const std::string e = faulttest::errorOf<FogIoError>([&] { readFogCsv(dir.path("cut.csv")); });
	EXPECT_NE(e.find("cut.csv"), std::string::npos) << e;
	EXPECT_TRUE(std::regex_search(e, std::regex("cut\\.csv:[0-9]+:"))) << e;  // file:line:
}
