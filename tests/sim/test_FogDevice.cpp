/* mrpt_fog: tests of the device description (defaults, YAML overlay, bad input). */
#include <gtest/gtest.h>
#include <mrpt/containers/yaml.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <sstream>

#include "YamlText.h"

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

namespace
{
FogDevice parseDevice(const std::string& text) { return fogtest::fromYamlText<FogDevice>(text, "dev.yaml"); }
std::string deviceErrorOf(const std::string& text) { return fogtest::fromYamlTextError<FogDevice>(text, "dev.yaml"); }
}  // namespace

TEST(FogDevice, DefaultHasTheSeedsFourThermistors)
{
	const FogDevice d = FogDevice::defaultDevice();
	ASSERT_EQ(d.thermistors.size(), 4u);
	EXPECT_EQ(d.thermistors[0].info.name, "Ti1");
	EXPECT_EQ(d.thermistors[0].info.side, CoilSide::Inner);
	EXPECT_EQ(d.thermistors[1].info.side, CoilSide::Outer);
	EXPECT_DOUBLE_EQ(d.thermistors[1].info.angle_deg, d.thermistors[0].info.angle_deg);  // paired by angle
	EXPECT_DOUBLE_EQ(d.thermistors[2].info.angle_deg, 180.0);
	EXPECT_EQ(d.winding.pattern, WindingPattern::Quadrupolar);
	EXPECT_GE(d.thermal.layers, 8);
	EXPECT_GE(d.thermal.sectors, 8);
	EXPECT_NO_THROW(d.validate());
}

TEST(FogDevice, YamlOverlaysOnlyGivenKeys)
{
	const FogDevice d = parseDevice(
		"latitude_deg: 30\n"
		"coil: {pattern: octupolar, midpoint_offset_m: 0.5, fiber_layers: 64}\n"
		"thermal: {layers: 10, housing_to_air_W_K: 0.8}\n"
		"errors: {temp_poly_dph: [0.002, 0, 1e-6]}\n"
		"thermistors:\n  - {name: A, side: outer, angle_deg: 90, tau_s: 12}\n");
	EXPECT_DOUBLE_EQ(d.latitude_deg, 30);
	EXPECT_EQ(d.winding.pattern, WindingPattern::Octupolar);
	EXPECT_DOUBLE_EQ(d.winding.midpoint_offset_m, 0.5);
	EXPECT_EQ(d.winding.fiber_layers, 64);
	EXPECT_EQ(d.thermal.layers, 10);
	EXPECT_DOUBLE_EQ(d.thermal.housing_to_air_W_K, 0.8);
	EXPECT_DOUBLE_EQ(d.thermal.hub_capacity_J_K, FogDevice::defaultDevice().thermal.hub_capacity_J_K);
	ASSERT_EQ(d.errors.temp_poly_dph.size(), 3u);
	ASSERT_EQ(d.thermistors.size(), 1u);
	EXPECT_DOUBLE_EQ(d.thermistors[0].tau_s, 12);
	// describe() records every section
	bool has_offset = false;
	for (const auto& kv : d.describe())
		if (kv.first == "device.coil.midpoint_offset_m" && kv.second == "0.5") has_offset = true;
	EXPECT_TRUE(has_offset);
}

TEST(FogDevice, BadInputNamesFileAndField)
{
	EXPECT_NE(deviceErrorOf("coil: {pattern: spiral}\n").find("dev.yaml: coil.pattern"), std::string::npos);
	EXPECT_NE(deviceErrorOf("thermal: {layers: 1}\n").find("thermal.layers"), std::string::npos);
	EXPECT_NE(deviceErrorOf("noise: {arw: 1}\n").find("dev.yaml: noise.arw"), std::string::npos);
	EXPECT_NE(deviceErrorOf("latitude_deg: 95\n").find("latitude_deg"), std::string::npos);
	EXPECT_NE(deviceErrorOf("thermistors:\n  - {name: 'a b', side: inner}\n").find("thermistors[0].name"), std::string::npos);
	EXPECT_NE(deviceErrorOf("thermistors:\n  - {name: A}\n  - {name: A}\n").find("duplicate"), std::string::npos);
	EXPECT_NE(deviceErrorOf("errors: {temp_poly_dph: 3}\n").find("temp_poly_dph"), std::string::npos);
	EXPECT_NE(deviceErrorOf("colour: red\n").find("dev.yaml: colour"), std::string::npos);
}

TEST(FogDevice, WithoutNoiseSilencesEveryNoiseSourceAndKeepsThePhysics)
{
	const auto dev = FogDevice::defaultDevice();
	const auto quiet = dev.withoutNoise();
	EXPECT_EQ(quiet.noise.arw_deg_rt_h, 0.0);
	EXPECT_EQ(quiet.noise.bias_instability_dph, 0.0);
	EXPECT_EQ(quiet.noise.rrw_deg_h_rt_h, 0.0);
	EXPECT_EQ(quiet.noise.angle_quantum_arcsec, 0.0);
	EXPECT_EQ(quiet.thermistor_noise_C, 0.0);
	EXPECT_EQ(quiet.thermistor_quantum_C, 0.0);
	// everything that is not noise is kept
	const auto describe_without_noise = [](const FogDevice& d) {
		auto rows = d.describe();
		rows.erase(std::remove_if(rows.begin(), rows.end(),
								  [](const auto& kv) { return kv.first.find("noise") != std::string::npos ||
															  kv.first.find("quantum") != std::string::npos; }),
				   rows.end());
		return rows;
	};
	EXPECT_EQ(describe_without_noise(quiet), describe_without_noise(dev));
	EXPECT_GT(dev.noise.arw_deg_rt_h, 0.0);  // the default device is noisy: the test means something
}
