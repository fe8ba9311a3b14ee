/* mrpt_fog: tests of chamber profiles. */
#include <gtest/gtest.h>
#include <mrpt/containers/yaml.h>
#include <mrpt_fog/sim/ChamberProfile.h>

#include <cmath>
#include <fstream>
#include <sstream>

#include "YamlText.h"

using namespace mrpt_fog::sim;

namespace
{
ChamberProfile parse(const std::string& text) { return fogtest::fromYamlText<ChamberProfile>(text, "test.yaml"); }
std::string errorOf(const std::string& text) { return fogtest::fromYamlTextError<ChamberProfile>(text, "test.yaml"); }
}  // namespace

TEST(ChamberProfile, SeedPresetIsThePapersRun)
{
	const auto p = ChamberProfile::preset("seed");
	EXPECT_DOUBLE_EQ(p.duration_s(), 6.75 * 3600);  // 65 + 120 + 100 + 120 min
	EXPECT_DOUBLE_EQ(p.stateAt(0).air_C, 25.0);
	EXPECT_DOUBLE_EQ(p.stateAt(30 * 60).air_C, -5.0);  // 1 C/min down
	EXPECT_DOUBLE_EQ(p.stateAt(65 * 60).air_C, -40.0);
	EXPECT_DOUBLE_EQ(p.stateAt(100 * 60).air_C, -40.0);
	EXPECT_DOUBLE_EQ(p.stateAt(185 * 60 + 50 * 60).air_C, 10.0);  // 1 C/min up
	EXPECT_DOUBLE_EQ(p.stateAt(p.duration_s()).air_C, 60.0);
	EXPECT_TRUE(p.stateAt(1000).power_on);
	EXPECT_EQ(p.initialState(), InitialThermalState::Steady);
}

TEST(ChamberProfile, AllPresetsParseAndDiffer)
{
	for (const auto& name : ChamberProfile::presetNames())
	{
		const auto p = ChamberProfile::preset(name);
		EXPECT_GT(p.duration_s(), 3600.0) << name;
	}
	EXPECT_NE(ChamberProfile::preset("B").duration_s(), ChamberProfile::preset("seed").duration_s());
	EXPECT_EQ(ChamberProfile::preset("warmup").initialState(), InitialThermalState::Cold);
	EXPECT_THROW(ChamberProfile::preset("nope"), std::invalid_argument);
}

TEST(ChamberProfile, StepsSinesSweepsAndSettings)
{
	const auto p = parse(
		"initial_temp_C: 10\n"
		"segments:\n"
		"  - {type: hold, duration_min: 1}\n"
		"  - {type: step, to_C: 20}\n"
		"  - {type: sine, amplitude_C: 5, period_min: 4, cycles: 2}\n"
		"  - {type: power, on: false}\n"
		"  - {type: table, rate_dph: 100}\n"
		"  - {type: field, field_uT: 50}\n"
		"  - {type: sweep, amplitude_C: 2, period_start_min: 10, period_end_min: 1, duration_min: 20}\n");
	EXPECT_DOUBLE_EQ(p.duration_s(), 60 + 8 * 60 + 20 * 60);
	EXPECT_DOUBLE_EQ(p.stateAt(30).air_C, 10.0);
	EXPECT_NEAR(p.stateAt(60 + 60).air_C, 25.0, 1e-9);  // quarter period of the sine
	EXPECT_NEAR(p.stateAt(60 + 180).air_C, 15.0, 1e-9);
	EXPECT_TRUE(p.stateAt(60 + 479).power_on);
	const auto s = p.stateAt(60 + 480 + 1);
	EXPECT_FALSE(s.power_on);
	EXPECT_DOUBLE_EQ(s.table_rate_dph, 100.0);
	EXPECT_DOUBLE_EQ(s.field_uT, 50.0);
	// Sweep: starts at its centre, first zero crossing after half the start period (~5 min).
	EXPECT_NEAR(p.stateAt(60 + 480).air_C, 20.0, 1e-9);
	EXPECT_GT(p.stateAt(60 + 480 + 60).air_C, 20.0);
}

TEST(ChamberProfile, BadInputNamesTheField)
{
	EXPECT_NE(errorOf("segments:\n  - {type: ramp, to_C: 5, rate_C_per_min: 0}\n").find("segments[0].rate_C_per_min"),
			  std::string::npos);
	EXPECT_NE(errorOf("segments:\n  - {type: hold, duration_min: 1}\n  - {type: jump}\n").find("segments[1].type"),
			  std::string::npos);
	EXPECT_NE(errorOf("segments:\n  - {type: hold, duraton_min: 1}\n").find("duraton_min"), std::string::npos);
	EXPECT_NE(errorOf("segments:\n  - {type: hold, duration_min: abc}\n").find("expected a number"), std::string::npos);
	EXPECT_NE(errorOf("initial_temp_C: 3\n").find("segments"), std::string::npos);
	EXPECT_NE(errorOf("initial_state: hot\nsegments:\n  - {type: hold, duration_min: 1}\n").find("initial_state"),
			  std::string::npos);
	EXPECT_THROW(ChamberProfile::fromFile("/nonexistent/p.yaml"), std::invalid_argument);
}
