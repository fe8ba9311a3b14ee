/* mrpt_fog: tests of the stepped FOG simulator and its switchable error sources. */
#include <gtest/gtest.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/FogSimulator.h>

#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

namespace
{
// A device without noise or quantisation, so each effect can be read exactly.
FogDevice quietDevice()
{
	FogDevice d = FogDevice::defaultDevice();
	d.noise = GyroNoiseParams{0, 0, 300, 0, 0};
	d.thermistor_noise_C = 0;
	d.thermistor_quantum_C = 0;
	d.errors.constant_bias_dph = 0;
	return d;
}

ChamberState air(double T, bool on = true, double table = 0, double field = 0)
{
	ChamberState s;
	s.air_C = T;
	s.power_on = on;
	s.table_rate_dph = table;
	s.field_uT = field;
	return s;
}
}  // namespace

TEST(FogSimulator, EarthRateAloneIsVerticalComponent)
{
	FogSimulator sim(quietDevice(), {"earth_rate"}, 1);
	sim.start(air(25), InitialThermalState::Steady);
	const sim::FogSample s = sim.advance(0.1, air(25));
	EXPECT_NEAR(s.rate_dph, 15.041 * std::sin(40 * units::kDegToRad), 1e-3);  // PHYSICS.md, 40 deg
	EXPECT_DOUBLE_EQ(s.rate_dph, s.ideal_rate_dph);
}

TEST(FogSimulator, NoEffectsAndNoNoiseGiveZero)
{
	FogSimulator sim(quietDevice(), {}, 1);
	sim.start(air(25), InitialThermalState::Steady);
	for (int k = 0; k < 100; k++)
	{
		const sim::FogSample s = sim.advance(1.0, air(25 - 0.1 * k));
		EXPECT_DOUBLE_EQ(s.rate_dph, 0.0);
	}
}

TEST(FogSimulator, ShupeTermFollowsNodeRatesAndVanishesAtSteadyState)
{
	FogSimulator sim(quietDevice(), {"shupe_rate"}, 1);
	sim.start(air(25), InitialThermalState::Steady);
	sim::FogSample s;
	double peak = 0;
	for (int k = 0; k < 3600; k++)
	{
		s = sim.advance(1.0, air(25 - k / 60.0));  // 1 C/min down for an hour
		EXPECT_DOUBLE_EQ(s.rate_dph, s.shupe_dph);
		peak = std::max(peak, std::abs(s.rate_dph));
	}
	EXPECT_GT(peak, 1e-3);
	for (int k = 0; k < 6 * 3600; k++) s = sim.advance(1.0, air(-35));  // soak 6 h
	EXPECT_LT(std::abs(s.rate_dph), 1e-4 * peak);
}

TEST(FogSimulator, ScaleFactorActsOnAppliedRate)
{
	FogDevice d = quietDevice();
	FogSimulator sim(d, {"scale_factor_temp"}, 1);
	sim.start(air(-15, true, 36000), InitialThermalState::Steady);
	const sim::FogSample s = sim.advance(0.1, air(-15, true, 36000));
	const double expected = 36000 * (1 + d.errors.sf_ppm_per_C() * 1e-6 * (s.coil_mean_C - d.errors.sf_ref_C));
	EXPECT_NEAR(s.rate_dph, expected, 1e-9 * 36000);
	EXPECT_DOUBLE_EQ(s.ideal_rate_dph, 36000.0);
}

TEST(FogSimulator, MagneticAndRadialGradientAreLinear)
{
	FogDevice d = quietDevice();
	FogSimulator mag(d, {"magnetic"}, 1);
	mag.start(air(25), InitialThermalState::Steady);
	EXPECT_NEAR(mag.advance(0.1, air(25, true, 0, 500)).rate_dph, 500 * d.errors.magnetic_dph_per_uT(), 1e-12);
	FogSimulator rg(d, {"radial_gradient"}, 1);
	rg.start(air(25), InitialThermalState::Steady);
	const sim::FogSample s = rg.advance(10.0, air(20));
	EXPECT_NEAR(s.rate_dph, d.errors.radial_gradient_dph_per_C() * (s.inner_C - s.outer_C), 1e-12);
}

TEST(FogSimulator, WarmupDecaysAfterPowerOn)
{
	FogDevice d = quietDevice();
	FogSimulator sim(d, {"warmup"}, 1);
	const sim::FogSample s0 = sim.start(air(23), InitialThermalState::Cold);
	EXPECT_NEAR(s0.rate_dph, d.errors.warmup_dph(), 1e-12);
	sim::FogSample s;
	for (int k = 0; k < 600; k++) s = sim.advance(1.0, air(23));
	EXPECT_NEAR(s.rate_dph, d.errors.warmup_dph() * std::exp(-1.0), 1e-9);
	// Power cycle restarts it; while off the output is 0.
	EXPECT_DOUBLE_EQ(sim.advance(1.0, air(23, false)).rate_dph, 0.0);
	EXPECT_NEAR(sim.advance(1.0, air(23, true)).rate_dph, d.errors.warmup_dph(), 1e-12);
}

TEST(FogSimulator, HysteresisDependsOnDirection)
{
	FogDevice d = quietDevice();
	FogSimulator sim(d, {"hysteresis"}, 1);
	sim.start(air(25), InitialThermalState::Steady);
	sim::FogSample s;
	// Cool by 60 C (12 spans) and soak: the cooling branch, -H/2 (to exp(-12) ~ 6e-6 of H).
	for (int k = 0; k < 3600; k++) s = sim.advance(1.0, air(25 - k / 60.0));
	for (int k = 0; k < 4 * 3600; k++) s = sim.advance(1.0, air(-35));
	EXPECT_NEAR(s.rate_dph, -0.5 * d.errors.hysteresis_dph(), 1e-3 * d.errors.hysteresis_dph());
	// Heat by 60 C and soak: the heating branch, +H/2.
	for (int k = 0; k < 3600; k++) s = sim.advance(1.0, air(-35 + k / 60.0));
	for (int k = 0; k < 4 * 3600; k++) s = sim.advance(1.0, air(25));
	EXPECT_NEAR(s.rate_dph, 0.5 * d.errors.hysteresis_dph(), 1e-3 * d.errors.hysteresis_dph());
}

TEST(FogSimulator, HeatSourceWarmsTheCoil)
{
	FogDevice d = quietDevice();
	FogSimulator on(d, {"heat_source"}, 1), off(d, {}, 1);
	const sim::FogSample a = on.start(air(20), InitialThermalState::Steady);
	const sim::FogSample b = off.start(air(20), InitialThermalState::Steady);
	EXPECT_GT(a.coil_mean_C, b.coil_mean_C + 0.5);
	EXPECT_NEAR(b.coil_mean_C, 20.0, 1e-9);
}

TEST(FogSimulator, ThermistorLagIsFirstOrder)
{
	// Hold the coil still, then read a thermistor whose node jumps: with lag it approaches the
	// node with time constant tau_s; without lag it reads the node.
	FogDevice d = quietDevice();
	for (auto& t : d.thermistors) t.offset_C = 0;
	FogSimulator lag(d, {"thermistor_lag"}, 1), nolag(d, {}, 1);
	lag.start(air(25), InitialThermalState::Steady);
	nolag.start(air(25), InitialThermalState::Steady);
	sim::FogSample a, b;
	for (int k = 0; k < 600; k++)
	{
		a = lag.advance(1.0, air(25 - k / 60.0));
		b = nolag.advance(1.0, air(25 - k / 60.0));
	}
	// Under a slow ramp a first-order sensor lags by ~ tau x rate of the node.
	const double node_rate = nolag.advance(1.0, air(25 - 600 / 60.0)).temp_C[1] - b.temp_C[1];  // C per s
	ASSERT_LT(node_rate, 0.0);  // cooling
	const double lag_C = a.temp_C[1] - b.temp_C[1];  // the lagging sensor reads warmer
	EXPECT_NEAR(lag_C, -d.thermistors[1].tau_s * node_rate, 0.03 * std::abs(d.thermistors[1].tau_s * node_rate));
}

TEST(FogSimulator, IdealTwinSharesNoiseAndQuantisesAngle)
{
	FogDevice d = FogDevice::defaultDevice();
	FogSimulator sim(d, {}, 42);
	sim.start(air(25), InitialThermalState::Steady);
	double sum_diff = 0, angle_full = 0;
	const double q = d.noise.angle_quantum_arcsec;
	for (int k = 0; k < 1000; k++)
	{
		const sim::FogSample s = sim.advance(0.1, air(25));
		sum_diff += std::abs(s.rate_dph - s.ideal_rate_dph);
		// Each output is a whole number of angle quanta per sample: rate x dt / q is an integer.
		const double counts = s.rate_dph * 0.1 / q;
		EXPECT_NEAR(counts, std::round(counts), 1e-6);
		angle_full += s.rate_dph;
	}
	// Only the constant bias separates them (no thermal effects): differences are the
	// quantised constant bias, never noise.
	EXPECT_NEAR(sum_diff / 1000, d.errors.constant_bias_dph, 2 * q / 0.1 / 1000 * 10);
}

TEST(FogSimulator, WhiteNoiseMatchesArw)
{
	// PHYSICS.md: ARW N [deg/sqrt h] at fs Hz has sigma = 60 N sqrt(fs) deg/h.
	FogDevice d = quietDevice();
	d.noise.arw_deg_rt_h = 0.002;
	FogSimulator sim(d, {}, 3);
	sim.start(air(25), InitialThermalState::Steady);
	double s2 = 0;
	const int n = 200000;
	for (int k = 0; k < n; k++)
	{
		const double r = sim.advance(0.1, air(25)).rate_dph;
		s2 += r * r;
	}
	const double sigma = std::sqrt(s2 / n), expected = 60 * 0.002 * std::sqrt(10.0);
	EXPECT_NEAR(sigma, expected, 4 * expected / std::sqrt(2.0 * n));  // 4 sigma of the estimate
}
