/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/SimulatorConfig.h>

#include <filesystem>
#include <fstream>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
std::string writeTemp(const std::string& name, const std::string& text)
{
	const auto p = (std::filesystem::temp_directory_path() / name).string();
	std::ofstream(p) << text;
	return p;
}

std::string errorOf(const std::string& text)
{
	try
	{
		readSimulatorConfig(writeTemp("fog_simcfg_bad.yaml", text));
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(SimulatorConfig, ReadsDeviceEffectsFreeAndProfile)
{
	const auto p = writeTemp("fog_simcfg_ok.yaml",
							 "device:\n  errors: {radial_gradient_dph_per_C: 0.05}\n"
							 "effects: [shupe_rate, radial_gradient, earth_rate]\n"
							 "free: [constant_bias_dph, radial_gradient_dph_per_C, thermal_time_scale]\n"
							 "profile: rich\n");
	const auto c = readSimulatorConfig(p);
	EXPECT_DOUBLE_EQ(c.device.errors.radial_gradient_dph_per_C(), 0.05);
	EXPECT_EQ(c.effects, (sim::EffectSet{"shupe_rate", "radial_gradient", "earth_rate"}));
	EXPECT_EQ(c.free, (std::vector<std::string>{"constant_bias_dph", "radial_gradient_dph_per_C", "thermal_time_scale"}));
	EXPECT_FALSE(c.free_is_default);
	EXPECT_EQ(c.profile, "rich");
}

TEST(SimulatorConfig, DefaultFreeSetFollowsEnabledEffects)
{
	const auto c = readSimulatorConfig(writeTemp("fog_simcfg_def.yaml", "effects: [radial_gradient, heat_source, thermistor_lag]\n"));
	EXPECT_TRUE(c.free_is_default);
	EXPECT_EQ(c.free, (std::vector<std::string>{"constant_bias_dph", "radial_gradient_dph_per_C", "electronics_power_W",
												"thermal_time_scale", "thermistor_offsets_C"}));
	EXPECT_EQ(coefficientParameterOf("thermistor_lag"), "");
	EXPECT_EQ(coefficientParameterOf("scale_factor_temp"), "sf_ppm_per_C");
	for (const auto& id : sim::allEffectIds())
		if (auto p = coefficientParameterOf(id); !p.empty())
			EXPECT_NE(std::find(freeParameterIds().begin(), freeParameterIds().end(), p), freeParameterIds().end()) << p;
}

TEST(SimulatorConfig, BadInputNamesFileAndField)
{
	EXPECT_NE(errorOf("effects: [shupe_rate, no_such]\n").find("no_such"), std::string::npos);
	EXPECT_NE(errorOf("free: [gain]\n").find("free: unknown parameter 'gain'"), std::string::npos);
	EXPECT_NE(errorOf("devise: {}\n").find("devise"), std::string::npos);
	EXPECT_NE(errorOf("device:\n  errors: {radial: 1}\n").find("radial"), std::string::npos);
	EXPECT_NE(errorOf("device: {}\ndevice_file: x.yaml\n").find("not both"), std::string::npos);
	EXPECT_NE(errorOf("- a\n- b\n").find("fog_simcfg_bad.yaml"), std::string::npos);
	EXPECT_THROW(readSimulatorConfig("/nonexistent/sim.yaml"), std::invalid_argument);
}

// an empty SIM.yaml gave "not valid YAML: ==== MRPT exception ====". Empty, blank and
// comment-only files now say what a configuration needs; a parse error keeps the parser's line.
TEST(SimulatorConfig, EmptyOrMalformedFileGivesUsefulMessage)
{
	for (const std::string text : {std::string(""), std::string("\n  \n"), std::string("# nothing yet\n")})
	{
		const std::string e = errorOf(text);
		EXPECT_NE(e.find("fog_simcfg_bad.yaml: empty: a simulator configuration needs at least the device"), std::string::npos) << e;
		EXPECT_EQ(e.find("MRPT exception"), std::string::npos) << e;
	}
	const std::string bad = errorOf("effects: [shupe_rate\nfree: []\n");
	EXPECT_NE(bad.find("fog_simcfg_bad.yaml: not valid YAML: line 3"), std::string::npos) << bad;
	EXPECT_NE(bad.find("flow sequence without a closing bracket"), std::string::npos) << bad;
	EXPECT_EQ(bad.find("===="), std::string::npos) << bad;
	EXPECT_NE(errorOf("just a string\n").find("expected a map of key: value"), std::string::npos);
}
