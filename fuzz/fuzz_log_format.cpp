/* mrpt_fog: libFuzzer target: log format files (parseLogFormat) and a logger CSV read through
 * the parsed format. Contract checked (io/LogFormat.h, io/FogLogReader.h): any format text either
 * parses or throws std::invalid_argument; a parsed format reads the fixed CSV below into a
 * series that passes FogSeries::validate(), or throws FogIoError; never a crash, a sanitizer
 * report, another exception type or a hang. */
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/LogFormat.h>

#include <fstream>
#include <memory>

#include "FuzzTempFile.h"

namespace
{
const std::string& loggerCsv()
{
	static const std::string path = [] {
		const std::string p = fogfuzz::writeInput(reinterpret_cast<const uint8_t*>(""), 0, ".dat") + ".logger.csv";
		std::ofstream f(p, std::ios::binary);
		f << "Logger export\r\n\"Status\";\"Time [ms]\";\"Gyro Z [deg/s]\";\"T1 [degC]\";\"T2 [K]\";\"PWR\"\r\n"
			 "\"ok; a\";0;0.0028;25.1;298.3;1\r\n\"ok\";100;0.0029;25.1;;1\r\n\"ok\";200;;25.2;298.4;0\r\n";
		return p;
	}();
	return path;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string text(reinterpret_cast<const char*>(data), size);
	mrpt_fog::LogReadOptions opt;
	try
	{
		opt.format = std::make_shared<mrpt_fog::LogFormat>(mrpt_fog::parseLogFormat(text, "fuzz.yaml"));
	}
	catch (const std::invalid_argument&)
	{
		return 0;
	}
	catch (const std::exception& e)
	{
		fogfuzz::contractViolation("parseLogFormat threw something else than std::invalid_argument", e.what());
	}
	try
	{
		const mrpt_fog::FogSeries s = mrpt_fog::readFogLog(loggerCsv(), "", opt);
		try
		{
			s.validate();
		}
		catch (const std::exception& e)
		{
			fogfuzz::contractViolation("a formatted read returned an invalid series", e.what());
		}
	}
	catch (const mrpt_fog::FogIoError&)
	{
	}
	catch (const std::exception& e)
	{
		fogfuzz::contractViolation("a formatted read threw something else than FogIoError", e.what());
	}
	return 0;
}
