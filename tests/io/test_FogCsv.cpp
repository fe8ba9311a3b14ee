/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/GzFile.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "IoTestUtil.h"

using namespace mrpt_fog;
using iotest::dataFile;
using iotest::ioErrorOf;
using iotest::spit;
using iotest::slurp;


// Values checked against the literal text of tests/data/io/sample.csv.
TEST(FogCsv, ReadsEveryFieldOfTheSample)
{
	const FogSeries s = readFogCsv(dataFile("sample.csv"));
	EXPECT_EQ(s.sensor_label, "FOG");
	EXPECT_EQ(s.epoch_s, 1700000000.0);
	ASSERT_EQ(s.size(), 5u);
	EXPECT_EQ(s.time_s[1], 0.1);
	EXPECT_EQ(s.time_s[4], 0.4);
	EXPECT_FALSE(s.has_axis[0]);
	EXPECT_FALSE(s.has_axis[1]);
	ASSERT_TRUE(s.has_axis[2]);
	EXPECT_EQ(s.rate_dph[2][0], 0.1234567891234);
	EXPECT_EQ(s.rate_dph[2][2], -0.05);
	EXPECT_EQ(s.rate_dph[2][3], 1e-05);

	ASSERT_EQ(s.thermistorCount(), 4u);
	EXPECT_EQ(s.thermistors[0].name, "Ti1");
	EXPECT_EQ(s.thermistors[0].side, CoilSide::Inner);
	EXPECT_EQ(s.thermistors[1].side, CoilSide::Outer);
	EXPECT_EQ(s.thermistors[2].angle_deg, 180.0);
	// To2 has a column but no metadata line: side other, angle 0.
	EXPECT_EQ(s.thermistors[3].name, "To2");
	EXPECT_EQ(s.thermistors[3].side, CoilSide::Other);
	EXPECT_EQ(s.thermistors[3].angle_deg, 0.0);

	EXPECT_EQ(s.temp_C[0][0], 25.01);
	EXPECT_TRUE(std::isnan(s.temp_C[1][1]));  // empty cell = dropout, not 0
	EXPECT_TRUE(std::isnan(s.temp_C[2][2]));
	EXPECT_TRUE(std::isnan(s.temp_C[3][3]));
	for (int i = 0; i < 4; i++) EXPECT_TRUE(std::isnan(s.temp_C[i][4]));
	EXPECT_EQ(s.temp_C[3][2], 25.22);

	ASSERT_EQ(s.table_rate_dph.size(), 5u);
	EXPECT_EQ(s.table_rate_dph[2], 15.041);
	ASSERT_EQ(s.field_uT.size(), 5u);
	EXPECT_TRUE(std::isnan(s.field_uT[3]));
	EXPECT_EQ(s.power, (std::vector<double>{1, 1, 1, 0, 1}));
	EXPECT_NO_THROW(s.validate());
}

TEST(FogCsv, UnknownMetadataKeyIsKeptNotAnError)
{
	const FogSeries s = readFogCsv(dataFile("sample.csv"));
	EXPECT_EQ(s.metadataValue("operator"), "lab B, chamber 3");
	EXPECT_EQ(s.metadataValue("latitude_deg"), "30.5");
	iotest::ScratchDir dir;
	writeFogCsv(dir.path("out.csv"), s);
	const std::string text = slurp(dir.path("out.csv"));
	EXPECT_NE(text.find("# operator: lab B, chamber 3\n"), std::string::npos) << text;
	EXPECT_EQ(readFogCsv(dir.path("out.csv")).metadataValue("operator"), "lab B, chamber 3");
}

TEST(FogCsv, CrlfLineEndsReadLikeLf)
{
	ASSERT_NE(slurp(dataFile("sample_crlf.csv")).find("\r\n"), std::string::npos);
	iotest::expectSameSeries(readFogCsv(dataFile("sample.csv")), readFogCsv(dataFile("sample_crlf.csv")));
}

TEST(FogCsv, GzipFileReadsLikePlain)
{
	ASSERT_TRUE(io::isGzipFile(dataFile("sample.csv.gz")));
	iotest::expectSameSeries(readFogCsv(dataFile("sample.csv")), readFogCsv(dataFile("sample.csv.gz")));
}

TEST(FogCsv, TruncatedGzipThrows)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("truncated.csv.gz")); });
	EXPECT_NE(msg.find("truncated.csv.gz"), std::string::npos) << msg;
	EXPECT_NE(msg.find("truncated or corrupt gzip"), std::string::npos) << msg;
}

TEST(FogCsv, MissingTimeColumn)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_missing_time.csv")); });
	EXPECT_NE(msg.find("bad_missing_time.csv:2:"), std::string::npos) << msg;
	EXPECT_NE(msg.find("missing required column 'time_s'"), std::string::npos) << msg;
}

TEST(FogCsv, MissingRateColumn)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_missing_rate.csv")); });
	EXPECT_NE(msg.find("bad_missing_rate.csv:2:"), std::string::npos) << msg;
	EXPECT_NE(msg.find("missing required rate column"), std::string::npos) << msg;
}

TEST(FogCsv, UnparsableNumberNamesLineAndColumn)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_number.csv")); });
	EXPECT_NE(msg.find("bad_number.csv:4: column 2 (rate_z_dph): cannot parse '0.x3'"), std::string::npos) << msg;
}

TEST(FogCsv, TimeGoingBackwards)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_time_backwards.csv")); });
	EXPECT_NE(msg.find("bad_time_backwards.csv:4: column 1 (time_s)"), std::string::npos) << msg;
	EXPECT_NE(msg.find("goes backwards"), std::string::npos) << msg;
}

TEST(FogCsv, DuplicateTime)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_time_duplicate.csv")); });
	EXPECT_NE(msg.find("bad_time_duplicate.csv:4: column 1 (time_s)"), std::string::npos) << msg;
	EXPECT_NE(msg.find("duplicates"), std::string::npos) << msg;
}

TEST(FogCsv, WrongNumberOfCells)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_cell_count.csv")); });
	EXPECT_NE(msg.find("bad_cell_count.csv:3: 2 cells, but the header (line 1) has 3 columns"), std::string::npos) << msg;
}

TEST(FogCsv, EmptyRateCellIsAnErrorNotADropout)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_empty_rate.csv")); });
	EXPECT_NE(msg.find("bad_empty_rate.csv:2: column 2 (rate_z_dph): empty cell"), std::string::npos) << msg;
}

TEST(FogCsv, PowerOffRowsKeepTheThermistorsAndHaveNoGyroSample)
{
	// power 0 with an empty rate cell: thermistors kept, rate NaN (no sample), turn-on when
	// power returns; the power column may come before or after the rate column.
	iotest::ScratchDir dir;
	for (const std::string header : {"time_s,rate_z_dph,temp_Ti1_C,power", "time_s,power,temp_Ti1_C,rate_z_dph"})
	{
		const bool power_first = header.find("power") < header.find("rate");
		auto row = [&](const char* t, const char* rate, const char* temp, const char* p) {
			return power_first ? std::string(t) + "," + p + "," + temp + "," + rate + "\n"
							   : std::string(t) + "," + rate + "," + temp + "," + p + "\n";
		};
		spit(dir.path("p.csv"), header + "\n" + row("0", "1.5", "20", "1") + row("1", "", "20.5", "0") +
									row("2", "", "21", "0") + row("3", "1.25", "21.5", "1") + row("4", "1.0", "22", "1"));
		const FogSeries s = readFogCsv(dir.path("p.csv"));
		ASSERT_EQ(s.size(), 5u);
		EXPECT_EQ(s.rate_dph[2][0], 1.5);
		EXPECT_TRUE(std::isnan(s.rate_dph[2][1]));
		EXPECT_TRUE(std::isnan(s.rate_dph[2][2]));
		EXPECT_EQ(s.rate_dph[2][3], 1.25);
		EXPECT_EQ(s.temp_C[0][1], 20.5);  // thermistor kept on the power-off row
		EXPECT_EQ(s.temp_C[0][2], 21.0);
		EXPECT_FALSE(s.gyroOn(1));
		EXPECT_TRUE(s.gyroOn(3));
		EXPECT_EQ(s.turnOnSamples(), std::vector<std::size_t>({3}));
		EXPECT_NO_THROW(s.validate());
		// written back: the power-off rate is an empty cell again, everything else exact
		writeFogCsv(dir.path("back.csv"), s);
		const FogSeries b = readFogCsv(dir.path("back.csv"));
		EXPECT_TRUE(std::isnan(b.rate_dph[2][1]));
		EXPECT_EQ(b.temp_C[0], s.temp_C[0]);
		EXPECT_EQ(b.power, s.power);
	}
}

TEST(FogCsv, EmptyRateCellWithThePowerOnIsAnError)
{
	iotest::ScratchDir dir;
	spit(dir.path("t.csv"), "time_s,rate_z_dph,temp_Ti1_C,power\n0,1,20,1\n1,,20,1\n");
	std::string msg = ioErrorOf([&] { readFogCsv(dir.path("t.csv")); });
	EXPECT_NE(msg.find("t.csv:3: column 2 (rate_z_dph): empty cell with the gyro powered"), std::string::npos) << msg;
	// an empty power cell is an error of its own (not "off")
	spit(dir.path("t.csv"), "time_s,rate_z_dph,power\n0,,\n");
	msg = ioErrorOf([&] { readFogCsv(dir.path("t.csv")); });
	EXPECT_NE(msg.find("t.csv:2: column"), std::string::npos) << msg;
	EXPECT_NE(msg.find("empty cell"), std::string::npos) << msg;
	// no power column: an empty rate is an error that says where a rate may be empty
	spit(dir.path("t.csv"), "time_s,rate_z_dph\n0,1\n1,\n");
	msg = ioErrorOf([&] { readFogCsv(dir.path("t.csv")); });
	EXPECT_NE(msg.find("t.csv:3: column 2 (rate_z_dph): empty cell"), std::string::npos) << msg;
	EXPECT_NE(msg.find("power 0"), std::string::npos) << msg;
	// a NaN rate with the power on cannot be written either
	FogSeries s;
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}};
	s.time_s = {0, 1};
	s.rate_dph[2] = {1.0, std::nan("")};
	s.temp_C = {{20, 21}};
	s.power = {1, 1};
	msg = ioErrorOf([&] { writeFogCsv(dir.path("w.csv"), s); });
	EXPECT_NE(msg.find("non-finite rate_z_dph at sample 1"), std::string::npos) << msg;
}

TEST(FogCsv, EmptyFile)
{
	const std::string msg = ioErrorOf([] { readFogCsv(dataFile("empty.csv")); });
	EXPECT_NE(msg.find("empty.csv: empty file"), std::string::npos) << msg;
}

TEST(FogCsv, HeaderMissing)
{
	std::string msg = ioErrorOf([] { readFogCsv(dataFile("bad_no_header.csv")); });
	EXPECT_NE(msg.find("no header row"), std::string::npos) << msg;
	msg = ioErrorOf([] { readFogCsv(dataFile("bad_header_is_data.csv")); });
	EXPECT_NE(msg.find("bad_header_is_data.csv:1: header row missing"), std::string::npos) << msg;
}

TEST(FogCsv, MissingFileNamesIt)
{
	const std::string msg = ioErrorOf([] { readFogCsv("/nonexistent/dir/run.csv"); });
	EXPECT_NE(msg.find("/nonexistent/dir/run.csv"), std::string::npos) << msg;
}

TEST(FogCsv, OtherBadInputsNameTheLine)
{
	iotest::ScratchDir dir;
	struct Case
	{
		const char* text;
		const char* expect;
	} cases[] = {
		{"time_s,rate_z_dph,foo\n0,1,2\n", "t.csv:1: column 3 'foo' is not a known column"},
		{"time_s,rate_z_dph,rate_z_dph\n0,1,2\n", "t.csv:1: column 3 'rate_z_dph' repeats column 2"},
		{"# thermistor Ti1: side=middle angle_deg=0\ntime_s,rate_z_dph,temp_Ti1_C\n0,1,2\n", "t.csv:1: thermistor 'Ti1': side 'middle'"},
		{"# thermistor Ti9: side=inner\ntime_s,rate_z_dph\n0,1\n", "t.csv:1: thermistor 'Ti9' is declared but the header has no column"},
		{"time_s,rate_z_dph\n", "t.csv: header but no data rows"},
		{"time_s,rate_z_dph\n0,nan\n", "t.csv:2: column 2 (rate_z_dph): value 'nan' is not finite"},
		{"time_s,rate_z_dph,power\n0,1,0.5\n", "t.csv:2: column 3 (power): power must be 1 (on) or 0 (off)"},
		{"# latitude_deg: north\ntime_s,rate_z_dph\n0,1\n", "t.csv:1: latitude_deg"},
	};
	for (const auto& c : cases)
	{
		spit(dir.path("t.csv"), c.text);
		const std::string msg = ioErrorOf([&] { readFogCsv(dir.path("t.csv")); });
		EXPECT_NE(msg.find(c.expect), std::string::npos) << "input:\n" << c.text << "message: " << msg;
	}
}

TEST(FogCsv, WriteThenReadIsExactIncludingDropouts)
{
	// Random full-precision doubles: the writer's shortest round-trip format must give them back.
	std::mt19937_64 rng(42);
	std::uniform_real_distribution<double> u(-1e3, 1e3);
	FogSeries s;
	s.sensor_label = "FOG_A";
	s.epoch_s = 1234567890.25;
	s.has_axis = {true, false, true};
	s.thermistors = {{"Ti1", CoilSide::Inner, 12.5}, {"To1", CoilSide::Outer, 12.5}, {"x_3", CoilSide::Other, -90}};
	s.metadata = {{"latitude_deg", "45.5"}, {"note", "k: v, with commas"}, {"", "free comment"}};
	const std::size_t n = 300;
	s.temp_C.assign(3, {});
	for (std::size_t k = 0; k < n; k++)
	{
		s.time_s.push_back(k * 0.01 + u(rng) * 1e-6);
		s.rate_dph[0].push_back(u(rng));
		s.rate_dph[2].push_back(u(rng) * 1e-9);
		for (int i = 0; i < 3; i++) s.temp_C[i].push_back(k % (7 + i) == 0 ? std::nan("") : u(rng) / 10);
		s.power.push_back(k % 2);
	}
	std::sort(s.time_s.begin(), s.time_s.end());
	iotest::ScratchDir dir;
	for (const char* name : {"w.csv", "w.csv.gz"})
	{
		writeFogCsv(dir.path(name), s);
		iotest::expectSameSeries(s, readFogCsv(dir.path(name)));
	}
	EXPECT_TRUE(io::isGzipFile(dir.path("w.csv.gz")));
	EXPECT_FALSE(io::isGzipFile(dir.path("w.csv")));
}

TEST(FogCsv, FailedWriteLeavesNoFileAndKeepsThePreviousOne)
{
	iotest::ScratchDir dir;
	FogSeries good = readFogCsv(dataFile("sample.csv"));
	const std::string out = dir.path("out.csv");
	writeFogCsv(out, good);
	const std::string before = slurp(out);
	FogSeries bad = good;
	bad.time_s[2] = bad.time_s[1];  // not strictly increasing
	const std::string msg = ioErrorOf([&] { writeFogCsv(out, bad); });
	EXPECT_NE(msg.find("out.csv"), std::string::npos) << msg;
	EXPECT_EQ(slurp(out), before);
	ioErrorOf([&] { writeFogCsv(dir.path("never.csv"), bad); });
	EXPECT_FALSE(std::filesystem::exists(dir.path("never.csv")));
	for (const auto& e : std::filesystem::directory_iterator(dir.path("")))
		EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

TEST(FogCsv, MetadataThatCannotBeOneLineIsRefused)
{
	iotest::ScratchDir dir;
	FogSeries s = readFogCsv(dataFile("sample.csv"));
	s.metadata.emplace_back("note", "two\nlines");
	EXPECT_NE(ioErrorOf([&] { writeFogCsv(dir.path("m.csv"), s); }).find("metadata key 'note'"), std::string::npos);
	s.metadata.back() = {"a:b", "c"};
	EXPECT_NE(ioErrorOf([&] { writeFogCsv(dir.path("m.csv"), s); }).find("metadata key 'a:b'"), std::string::npos);
	EXPECT_FALSE(std::filesystem::exists(dir.path("m.csv")));
}
