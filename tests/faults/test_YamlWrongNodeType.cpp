/* mrpt_fog: the calibration YAML fuzzer's open finding: a map where a scalar is expected. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/CalibrationYaml.h>


#include "FaultRun.h"

using namespace mrpt_fog;

// Found by fuzz_calibration_yaml: a calibration file whose header comment runs into a mapping
// ("...fog-calibrate)Message:  Assert coef_dph...") loads a map where a string is read. MRPT's
// accessor throws std::logic_error; calibrationFromYaml turns it into the documented
// std::invalid_argument "<file>: <reason>" on one line.
TEST(YamlWrongNodeType, MapForScalarIsAnInvalidArgumentNamingTheFile)
{
	const std::string text =
		faulttest::readBytes(std::string(FOG_SOURCE_DIR) + "/tests/faults/data/yaml_map_for_scalar.yaml");
	ASSERT_FALSE(text.empty());
	try
	{
		(void)calibrationFromYaml(text, "map.yaml");
		ADD_FAILURE() << "loaded";
	}
	catch (const std::invalid_argument& e)
	{
		const std::string what = e.what();
		EXPECT_EQ(what.rfind("map.yaml: ", 0), 0u) << what;
		EXPECT_EQ(what.find('\n'), std::string::npos) << what;
	}
}
