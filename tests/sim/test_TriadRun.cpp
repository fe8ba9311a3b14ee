/* mrpt_fog: tests of the three-axis FOG (triad) runs. */
#include <gtest/gtest.h>
#include <mrpt/containers/yaml.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/DriveTrajectory.h>
#include <mrpt_fog/sim/TriadRun.h>

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

namespace
{
ChamberProfile yamlProfile(const std::string& text) { return ChamberProfile::fromYaml(mrpt::containers::yaml::FromText(text), "test"); }

// Earth rate [deg/h] (IERS: 7.292115e-5 rad/s), independent of units::kEarthRate_dph.
const double kOmega_dph = 7.292115e-5 * 180.0 / M_PI * 3600.0;
}  // namespace

TEST(TriadRun, UpAxisIsTheSingleAxisRunBitForBit)
{
	SimSettings s;
	s.rate_hz = 2.0;
	const auto warm = ChamberProfile::preset("warmup");
	const FogSeries one = simulateChamber(warm, FogDevice::defaultDevice(), s);
	const FogSeries tri = simulateTriadChamber(warm, FogDevice::defaultDevice(), s);
	ASSERT_TRUE(tri.has_axis[0] && tri.has_axis[1] && tri.has_axis[2]);
	EXPECT_EQ(tri.rate_dph[2], one.rate_dph[2]);
	EXPECT_EQ(tri.temp_C, one.temp_C);
	EXPECT_EQ(tri.power, one.power);
	EXPECT_NE(tri.rate_dph[0], one.rate_dph[2]);

	s.rate_hz = 1.0;
	const auto cabin = ChamberProfile::preset("drive_cabin");
	const DriveOutput d1 = simulateDrive(cabin, FogDevice::defaultDevice(), s);
	const DriveOutput d3 = simulateTriadDrive(cabin, FogDevice::defaultDevice(), s);
	EXPECT_EQ(d3.fog.rate_dph[2], d1.fog.rate_dph[2]);
	EXPECT_EQ(d3.fog_ideal.rate_dph[2], d1.fog_ideal.rate_dph[2]);
	EXPECT_EQ(d3.fog.temp_C, d1.fog.temp_C);
	ASSERT_EQ(d3.others.size(), d1.others.size());
	auto ideal0 = std::dynamic_pointer_cast<CObservationFOG>(d3.others[0]);
	ASSERT_TRUE(ideal0);
	EXPECT_EQ(ideal0->sensorLabel, "FOG_IDEAL");
}

TEST(TriadRun, HorizontalAxesSeeTheEarthRateProjectedOnTheTrueHeading)
{
	// Noise-free device, no thermal effect: the ideal x / y rates are the horizontal Earth rate
	// on the body axes, Omega cos(lat) (sin yaw, cos yaw), averaged over each sample interval;
	// checked against a 200-point midpoint quadrature of the truth heading. (The simulator's own
	// 32-point rule errs by dt^2 / (24 * 32^2) x |d2/dt2 Omega_h sin(yaw)|: ~2e-5 deg/h at 4 Hz.)
	SimSettings s;
	s.rate_hz = 4.0;
	s.effects = {"earth_rate"};
	const FogDevice dev = FogDevice::defaultDevice().withoutNoise();
	const auto cabin = ChamberProfile::preset("drive_cabin");
	const DriveOutput d = simulateTriadDrive(cabin, dev, s);
	const DriveTrajectory traj = DriveTrajectory::randomDrive(s.seed, cabin.duration_s());
	const double h = kOmega_dph * std::cos(40.0 * M_PI / 180.0);
	double worst = 0;
	for (std::size_t k = 1; k < d.fog_ideal.size(); k += 3)
	{
		const double t0 = d.fog_ideal.time_s[k - 1], t1 = d.fog_ideal.time_s[k];
		double sx = 0, sy = 0;
		const int m = 200;
		for (int j = 0; j < m; j++)
		{
			const double yaw = traj.at(t0 + (j + 0.5) * (t1 - t0) / m).yaw_rad;
			sx += std::sin(yaw) / m, sy += std::cos(yaw) / m;
		}
		worst = std::max({worst, std::abs(d.fog_ideal.rate_dph[0][k] - h * sx), std::abs(d.fog_ideal.rate_dph[1][k] - h * sy)});
	}
	EXPECT_LT(worst, 2e-4);  // deg/h
	// The output (not the ideal twin) adds the coil's constant bias on top: x -0.2, y 0.45 deg/h.
	EXPECT_NEAR(d.fog.rate_dph[0][100] - d.fog_ideal.rate_dph[0][100], -0.2, 1e-9);
	EXPECT_NEAR(d.fog.rate_dph[1][100] - d.fog_ideal.rate_dph[1][100], 0.45, 1e-9);
}

TEST(TriadRun, RateTableAboutXAndEarthRateMetadata)
{
	SimSettings s;
	s.rate_hz = 10.0;
	s.effects = {"earth_rate"};
	const FogDevice dev = FogDevice::defaultDevice().withoutNoise();
	// 60 s still, then one full turn (360 deg at 36 deg/s = 10 s), then 60 s still.
	const auto prof = yamlProfile(
		"name: turn\ninitial_temp_C: 20\npower_initially: true\ninitial_state: steady\nsegments:\n"
		"  - {type: hold, duration_min: 1}\n  - {type: table, rate_dph: 129600}\n  - {type: hold, duration_min: 0.16666666666666667}\n"
		"  - {type: table, rate_dph: 0}\n  - {type: hold, duration_min: 1}\n");
	const FogSeries r = simulateTriadChamber(prof, dev, s, GyroAxis::X);
	const double up = kOmega_dph * std::sin(40.0 * M_PI / 180.0), hz = kOmega_dph * std::cos(40.0 * M_PI / 180.0);
	// x up: table rate + vertical Earth rate + the x coil's constant bias
	EXPECT_NEAR(r.rate_dph[0][300], up - 0.2, 1e-4);
	EXPECT_NEAR(r.rate_dph[0][650], 129600 + up - 0.2, 1e-3);
	// y east, z north at the start; after a full turn the same again
	EXPECT_NEAR(r.rate_dph[1][300], 0.0 + 0.45, 1e-4);
	EXPECT_NEAR(r.rate_dph[2][300], hz + 0.3, 1e-4);
	EXPECT_NEAR(r.rate_dph[1][1200], 0.0 + 0.45, 1e-3);
	EXPECT_NEAR(r.rate_dph[2][1200], hz + 0.3, 1e-3);
	// a quarter turn in: y points north
	EXPECT_NEAR(r.rate_dph[1][625], hz * std::sin(M_PI / 2 - 0.5 * 0.1 * M_PI / 5) * std::sin(0.05 * M_PI / 5) / (0.05 * M_PI / 5) + 0.45, 2e-3);
	EXPECT_EQ(r.metadataValue("table_axis"), "x");
	EXPECT_EQ(r.metadataValue("triad.up_axis"), "x");
	EXPECT_FALSE(r.metadataValue("earth_rate_dph.x").empty());
	EXPECT_TRUE(r.metadataValue("earth_rate_dph.y").empty());  // the platform turns: not constant
	EXPECT_NEAR(std::stod(r.metadataValue("earth_rate_dph.x")), up, 1e-6);
}

TEST(TriadRun, AxisSeedsAndDevicesDiffer)
{
	EXPECT_EQ(triadAxisSeed(5, GyroAxis::Z), 5u);
	EXPECT_NE(triadAxisSeed(5, GyroAxis::X), triadAxisSeed(5, GyroAxis::Y));
	EXPECT_NE(triadAxisSeed(5, GyroAxis::X), 5u);
	const FogDevice z = FogDevice::defaultDevice();
	EXPECT_EQ(triadAxisDevice(z, GyroAxis::X).errors.sf_ppm_per_C(), 14.0);
	EXPECT_EQ(triadAxisDevice(z, GyroAxis::Y).errors.sf_ppm_per_C(), 27.0);
	EXPECT_EQ(triadAxisDevice(z, GyroAxis::Z).errors.sf_ppm_per_C(), z.errors.sf_ppm_per_C());
}
