/* mrpt_fog: hostile and unusual log files: multi-member gzip, decompression bombs,
 * long lines, tens of thousands of columns, absurd rates, binary cells, times closer than a
 * rawlog's 100 ns tick, a full disk, a thermistor count a CObservationRawDAQ cannot hold. Each
 * of these failed (crash, bad_alloc, silent garbage, lost reason) before the fix. */
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/io/GzFile.h>
#include <mrpt_fog/io/GzStream.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <sys/resource.h>
#include <sys/wait.h>

#include <fstream>

#include "IoTestUtil.h"
#include "support/AddressSpaceLimit.h"
#include "support/ChildProcess.h"

using namespace mrpt_fog;
using iotest::dataFile;
using iotest::ioErrorOf;

namespace
{
void writeGz(const std::string& path, const std::string& text, bool append = false)
{
	const std::string tmp = path + ".member";
	{
		io::GzWriter w(tmp, true);
		w.write(text);
		w.close();
	}
	std::ifstream in(tmp, std::ios::binary);
	std::ofstream out(path, std::ios::binary | (append ? std::ios::app : std::ios::trunc));
	out << in.rdbuf();
	std::filesystem::remove(tmp);
}
void writeText(const std::string& path, const std::string& text) { std::ofstream(path, std::ios::binary) << text; }
std::string decompressedBytes(const std::string& path) { return io::readWholeFile(path); }
}  // namespace

// pigz / bgzip / `cat a.gz b.gz` write several gzip members: all are read (was: "corrupt").
TEST(HostileLogs, MultiMemberGzipIsReadWhole)
{
	iotest::ScratchDir d;
	const std::string text = decompressedBytes(dataFile("sample.csv"));
	const std::size_t half = text.find('\n', text.size() / 2) + 1;
	writeGz(d.path("multi.csv.gz"), text.substr(0, half));
	writeGz(d.path("multi.csv.gz"), text.substr(half), true);
	const FogSeries a = readFogCsv(dataFile("sample.csv")), b = readFogCsv(d.path("multi.csv.gz"));
	ASSERT_EQ(a.size(), b.size());
	EXPECT_EQ(a.time_s, b.time_s);
	EXPECT_EQ(io::readWholeFile(d.path("multi.csv.gz")), text);
	// A corrupt second member is still caught.
	std::string bytes = decompressedBytes(d.path("multi.csv.gz"));  // decompressed; corrupt the file itself:
	std::ifstream in(d.path("multi.csv.gz"), std::ios::binary);
	std::string raw((std::istreambuf_iterator<char>(in)), {});
	raw[raw.size() - 6] ^= 0x55;  // inside the last member's CRC/length trailer
	writeText(d.path("bad.csv.gz"), raw);
	EXPECT_NE(ioErrorOf([&] { readFogCsv(d.path("bad.csv.gz")); }).find("truncated or corrupt gzip"), std::string::npos);
}

// 60 MB of blank lines in a 60 kB .csv.gz: memory stays flat (was: the whole text plus one
// std::string per line, ~32 x the decompressed size), the file is refused for having no header.
TEST(HostileLogs, BlankLineBombReadInFlatMemory)
{
	iotest::ScratchDir d;
	{
		io::GzWriter w(d.path("bomb.csv.gz"), true, 9);
		const std::string mb(1 << 20, '\n');
		for (int i = 0; i < 60; i++) w.write(mb);
		w.close();
	}
	// exit 0: refused for having no header; 1: read; 2: another FogIoError; 4: another exception
	EXPECT_EQ(fogtest::exitCodeInChild([&] {
		fogtest::limitAddressSpace(400ull << 20);  // well under the old cost (~2 GB); not under ASan
		try
		{
			readFogCsv(d.path("bomb.csv.gz"));
			return 1;
		}
		catch (const FogIoError& e)
		{
			return std::string(e.what()).find("empty file") != std::string::npos ? 0 : 2;
		}
		catch (...)
		{
			return 4;
		}
	}),
			  0);
}

TEST(HostileLogs, LineLengthLimitNamed)
{
	iotest::ScratchDir d;
	writeText(d.path("long.csv"), "time_s,rate_z_dph\n0," + std::string(2u << 20, '1') + "\n");
	const std::string e = ioErrorOf([&] { readFogCsv(d.path("long.csv")); });
	EXPECT_NE(e.find("long.csv:2: line longer than the limit of 1048576 bytes"), std::string::npos) << e.substr(0, 300);
}

// 40 000 thermistor columns: refused at the header (was: 12.3 GB and 88 s in screening).
TEST(HostileLogs, ThermistorCountLimitNamed)
{
	iotest::ScratchDir d;
	std::string h = "time_s,rate_z_dph";
	for (int i = 0; i < 40000; i++) h += ",temp_T" + std::to_string(i) + "_C";
	writeText(d.path("wide.csv"), h + "\n" + "0,1" + std::string(40000, ',') + "\n");
	const std::string e = ioErrorOf([&] { readFogCsv(d.path("wide.csv")); });
	EXPECT_NE(e.find("wide.csv:1: column 67 'temp_T64_C': more than the limit of 64 thermistor columns"), std::string::npos)
		<< e;
}

TEST(HostileLogs, AbsurdRateRefusedWithLine)
{
	iotest::ScratchDir d;
	writeText(d.path("r.csv"), "time_s,rate_z_dph,table_rate_dph\n0,1,0\n0.1,1e308,0\n");
	EXPECT_NE(ioErrorOf([&] { readFogCsv(d.path("r.csv")); })
				  .find("r.csv:3: column 2 (rate_z_dph): rate 1e308 deg/h is beyond the limit of 100000000 deg/h"),
			  std::string::npos);
	writeText(d.path("t.csv"), "time_s,rate_z_dph,table_rate_dph\n0,1,-2e9\n");
	EXPECT_NE(ioErrorOf([&] { readFogCsv(d.path("t.csv")); }).find("t.csv:2: column 3 (table_rate_dph)"), std::string::npos);
}

// An applied field beyond 1e4 uT (10 mT) is no gyro test's: refused naming the line and column
// in a CSV and the object in a rawlog (was: 1e300 uT compensated to -2e296 deg/h, silently).
TEST(HostileLogs, AbsurdFieldRefusedWithLine)
{
	iotest::ScratchDir d;
	writeText(d.path("f.csv"), "time_s,rate_z_dph,field_uT\n0,1,50\n0.1,1,1e300\n");
	const std::string e = ioErrorOf([&] { readFogCsv(d.path("f.csv")); });
	EXPECT_NE(e.find("f.csv:3: column 3 (field_uT): applied field 1e300 uT is beyond the limit of 10000 uT"),
			  std::string::npos)
		<< e;
	writeText(d.path("ok.csv"), "time_s,rate_z_dph,field_uT\n0,1,-10000\n0.1,1,\n");
	FogSeries s = readFogCsv(d.path("ok.csv"));  // -1e4 uT (the limit) and an empty cell: read
	EXPECT_EQ(s.field_uT[0], -10000.0);
	s.field_uT = {50.0, 1e6};
	writeFogRawlog(d.path("f.rawlog"), s);
	const std::string r = ioErrorOf([&] { readFogRawlog(d.path("f.rawlog")); });
	EXPECT_NE(r.find("field_uT 1000000 uT is beyond the limit of 10000 uT"), std::string::npos) << r;
}

// A 10 kB cell of binary bytes: the message shows 40 bytes, escaped, and the length.
TEST(HostileLogs, LongBinaryCellCutAndEscaped)
{
	iotest::ScratchDir d;
	std::string cell(10000, '\x01');
	cell[0] = 'x';
	writeText(d.path("b.csv"), "time_s,rate_z_dph\n0," + cell + "\n");
	const std::string e = ioErrorOf([&] { readFogCsv(d.path("b.csv")); });
	EXPECT_LT(e.size(), 300u) << e.substr(0, 400);
	EXPECT_NE(e.find("cannot parse 'x\\x01\\x01"), std::string::npos) << e;
	EXPECT_NE(e.find("... (10000 bytes)"), std::string::npos) << e;
	EXPECT_EQ(e.find('\x01'), std::string::npos);
}

// Times 40 ns apart are distinct in a CSV but not in a rawlog (100 ns ticks): the conversion is
// refused naming the sample (was: written, then refused by every reader).
TEST(HostileLogs, TimesCloserThanRawlogTickRefusedAtConversion)
{
	iotest::ScratchDir d;
	writeText(d.path("fast.csv"), "time_s,rate_z_dph\n0,1\n0.00000004,1\n");
	const FogSeries s = readFogCsv(d.path("fast.csv"));
	const std::string e = ioErrorOf([&] { writeFogRawlog(d.path("fast.rawlog"), s); });
	EXPECT_NE(e.find("fast.rawlog: cannot write sample 1: time 4e-08 s is less than 100 ns after"), std::string::npos) << e;
	EXPECT_FALSE(std::filesystem::exists(d.path("fast.rawlog")));
}

// A full disk: the reason reaches the message (was: "write error" or nothing; MRPT's gz stream
// does not check its close). /dev/full returns ENOSPC on every write.
TEST(HostileLogs, WriteErrorKeepsReason)
{
	iotest::ScratchDir d;
	std::filesystem::create_symlink("/dev/full", d.path("full.rawlog"));
	std::filesystem::create_symlink("/dev/full", d.path("full.csv"));
	const FogSeries s = readFogCsv(dataFile("sample.csv"));
	EXPECT_NE(ioErrorOf([&] { writeFogRawlog(d.path("full.rawlog"), s); }).find("No space left on device"), std::string::npos);
	EXPECT_NE(ioErrorOf([&] { writeFogCsv(d.path("full.csv"), s); }).find("No space left on device"), std::string::npos);
}

TEST(HostileLogs, TooManyThermistorsForStockRawDaqRefused)
{
	CObservationFOG o;
	for (int i = 0; i < 66000; i++) o.addThermistor({"T" + std::to_string(i), CoilSide::Other, 0.0}, 20.0);
	EXPECT_THROW(o.toRawDAQ(), std::invalid_argument);
}

// The streaming reader and writer reproduce the whole-file ones exactly.
TEST(HostileLogs, StreamingRoundTripMatches)
{
	iotest::ScratchDir d;
	const FogSeries s = readFogCsv(dataFile("sample.csv"));
	{
		FogLogReader r(dataFile("sample.csv"));
		FogLogWriter w(d.path("s.rawlog"), r.header());
		FogSample x;
		while (r.next(x)) w.write(x);
		w.close();
		EXPECT_EQ(r.samplesRead(), s.size());
	}
	const FogSeries back = readFogRawlog(d.path("s.rawlog")).fog;
	ASSERT_EQ(back.size(), s.size());
	for (std::size_t k = 0; k < s.size(); k++)
	{
		EXPECT_EQ(back.time_s[k], s.time_s[k]);
		for (std::size_t i = 0; i < s.temp_C.size(); i++) EXPECT_TRUE(iotest::sameValue(back.temp_C[i][k], s.temp_C[i][k]));
	}
	EXPECT_EQ(back.metadata, s.metadata);
}
