/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* Long test (label "long"): random byte corruption of a rawlog. A corrupt length field makes
 * MRPT's deserializer allocate up to 4 GB before it finds the data missing, which takes seconds
 * per case; hence not in the default run. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/GzFile.h>

#include <cmath>
#include <iostream>
#include <random>

#include "../IoTestUtil.h"

using namespace mrpt_fog;

// Corrupt bytes anywhere (class names, lengths, values): the reader either reads a valid series or
// throws FogIoError naming the file; it never crashes, hangs or throws anything else.
TEST(FogRawlogCorruption, CorruptBytesGiveFogIoErrorOrAValidRead)
{
	iotest::ScratchDir dir;
	FogSeries s;
	s.has_axis = {false, false, true};
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}, {"To1", CoilSide::Outer, 0}};
	s.temp_C.assign(2, {});
	for (int k = 0; k < 8; k++)
	{
		s.time_s.push_back(k / 10.0);
		s.rate_dph[2].push_back(0.5 + k * 1e-3);
		s.temp_C[0].push_back(k == 3 ? std::nan("") : 25.0 + k * 0.01);
		s.temp_C[1].push_back(25.5 + k * 0.01);
	}
	writeFogRawlog(dir.path("ok.rawlog"), s);
	const std::string clean = io::readWholeFile(dir.path("ok.rawlog"));
	std::mt19937 rng(11);
	int errors = 0, reads = 0;
	for (int trial = 0; trial < 300; trial++)
	{
		std::string b = clean;
		const int flips = 1 + trial % 3;
		for (int f = 0; f < flips; f++)
			b[std::uniform_int_distribution<std::size_t>(0, b.size() - 1)(rng)] = static_cast<char>(rng());
		io::writeWholeFileAtomically(dir.path("bad.rawlog"), b, true);
		try
		{
			const auto c = readFogRawlog(dir.path("bad.rawlog"));
			EXPECT_NO_THROW(c.fog.validate());
			reads++;
		}
		catch (const FogIoError& e)
		{
			EXPECT_NE(std::string(e.what()).find("bad.rawlog"), std::string::npos) << e.what();
			errors++;
		}
	}
	EXPECT_GT(errors, 0);
	std::cout << "corrupted files: " << errors << " rejected, " << reads << " read (value-only changes)\n";
}
