/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/GzFile.h>

#include <cstdlib>
#include <fstream>

#include "IoTestUtil.h"

using namespace mrpt_fog;

// Reference value of CRC-32/ISO-HDLC (the gzip CRC) for "123456789".
TEST(GzFile, Crc32MatchesTheStandardCheckValue)
{
	const std::string s = "123456789";
	EXPECT_EQ(io::crc32Ieee(s.data(), s.size()), 0xCBF43926u);
	EXPECT_EQ(io::crc32Ieee(s.data() + 4, 5, io::crc32Ieee(s.data(), 4)), 0xCBF43926u);  // incremental
}

// The system's gzip(1) is an independent writer: its output must read back, and a cut copy must not.
TEST(GzFile, ReadsGzipOutputAndRejectsACutCopy)
{
	iotest::ScratchDir dir;
	std::string text;
	for (int i = 0; i < 20000; i++) text += std::to_string(i * 7919 % 1000) + ",";
	{
		std::ofstream f(dir.path("a.txt"), std::ios::binary);
		f << text;
	}
	ASSERT_EQ(std::system(("gzip -k " + dir.path("a.txt")).c_str()), 0);
	EXPECT_EQ(io::readWholeFile(dir.path("a.txt.gz")), text);
	EXPECT_EQ(io::readWholeFile(dir.path("a.txt")), text);
	for (int cut : {1, 8, 100, 1000})
	{
		const std::string cmd = "head -c -" + std::to_string(cut) + " " + dir.path("a.txt.gz") + " > " + dir.path("cut.gz");
		ASSERT_EQ(std::system(cmd.c_str()), 0);
		const std::string msg = iotest::ioErrorOf([&] { io::readWholeFile(dir.path("cut.gz")); });
		EXPECT_NE(msg.find("cut.gz"), std::string::npos) << msg;
	}
	io::writeWholeFileAtomically(dir.path("b.gz"), text, true);
	ASSERT_EQ(std::system(("gzip -t " + dir.path("b.gz")).c_str()), 0);
	EXPECT_EQ(io::readWholeFile(dir.path("b.gz")), text);
}
