/* mrpt_fog: the calibration YAML fuzzer's open finding: a map where a scalar is expected. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/CalibrationYaml.h>

#include <iostream>
#include <typeinfo>

#include "FaultRun.h"

using namespace mrpt_fog;

// Found by fuzz_calibration_yaml: a calibration file whose header comment runs into a mapping
// ("...fog-calibrate)Message:  Assert coef_dph...") loads a map where a string is read. The load
// fails with an exception carrying a message (no crash, no hang, nothing returned), but it is
// MRPT's std::logic_error, not the std::invalid_argument "<file>: <field>: <reason>" that
// CalibrationYaml.h documents: reported to the model room (open). This test pins what holds.
TEST(YamlWrongNodeType, MapForScalarFailsWithAnException)
{
	const std::string text =
		faulttest::readBytes(std::string(FOG_SOURCE_DIR) + "/tests/faults/data/yaml_map_for_scalar.yaml");
	ASSERT_FALSE(text.empty());
	bool threw = false;
	try
	{
		(void)calibrationFromYaml(text, "map.yaml");
	}
	catch (const std::exception& e)
	{
		threw = true;
		EXPECT_FALSE(std::string(e.what()).empty());
		std::cout << "exception type " << typeid(e).name() << ", invalid_argument: "
				  << (dynamic_cast<const std::invalid_argument*>(&e) != nullptr) << "\n";
	}
	EXPECT_TRUE(threw);
}
