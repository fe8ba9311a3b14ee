/* mrpt_fog: regression of the calibration YAML fuzzer's finding: a parser hang on invalid UTF-8. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/FogDevice.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>

#include "FaultRun.h"
#include "support/ChildProcess.h"

using namespace mrpt_fog;

namespace
{
/** Loads `text` in a child process killed after 20 s. Exit 0: std::invalid_argument naming
 * the source; 1: loaded; 2: another exception; 100 + signal: killed (hang) or crashed. */
int loadInChild(const std::string& text)
{
	return fogtest::exitCodeInChild([&] {
		::alarm(20);
		try
		{
			(void)calibrationFromYaml(text, "hang.yaml");
		}
		catch (const std::invalid_argument& e)
		{
			return std::string(e.what()).find("hang.yaml") != std::string::npos ? 0 : 2;
		}
		catch (...)
		{
			return 2;
		}
		return 1;
	});
}
}  // namespace

// Found by fuzz_calibration_yaml (41 bytes): libfyaml, MRPT's YAML parser, loops forever on a
// '%' directive line holding invalid UTF-8 ("%\xd5\n" is enough). calibrationFromYaml now
// refuses text that is not valid UTF-8 before parsing, naming the file and the byte offset.
TEST(YamlParserHang, InvalidUtf8DirectiveIsRefusedNotHung)
{
	const std::string found = faulttest::readBytes(std::string(FOG_SOURCE_DIR) + "/tests/faults/data/yaml_directive_hang.yaml");
	ASSERT_EQ(found.size(), 41u);
	EXPECT_EQ(loadInChild(found), 0);
	EXPECT_EQ(loadInChild("%\xd5\n"), 0);
	EXPECT_EQ(loadInChild("%YAML\xd5\n"), 0);
	try
	{
		(void)calibrationFromYaml("format: x\n%\xd5\n", "c.yaml");
		ADD_FAILURE() << "loaded";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("c.yaml: not valid UTF-8 text (byte offset 11)"), std::string::npos) << e.what();
	}
	// valid UTF-8 is still parsed (and refused for its content, not its encoding)
	try
	{
		(void)calibrationFromYaml("name: \xc3\xa9t\xc3\xa9\n", "u.yaml");
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_EQ(std::string(e.what()).find("UTF-8"), std::string::npos) << e.what();
	}
}

// The simulator's YAML files (chamber profile, device) go through the same parser: the same
// input must be refused there too, naming the file, not hang.
TEST(YamlParserHang, SimulatorYamlFilesRefuseInvalidUtf8)
{
	const std::string path = std::string(FOG_BINARY_DIR) + "/hang_profile.yaml";
	{
		std::ofstream f(path, std::ios::binary);
		f << "%\xd5\n";
	}
	// exit 0: both refused naming the file; bits 1/2/4: loaded / another message / another
	// exception; 100 + signal: killed by the alarm (hang) or crashed
	EXPECT_EQ(fogtest::exitCodeInChild([&] {
		::alarm(20);
		int code = 0;
		for (int which = 0; which < 2; which++)
		{
			try
			{
				if (which == 0) (void)sim::ChamberProfile::fromFile(path);
				else (void)sim::FogDevice::fromFile(path);
				code |= 1;
			}
			catch (const std::invalid_argument& e)
			{
				if (std::string(e.what()).find("hang_profile.yaml: not valid UTF-8") == std::string::npos) code |= 2;
			}
			catch (...)
			{
				code |= 4;
			}
		}
		return code;
	}),
			  0);
	std::remove(path.c_str());
}
