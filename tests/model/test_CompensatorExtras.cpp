/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// The compensator's optional stages (calibration version 2): warm-up term and scale factor vs
// temperature, checked against the closed form applied to the bias-only compensator's output.
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <cmath>

#include "ScaleFactorFixture.h"
#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
const Calibration& biasOnly()
{
	static const Calibration cal = [] {
		FogSeries a = fogtest::makeCoilRun("A", 71);
		return fitCalibration({a}, "multipoint");
	}();
	return cal;
}
/** The run with a 1 deg/s table rate on its raw output, so that the scale factor matters. */
FogSeries onTurningTable(FogSeries run)
{
	for (auto& r : run.rate_dph[2]) r += 3600.0;
	return run;
}
ScaleFactorModel linearSf(double ppm_per_C)
{
	return fogtest::scaleFactorModel("To1", {100.0, ppm_per_C * 50});  // s = 100 + k (T - 10)
}
}  // namespace

// Without the optional sections the compensation is exactly the bias-only one (same doubles).
TEST(CompensatorExtras, AbsentSectionsChangeNothing)
{
	FogSeries b = fogtest::makeCoilRun("B", 72);
	b.setMetadata("power_on_time_s", "0");
	const CompensatedSeries x = compensate(biasOnly(), b);
	Calibration same = biasOnly();
	EXPECT_FALSE(same.scale_factor || same.warmup);
	EXPECT_EQ(compensate(same, b).compensated_dph, x.compensated_dph);
	for (std::size_t k = 0; k < x.compensated_dph.size(); k++)
		ASSERT_EQ(x.compensated_dph[k], x.raw_dph[k] - x.bias_dph[k]);
}

// omega = (raw - bias - A exp(-(t - t_on)/tau)) / (1 + 1e-6 (100 + 20 (clamp(To1) - 10)))
TEST(CompensatorExtras, ScaleFactorAndWarmupFollowTheClosedForm)
{
	FogSeries b = onTurningTable(fogtest::makeCoilRun("B", 73));
	const CompensatedSeries plain = compensate(biasOnly(), b);
	Calibration cal = biasOnly();
	cal.scale_factor = linearSf(20.0);
	WarmupModel w;
	w.amplitude_dph = 0.2;
	w.tau_s = 900;
	cal.warmup = w;
	const double t_on = 1234.5;
	b.setMetadata("power_on_time_s", "1234.5");
	const CompensatedSeries out = compensate(cal, b);
	const int col = b.thermistorIndex("To1");
	for (std::size_t k = 0; k < b.size(); k++)
	{
		const double t = b.time_s[k];
		const double warm = t >= t_on ? 0.2 * std::exp(-(t - t_on) / 900.0) : 0.0;
		const double T = std::min(60.0, std::max(-40.0, b.temp_C[col][k]));
		const double s_ppm = 100.0 + 20.0 * (T - 10.0);
		const double expect = (plain.raw_dph[k] - plain.bias_dph[k] - warm) / (1 + 1e-6 * s_ppm);
		ASSERT_NEAR(out.compensated_dph[k], expect, 1e-9 * std::abs(expect)) << k;
		ASSERT_NEAR(out.bias_dph[k], plain.bias_dph[k] + warm, 1e-12) << k;
	}
	// with an unknown turn-on no warm-up term is added
	b.setMetadata("power_on_time_s", "");
	FogSeries c = onTurningTable(fogtest::makeCoilRun("B", 73));
	Calibration only_warm = biasOnly();
	only_warm.warmup = w;
	EXPECT_EQ(compensate(only_warm, c).compensated_dph, plain.compensated_dph);
}

// The start-up offset is added exactly where the rate-free start-up model runs in the first rate
// window after a turn-on, on top of the exponential terms; with the turn-on later, nowhere.
TEST(CompensatorExtras, StartupOffsetOnlyWhileTheStartupModelRunsAfterATurnOn)
{
	FogSeries b = fogtest::makeCoilRun("B", 77);
	const double t_on = b.time_s.front();
	b.setMetadata("power_on_time_s", std::to_string(t_on));
	const CompensatedSeries plain = compensate(biasOnly(), b);
	Calibration cal = biasOnly();
	ASSERT_TRUE(cal.startup.has_value()) << "the test needs a model with rates and its start-up model";
	WarmupModel w;
	w.amplitude_dph = 0.2;
	w.tau_s = 900;
	w.amplitude2_dph = -0.05;
	w.tau2_s = 3000;
	w.startup_offset_dph = -1.5;
	cal.warmup = w;
	const CompensatedSeries out = compensate(cal, b);
	std::size_t with_offset = 0;
	for (std::size_t k = 0; k < b.size(); k++)
	{
		const double dt = b.time_s[k] - t_on;
		const bool startup = (plain.flags[k] & CompensationFlag::RateFree) != 0 && dt <= cal.rate_estimator.window_s;
		with_offset += startup;
		const double extra = 0.2 * std::exp(-dt / 900.0) - 0.05 * std::exp(-dt / 3000.0) + (startup ? -1.5 : 0.0);
		ASSERT_NEAR(out.bias_dph[k] - plain.bias_dph[k], extra, 1e-12) << k;
	}
	EXPECT_GT(with_offset, 0u);
	EXPECT_LT(with_offset, b.size() / 10);
	// a turn-on after the start-up window: the exponentials from there, the offset nowhere
	const double later = t_on + 1000.0;
	b.setMetadata("power_on_time_s", std::to_string(later));
	const CompensatedSeries out2 = compensate(cal, b);
	for (std::size_t k = 0; k < b.size(); k++)
	{
		const double dt = b.time_s[k] - later;
		const double extra = dt >= 0 ? 0.2 * std::exp(-dt / 900.0) - 0.05 * std::exp(-dt / 3000.0) : 0.0;
		ASSERT_NEAR(out2.bias_dph[k] - plain.bias_dph[k], extra, 1e-12) << k;
	}
}

// A power step 0 -> 1 restarts the warm-up term; a missing scale-factor thermistor holds s.
TEST(CompensatorExtras, TurnOnFromThePowerColumnAndHeldScaleFactor)
{
	FogSeries b = fogtest::makeCoilRun("B", 74);
	const std::size_t off = 1000, on = 1200;
	b.power.assign(b.size(), 1.0);
	for (std::size_t k = off; k < on; k++) b.power[k] = 0.0;
	Calibration cal = biasOnly();
	WarmupModel w;
	w.amplitude_dph = 0.5;
	w.tau_s = 300;
	cal.warmup = w;
	const CompensatedSeries plain = compensate(biasOnly(), b), out = compensate(cal, b);
	for (std::size_t k = 0; k < b.size(); k++)
	{
		const double extra = k >= on ? 0.5 * std::exp(-(b.time_s[k] - b.time_s[on]) / 300.0) : 0.0;
		ASSERT_NEAR(out.bias_dph[k] - plain.bias_dph[k], extra, 1e-12) << k;
	}
	// scale factor thermistor drops out from sample 500 on: s stays at its last value
	FogSeries d = fogtest::makeCoilRun("B", 75);
	const int col = d.thermistorIndex("To1");
	const double held_T = d.temp_C[col][499];
	for (std::size_t k = 500; k < 700; k++) d.temp_C[col][k] = std::nan("");
	Calibration sf = biasOnly();
	sf.scale_factor = linearSf(20.0);
	sf.fallbacks.clear();  // the bias falls back to the mean: irrelevant here, the ratio is checked
	const CompensatedSeries o = compensate(sf, d);
	for (std::size_t k = 500; k < 700; k++)
	{
		const double ratio = (o.raw_dph[k] - o.bias_dph[k]) / o.compensated_dph[k];
		ASSERT_NEAR(ratio, 1 + 1e-6 * (100.0 + 20.0 * (held_T - 10.0)), 1e-12) << k;
	}
	// a layout without the scale-factor thermistor is refused
	FogSeries e = fogtest::makeCoilRun("B", 76);
	Calibration other = biasOnly();
	other.scale_factor = linearSf(20.0);
	other.scale_factor->thermistor = "Tx";
	EXPECT_THROW(compensate(other, e), std::invalid_argument);
}

// A scale factor in the mean of several thermistors (fog-calibrate --sf-temperature mean):
// s from (Ti1 + To1) / 2, closed form on the bias-only output; it round-trips through the file.
TEST(CompensatorExtras, ScaleFactorInTheMeanOfThermistors)
{
	FogSeries b = onTurningTable(fogtest::makeCoilRun("B", 74));
	const CompensatedSeries plain = compensate(biasOnly(), b);
	Calibration cal = biasOnly();
	cal.scale_factor = linearSf(20.0);
	cal.scale_factor->thermistor = "mean";
	cal.scale_factor->thermistors = {"Ti1", "To1"};
	cal.scale_factor->covariance_ppm2 = Eigen::MatrixXd::Identity(2, 2);  // the file needs one
	const CompensatedSeries out = compensate(cal, b);
	const int i1 = b.thermistorIndex("Ti1"), o1 = b.thermistorIndex("To1");
	for (std::size_t k = 0; k < b.size(); k++)
	{
		const double T = std::min(60.0, std::max(-40.0, 0.5 * (b.temp_C[i1][k] + b.temp_C[o1][k])));
		const double expect = (plain.raw_dph[k] - plain.bias_dph[k]) / (1 + 1e-6 * (100.0 + 20.0 * (T - 10.0)));
		ASSERT_NEAR(out.compensated_dph[k], expect, 1e-9 * std::abs(expect)) << k;
	}
	const Calibration back = calibrationFromYaml(calibrationToYaml(cal), "mean.yaml");
	ASSERT_TRUE(back.scale_factor.has_value());
	EXPECT_EQ(back.scale_factor->thermistors, cal.scale_factor->thermistors);
	EXPECT_EQ(compensate(back, b).compensated_dph, out.compensated_dph);
	// a listed thermistor outside the layout is a field error
	std::string text = calibrationToYaml(cal);
	text.replace(text.find("thermistors: [\"Ti1\", \"To1\"]"), 27, "thermistors: [\"Ti1\", \"Tx9\"]");
	EXPECT_THROW(calibrationFromYaml(text, "bad.yaml"), std::invalid_argument);
}
