/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/LogFormat.h>

#include <cmath>
#include <fstream>
#include <memory>

#include "IoTestUtil.h"

using namespace mrpt_fog;
using iotest::ioErrorOf;
using iotest::spit;

namespace
{

std::string invalidArgumentOf(const std::function<void()>& f) { return fogtest::messageOf<std::invalid_argument>(f); }

const char* const kVendorFormat = R"(delimiter: ";"
skip_lines: 2
time: {column: "Time [ms]", unit: ms}
rates:
  z: {column: "Gyro Z [deg/s]", unit: deg/s}
thermistors:
  Ti1: {column: "T coil in 1 [K]", unit: K, side: inner, angle_deg: 0}
  To1: {column: "T coil out 1 [degC]", unit: C, side: outer, angle_deg: 180}
table_rate: {column: "Table [rad/s]", unit: rad/s}
power: {column: "PWR"}
metadata: {sensor: FOG_Z, latitude_deg: 45.5, epoch_s: 1700000000, site: lab 3}
)";
}  // namespace

TEST(LogFormat, ParsesEveryKeyOfTheSchema)
{
	const LogFormat f = parseLogFormat(kVendorFormat, "vendor.yaml");
	ASSERT_TRUE(f.delimiter.has_value());
	EXPECT_EQ(*f.delimiter, ';');
	EXPECT_EQ(f.skip_lines, 2u);
	EXPECT_EQ(f.time.column, "Time [ms]");
	EXPECT_EQ(f.time_unit, TimeUnit::ms);
	EXPECT_FALSE(f.rates[0]);
	ASSERT_TRUE(f.rates[2]);
	EXPECT_EQ(f.rates[2]->unit, RateUnit::deg_per_s);
	ASSERT_EQ(f.thermistors.size(), 2u);
	ASSERT_TRUE(f.table_rate);
	EXPECT_EQ(f.table_rate->unit, RateUnit::rad_per_s);
	ASSERT_TRUE(f.power);
	EXPECT_EQ(f.metadata.size(), 4u);
}

TEST(LogFormat, BadFormatFilesNameTheKey)
{
	const auto err = [](const std::string& text) { return invalidArgumentOf([&] { parseLogFormat(text, "F.yaml"); }); };
	EXPECT_NE(err("time: {unit: s}\nrates: {z: {column: g, unit: deg/h}}").find("F.yaml: time.column: missing"),
			  std::string::npos);
	EXPECT_NE(err("time: {column: t, unit: min}\nrates: {z: {column: g, unit: deg/h}}").find("F.yaml: time.unit: unknown time unit 'min'"),
			  std::string::npos);
	EXPECT_NE(err("time: {column: t, unit: s}\nrates: {z: {column: g, unit: dps}}").find("rates.z.unit: unknown rate unit 'dps' (expected deg/h, deg/s, rad/s or mdeg/s)"),
			  std::string::npos);
	EXPECT_NE(err("time: {column: t, unit: s}\nrates: {z: {column: g, unit: deg/h}}\nthermistors: {A: {column: g, unit: C}}")
				  .find("thermistors.A.column: column 'g' is already mapped by rates.z"),
			  std::string::npos);
	EXPECT_NE(err("time: {column: t, unit: s}\nrates: {z: {column: g, unit: deg/h}}\nthermistors: {A: {column: a, unit: F}}")
				  .find("thermistors.A.unit: unknown temperature unit 'F'"),
			  std::string::npos);
	EXPECT_NE(err("time: {column: t, unit: s}\nrate: {z: {column: g, unit: deg/h}}").find("F.yaml: rate: unknown key"),
			  std::string::npos);
	EXPECT_NE(err("time: {column: t, unit: s}").find("F.yaml: rates: missing"), std::string::npos);
}

// The same samples written natively and in a vendor layout (other names, ms, deg/s, K,
// semicolons, quotes, an extra column, preamble lines) read back to the same series, to the
// rounding of the unit conversions.
TEST(LogFormat, VendorLayoutReadsAsTheNativeCsv)
{
	iotest::ScratchDir dir;
	std::string native = "# sensor: FOG_Z\n# epoch_s: 1700000000\n# latitude_deg: 45.5\n# site: lab 3\n"
						 "# thermistor Ti1: side=inner angle_deg=0\n# thermistor To1: side=outer angle_deg=180\n"
						 "time_s,rate_z_dph,temp_Ti1_C,temp_To1_C,table_rate_dph,power\n";
	std::string vendor = "Logger v2 export\nrun: 17\n\"Status\";\"Time [ms]\";\"Gyro Z [deg/s]\";\"T coil in 1 [K]\";"
						 "\"T coil out 1 [degC]\";\"Table [rad/s]\";\"PWR\"\n";
	const double pi = 3.14159265358979323846;
	for (int k = 0; k < 50; k++)
	{
		const double t = 0.1 * k, r = 0.25 + 0.01 * k, ti = 20 + 0.1 * k, to = 21 - 0.05 * k, tab = k < 25 ? 0 : 36000;
		char line[512];
		std::snprintf(line, sizeof line, "%.17g,%.17g,%.17g,%.17g,%.17g,1\n", t, r + tab, ti, to, tab);
		native += line;
		std::snprintf(line, sizeof line, "\"ok; fine\";%.17g;%.17g;%.17g;%.17g;%.17g;1\n", t * 1000, (r + tab) / 3600,
					  ti + 273.15, to, tab / 3600 * pi / 180);
		vendor += line;
	}
	spit(dir.path("native.csv"), native);
	spit(dir.path("vendor.dat"), vendor);
	spit(dir.path("vendor.yaml"), kVendorFormat);
	LogReadOptions opt;
	opt.format = std::make_shared<LogFormat>(readLogFormat(dir.path("vendor.yaml")));
	std::vector<LogNotice> notices;
	opt.notice = [&](const LogNotice& n) { notices.push_back(n); };
	const FogSeries a = readFogLog(dir.path("native.csv"));
	const FogSeries b = readFogLog(dir.path("vendor.dat"), "", opt);
	ASSERT_EQ(a.size(), b.size());
	EXPECT_EQ(a.sensor_label, b.sensor_label);
	EXPECT_EQ(a.epoch_s, b.epoch_s);
	EXPECT_TRUE(a.sameLayout(b));
	EXPECT_EQ(a.metadata, b.metadata);
	for (std::size_t k = 0; k < a.size(); k++)
	{
		EXPECT_NEAR(a.time_s[k], b.time_s[k], 1e-15 * (1 + a.time_s[k]));
		EXPECT_NEAR(a.rate_dph[2][k], b.rate_dph[2][k], 1e-12 * (1 + std::abs(a.rate_dph[2][k])));
		for (int i = 0; i < 2; i++) EXPECT_NEAR(a.temp_C[i][k], b.temp_C[i][k], 1e-12);
		EXPECT_NEAR(a.table_rate_dph[k], b.table_rate_dph[k], 1e-9);
	}
	ASSERT_GE(notices.size(), 1u);
	EXPECT_EQ(notices[0].kind, LogNotice::Kind::Note);
	EXPECT_NE(notices[0].message.find("1 column not in the format"), std::string::npos) << notices[0].message;
	EXPECT_NE(notices[0].message.find("\"Status\""), std::string::npos);
}

TEST(LogFormat, AColumnTheFileLacksNamesFormatKeyAndHeader)
{
	iotest::ScratchDir dir;
	spit(dir.path("v.csv"), "t_ms,gz\n0,1\n1,2\n");
	LogReadOptions opt;
	opt.format = std::make_shared<LogFormat>(
		parseLogFormat("time: {column: t_ms, unit: ms}\nrates: {z: {column: \"Gyro Z\", unit: deg/s}}", "F.yaml"));
	const std::string m = ioErrorOf([&] { readFogLog(dir.path("v.csv"), "", opt); });
	EXPECT_NE(m.find("F.yaml: rates.z.column: no column 'Gyro Z' in "), std::string::npos) << m;
	EXPECT_NE(m.find("its columns: \"t_ms\", \"gz\""), std::string::npos) << m;
	spit(dir.path("d.csv"), "t_ms,gz,gz\n0,1,1\n1,2,2\n");
	opt.format = std::make_shared<LogFormat>(
		parseLogFormat("time: {column: t_ms, unit: ms}\nrates: {z: {column: gz, unit: deg/s}}", "F.yaml"));
	const std::string d = ioErrorOf([&] { readFogLog(dir.path("d.csv"), "", opt); });
	EXPECT_NE(d.find("F.yaml: rates.z.column: column 'gz' appears twice (columns 2 and 3)"), std::string::npos) << d;
}

TEST(LogFormat, DelimiterDetectedAndQuotedCellsRead)
{
	iotest::ScratchDir dir;
	spit(dir.path("v.txt"), "\"time\"\t\"w z\"\n0\t\"1.5\"\n0.5\t2.5\n");
	LogReadOptions opt;
	opt.format = std::make_shared<LogFormat>(
		parseLogFormat("time: {column: time, unit: s}\nrates: {z: {column: w z, unit: deg/h}}", "F.yaml"));
	const FogSeries s = readFogLog(dir.path("v.txt"), "", opt);
	ASSERT_EQ(s.size(), 2u);
	EXPECT_EQ(s.rate_dph[2][0], 1.5);
	EXPECT_EQ(s.time_s[1], 0.5);
}

TEST(LogFormat, GuessReadsNamesAndBracketedUnits)
{
	iotest::ScratchDir dir;
	spit(dir.path("v.csv"), "Logger export\n\"Time [ms]\";\"Gyro Z [deg/s]\";\"T coil in 1 [degC]\";Status\n0;0.1;20;ok\n10;0.1;20;ok\n");
	const std::string g = guessLogFormat(dir.path("v.csv"));
	const LogFormat f = parseLogFormat(g, "guess");  // the draft is a valid format file
	EXPECT_EQ(f.skip_lines, 1u);
	EXPECT_EQ(*f.delimiter, ';');
	EXPECT_EQ(f.time.column, "Time [ms]");
	EXPECT_EQ(f.time_unit, TimeUnit::ms);
	ASSERT_TRUE(f.rates[2]);
	EXPECT_EQ(f.rates[2]->unit, RateUnit::deg_per_s);
	ASSERT_EQ(f.thermistors.size(), 1u);
	EXPECT_EQ(f.thermistors[0].column, "T coil in 1 [degC]");
	EXPECT_NE(g.find("\"Status\""), std::string::npos) << g;
}

// A public IMU log's header (EuRoC MAV, imu0/data.csv): units written as "rad s^-1".
TEST(LogFormat, GuessReadsExponentUnits)
{
	iotest::ScratchDir dir;
	spit(dir.path("imu.csv"), "#timestamp [ns],w_RS_S_x [rad s^-1],w_RS_S_y [rad s^-1],w_RS_S_z [rad s^-1],a_RS_S_x [m s^-2]\n"
							  "1403636579758555392,-0.099,0.147,0.027,8.14\n1403636579763555584,-0.099,0.140,0.029,8.03\n");
	const LogFormat f = parseLogFormat(guessLogFormat(dir.path("imu.csv")), "guess");
	EXPECT_EQ(f.time_unit, TimeUnit::ns);
	for (int a = 0; a < 3; a++)
	{
		ASSERT_TRUE(f.rates[a]) << a;
		EXPECT_EQ(f.rates[a]->unit, RateUnit::rad_per_s);
	}
}

// Text after a closing quote is an error naming the line, not a number made of both parts.
TEST(LogFormat, TextAfterAClosingQuoteIsAnError)
{
	iotest::ScratchDir dir;
	spit(dir.path("v.csv"), "time_s,rate_z_dph\n0,\"1\"2\n");
	const std::string m = ioErrorOf([&] { readFogLog(dir.path("v.csv")); });
	EXPECT_NE(m.find("v.csv:2: a quoted cell is malformed"), std::string::npos) << m;
}
