/* mrpt_fog: libFuzzer target: the lab CSV reader (readFogCsv).
 * Contract checked (io/FogLogIO.h): any input either reads into a series that passes
 * FogSeries::validate(), or throws FogIoError; never a crash, a sanitizer report, another
 * exception type or a hang. */
#include <mrpt_fog/io/FogLogIO.h>

#include "FuzzTempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string& path = fogfuzz::writeInput(data, size, ".csv");
	try
	{
		const mrpt_fog::FogSeries s = mrpt_fog::readFogCsv(path);
		try
		{
			s.validate();
		}
		catch (const std::exception& e)
		{
			fogfuzz::contractViolation("readFogCsv returned an invalid series", e.what());
		}
	}
	catch (const mrpt_fog::FogIoError&)
	{
	}
	catch (const std::exception& e)
	{
		fogfuzz::contractViolation("readFogCsv threw something else than FogIoError", e.what());
	}
	return 0;
}
