/* mrpt_fog: libFuzzer target: the rawlog reader (readFogRawlog) on plain (uncompressed) bytes,
 * so that mutations reach MRPT's object deserialisation instead of the gzip CRC check.
 * Contract checked (io/FogLogIO.h): a series that passes FogSeries::validate(), or FogIoError;
 * never a crash, a sanitizer report, another exception type or a hang. */
#include <mrpt_fog/io/FogLogIO.h>

#include "FuzzTempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string& path = fogfuzz::writeInput(data, size, ".rawlog");
	try
	{
		const mrpt_fog::FogRawlogContents c = mrpt_fog::readFogRawlog(path);
		try
		{
			c.fog.validate();
		}
		catch (const std::exception& e)
		{
			fogfuzz::contractViolation("readFogRawlog returned an invalid series", e.what());
		}
	}
	catch (const mrpt_fog::FogIoError&)
	{
	}
	catch (const std::exception& e)
	{
		fogfuzz::contractViolation("readFogRawlog threw something else than FogIoError", e.what());
	}
	return 0;
}
