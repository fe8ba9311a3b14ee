/* mrpt_fog: the simulator's turn-on repeatability and aging (FogDevice::turn_on). */
#include <gtest/gtest.h>
#include <mrpt/containers/yaml.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "YamlText.h"

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

namespace
{
FogDevice quietTurnOnDevice()
{
	FogDevice d = FogDevice::defaultDevice();
	d.noise = GyroNoiseParams{0, 0, 300, 0, 0};
	d.thermistor_noise_C = 0;
	d.thermistor_quantum_C = 0;
	d.errors.constant_bias_dph = 0;
	return d;
}

ChamberState chamberAir(double T, bool on = true, double table = 0)
{
	ChamberState s;
	s.air_C = T;
	s.power_on = on;
	s.table_rate_dph = table;
	return s;
}

double mean(const std::vector<double>& v)
{
	double s = 0;
	for (double x : v) s += x;
	return s / static_cast<double>(v.size());
}

double stddev(const std::vector<double>& v)
{
	const double m = mean(v);
	double s = 0;
	for (double x : v) s += (x - m) * (x - m);
	return std::sqrt(s / static_cast<double>(v.size() - 1));
}
}  // namespace

// Off by default, and then not in the run's metadata (the bundled datasets keep their bytes).
TEST(TurnOnAging, OffByDefaultAndNotDescribed)
{
	const FogDevice d = FogDevice::defaultDevice();
	EXPECT_FALSE(d.turn_on.any());
	for (const auto& kv : d.describe()) EXPECT_EQ(kv.first.find("turn_on"), std::string::npos) << kv.first;
	FogDevice on = d;
	on.turn_on.bias_repeatability_dph = 0.3;
	bool listed = false;
	for (const auto& kv : on.describe()) listed |= kv.first == "device.turn_on.bias_repeatability_dph" && kv.second == "0.3";
	EXPECT_TRUE(listed);
}

// Each power-on draws a new offset, constant until the next one; over 2000 turn-ons the offsets'
// standard deviation is the stated repeatability (its sampling sd is 1.6 %: 5 % is > 3 sd) and
// their mean is 0 (within 4 sd of the mean, 4 x 0.3 / sqrt(2000)).
TEST(TurnOnAging, OffsetIsDrawnAtEachTurnOnWithTheStatedRepeatability)
{
	FogDevice d = quietTurnOnDevice();
	d.turn_on.bias_repeatability_dph = 0.3;
	FogSimulator sim(d, {}, 17);
	sim::FogSample s = sim.start(chamberAir(25), InitialThermalState::Steady);
	std::vector<double> offsets;
	for (int cycle = 0; cycle < 2000; cycle++)
	{
		const double first = sim.advance(1.0, chamberAir(25)).rate_dph;
		EXPECT_EQ(sim.advance(1.0, chamberAir(25)).rate_dph, first);  // constant within a turn-on
		offsets.push_back(first);
		EXPECT_EQ(sim.advance(1.0, chamberAir(25, false)).rate_dph, 0.0);  // off
		s = sim.advance(1.0, chamberAir(25, true));  // the next turn-on
		EXPECT_NE(s.rate_dph, first);
	}
	EXPECT_NEAR(stddev(offsets), 0.3, 0.05 * 0.3);
	EXPECT_NEAR(mean(offsets), 0.0, 4 * 0.3 / std::sqrt(2000.0));
}

// The draws come from their own random stream: with noise on, the output with the turn-on offset
// minus the output without it is exactly the offset, and the ideal twin is unchanged.
TEST(TurnOnAging, OtherRandomStreamsDoNotChange)
{
	FogDevice d = FogDevice::defaultDevice();
	d.noise.angle_quantum_arcsec = 0;  // the offset then enters the rate unquantised
	FogDevice on = d;
	on.turn_on.bias_repeatability_dph = 0.3;
	FogSimulator a(d, defaultEffects(), 5), b(on, defaultEffects(), 5);
	a.start(chamberAir(10), InitialThermalState::Cold);
	b.start(chamberAir(10), InitialThermalState::Cold);
	for (int k = 0; k < 200; k++)
	{
		const sim::FogSample x = a.advance(0.1, chamberAir(10)), y = b.advance(0.1, chamberAir(10));
		EXPECT_EQ(x.ideal_rate_dph, y.ideal_rate_dph);
		EXPECT_EQ(x.temp_C, y.temp_C);
		EXPECT_NEAR(y.rate_dph - x.rate_dph, y.turn_on_bias_dph, 1e-12);
		EXPECT_NE(y.turn_on_bias_dph, 0.0);
	}
}

// Aging: bias = aging rate x (age at t = 0 + t) / 365.25 days.
TEST(TurnOnAging, AgingDriftsWithTheDevicesAge)
{
	FogDevice d = quietTurnOnDevice();
	d.turn_on.aging_dph_per_year = 0.5;
	d.turn_on.age_days = 365.25;
	FogSimulator sim(d, {}, 1);
	EXPECT_NEAR(sim.start(chamberAir(25), InitialThermalState::Steady).rate_dph, 0.5, 1e-12);
	sim::FogSample s;
	for (int k = 0; k < 10; k++) s = sim.advance(86400.0, chamberAir(25));  // ten days on
	EXPECT_NEAR(s.rate_dph, 0.5 * (365.25 + 10) / 365.25, 1e-12);
}

// Scale-factor turn-on repeatability: the drawn error acts on the applied rate (table + Earth).
TEST(TurnOnAging, ScaleFactorDrawActsOnTheAppliedRate)
{
	FogDevice d = quietTurnOnDevice();
	d.turn_on.sf_repeatability_ppm = 50;
	FogSimulator sim(d, {}, 3);
	sim.start(chamberAir(25, true, 36000), InitialThermalState::Steady);
	std::vector<double> ppm;
	for (int cycle = 0; cycle < 1000; cycle++)
	{
		const sim::FogSample s = sim.advance(1.0, chamberAir(25, true, 36000));
		EXPECT_NEAR(s.rate_dph, 36000 * (1 + s.turn_on_sf_ppm * 1e-6), 1e-9);
		EXPECT_EQ(s.ideal_rate_dph, 36000.0);
		ppm.push_back(s.turn_on_sf_ppm);
		sim.advance(1.0, chamberAir(25, false, 36000));
	}
	EXPECT_NEAR(stddev(ppm), 50, 0.07 * 50);  // sampling sd 2.2 %
}

TEST(TurnOnAging, DeviceFileReadsAndChecksTheSection)
{
	const FogDevice d = fogtest::fromYamlText<FogDevice>(
		"turn_on: {bias_repeatability_dph: 0.08, sf_repeatability_ppm: 20, aging_dph_per_year: 0.05, age_days: 90}\n",
		"dev.yaml");
	EXPECT_EQ(d.turn_on.bias_repeatability_dph, 0.08);
	EXPECT_EQ(d.turn_on.sf_repeatability_ppm, 20);
	EXPECT_EQ(d.turn_on.aging_dph_per_year, 0.05);
	EXPECT_EQ(d.turn_on.age_days, 90);
	EXPECT_NE(fogtest::fromYamlTextError<FogDevice>("turn_on: {repeatability: 1}\n", "dev.yaml").find("turn_on"),
			  std::string::npos);
	EXPECT_NE(fogtest::fromYamlTextError<FogDevice>("turn_on: {bias_repeatability_dph: -1}\n", "dev.yaml")
				  .find("turn_on.bias_repeatability_dph"),
			  std::string::npos);
}

// Logs of an aging device carry their dates: t = 0 is age_days after the simulator's epoch.
TEST(TurnOnAging, AgedDeviceIsSimulatedLater)
{
	FogDevice d = FogDevice::defaultDevice();
	EXPECT_EQ(d.epoch_s(), kSimEpoch_s);
	d.turn_on.age_days = 30;
	EXPECT_EQ(d.epoch_s(), kSimEpoch_s + 30 * 86400.0);
}
