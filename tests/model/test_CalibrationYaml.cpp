/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <cstdio>
#include <fstream>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
const Calibration& cal()
{
	static const Calibration c = fitCalibration({fogtest::makeCoilRun("A", 61)}, "multipoint");
	return c;
}
std::string replaced(std::string s, const std::string& from, const std::string& to)
{
	const auto p = s.find(from);
	EXPECT_NE(p, std::string::npos) << from;
	if (p != std::string::npos) s.replace(p, from.size(), to);
	return s;
}
std::string errorOf(const std::string& text)
{
	try
	{
		calibrationFromYaml(text, "cal.yaml");
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

// Exact round trip: identical coefficients, normalisation, and bit-identical compensation.
TEST(CalibrationYaml, RoundTripIsExact)
{
	const std::string path = std::string(FOG_BINARY_DIR) + "/test_cal_roundtrip.yaml";
	saveCalibrationYaml(cal(), path);
	const Calibration back = loadCalibrationYaml(path);
	EXPECT_EQ(back.model.coef_dph, cal().model.coef_dph);
	EXPECT_EQ(back.model.features.termNames(), cal().model.features.termNames());
	EXPECT_EQ(back.fallbacks.size(), cal().fallbacks.size());
	EXPECT_EQ(back.layout, cal().layout);
	EXPECT_TRUE(back.rate_estimator == cal().rate_estimator);
	EXPECT_EQ(back.model.covariance, cal().model.covariance);
	EXPECT_EQ(back.in_sample.stability_dph, cal().in_sample.stability_dph);
	EXPECT_EQ(back.held_out.label, cal().held_out.label);
	EXPECT_EQ(back.in_sample.valid, cal().in_sample.valid);
	EXPECT_TRUE(back.in_sample.valid);
	EXPECT_EQ(back.fallbacks[0].dropped, cal().fallbacks[0].dropped);
	EXPECT_EQ(back.mean_bias_dph, cal().mean_bias_dph);
	FogSeries s = fogtest::makeCoilRun("B", 62);
	s.resize(3000);
	EXPECT_EQ(compensate(back, s).bias_dph, compensate(cal(), s).bias_dph);
	std::remove(path.c_str());
}

// The extrapolation policy round-trips; a file without it (written before issue 11) reads as the
// default (linear); an unknown policy is a field error.
TEST(CalibrationYaml, ExtrapolationPolicyIsStored)
{
	Calibration clamp = cal();
	clamp.extrapolation = ExtrapolationPolicy::Clamp;
	const std::string text = calibrationToYaml(clamp);
	EXPECT_EQ(calibrationFromYaml(text, "cal.yaml").extrapolation, ExtrapolationPolicy::Clamp);
	const auto p = text.find("extrapolation: ");
	ASSERT_NE(p, std::string::npos);
	std::string old = text;
	old.erase(p, text.find('\n', p) - p + 1);
	EXPECT_EQ(calibrationFromYaml(old, "cal.yaml").extrapolation, ExtrapolationPolicy::Linear);
	const std::string e = errorOf(replaced(text, "extrapolation: \"clamp\"", "extrapolation: \"cubic\""));
	EXPECT_NE(e.find("cal.yaml: extrapolation:"), std::string::npos) << e;
}

// Every broken field gives "<file>: <field>: <reason>".
TEST(CalibrationYaml, BadFilesGiveFieldErrors)
{
	const std::string good = calibrationToYaml(cal());
	ASSERT_EQ(errorOf(good), "");
	EXPECT_NE(errorOf(replaced(good, "format: \"mrpt_fog_calibration\"", "format: \"other\"")).find("cal.yaml: format"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "version: 1", "version: 7")).find("version"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "window_s: 60", "window_s: abc")).find("rate_estimator.window_s: not a number"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "kind: \"causal\"", "kind: \"kalman\"")).find("rate_estimator"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "    - name: \"T(Ti1)^2\"", "    - name: \"T(Ti1)^9\"")).find("model.terms"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "side: \"inner\"", "side: \"middle\"")).find("sensor.thermistors[0].side"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "  axis: \"z\"", "  axis: \"q\"")).find("sensor.axis"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "    - name: \"To2\"\n", "    - name: \"Tq\"\n")).find("not in sensor.thermistors"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "mean_bias_dph:", "mean_bias:")).find("mean_bias_dph: missing"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "      scale: ", "      scale: -")).find(".scale"), std::string::npos);
	EXPECT_NE(errorOf("a: [unclosed").find("cal.yaml"), std::string::npos);
	EXPECT_NE(errorOf("- 1\n- 2\n").find("cal.yaml"), std::string::npos);
	// a fallback that uses the thermistor it replaces
	const std::string fb = "  - dropped: \"" + cal().fallbacks[0].dropped + "\"";
	const std::string other = cal().fallbacks[1].dropped;
	EXPECT_NE(errorOf(replaced(good, fb, "  - dropped: \"" + other + "\"")).find("fallbacks[0]"), std::string::npos);
	EXPECT_THROW(loadCalibrationYaml("/nonexistent/cal.yaml"), std::invalid_argument);
}

TEST(CalibrationYaml, SaveIsAtomic)
{
	EXPECT_THROW(saveCalibrationYaml(cal(), "/nonexistent_dir/cal.yaml"), std::exception);
	const std::string path = std::string(FOG_BINARY_DIR) + "/test_cal_atomic.yaml";
	{
		std::ofstream(path) << "previous";
	}
	saveCalibrationYaml(cal(), path);
	EXPECT_EQ(loadCalibrationYaml(path).model.coef_dph, cal().model.coef_dph);
	std::remove(path.c_str());
}

// A one-thermistor calibration: its fallback (without that thermistor) is constant-only, with
// no signals. It must save and load (an empty "signals:" block once read back as null).
TEST(CalibrationYaml, OneThermistorCalibrationWithConstantFallbackRoundTrips)
{
	const Calibration one = fitCalibration({fogtest::makeCoilRun("A", 61)}, "multipoint:Ti1");
	ASSERT_EQ(one.fallbacks.size(), 1u);
	ASSERT_TRUE(one.fallbacks[0].features.signals().empty());
	const std::string path = std::string(FOG_BINARY_DIR) + "/test_cal_one_thermistor.yaml";
	saveCalibrationYaml(one, path);
	const Calibration back = loadCalibrationYaml(path);
	EXPECT_EQ(back.fallbacks.size(), 1u);
	EXPECT_EQ(back.fallbacks[0].coef_dph, one.fallbacks[0].coef_dph);
	EXPECT_EQ(back.model.coef_dph, one.model.coef_dph);
	std::remove(path.c_str());
}
