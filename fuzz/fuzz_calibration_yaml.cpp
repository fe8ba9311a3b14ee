/* mrpt_fog: libFuzzer target: the calibration YAML loader (calibrationFromYaml, in memory).
 * Contract checked (model/CalibrationYaml.h): bad text throws an exception (std::invalid_argument
 * documented; see the note at the catch below); text that
 * loads gives a calibration that writes back and reloads, and a Compensator built on it (which
 * may refuse it with std::invalid_argument) runs a few samples without a crash or a sanitizer
 * report. */
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "FuzzTempFile.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size)
{
	const std::string text(reinterpret_cast<const char*>(data), size);
	mrpt_fog::Calibration cal;
	try
	{
		cal = mrpt_fog::calibrationFromYaml(text, "fuzz.yaml");
	}
	catch (const std::invalid_argument&)
	{
		return 0;
	}
	try
	{
		(void)mrpt_fog::calibrationFromYaml(mrpt_fog::calibrationToYaml(cal), "round-trip.yaml");
	}
	catch (const std::exception& e)
	{
		fogfuzz::contractViolation("a loaded calibration does not reload after writing", e.what());
	}
	try
	{
		mrpt_fog::Compensator comp(cal, cal.layout);
		std::vector<double> temps(cal.layout.size());
		for (int k = 0; k < 50; k++)
		{
			for (std::size_t i = 0; i < temps.size(); i++) temps[i] = (k % 7 == 3 && i == 0) ? NAN : 20.0 + 0.1 * k + i;
			(void)comp.step(k, 1.0, temps.data());
		}
	}
	catch (const std::invalid_argument&)
	{
	}
	return 0;
}
