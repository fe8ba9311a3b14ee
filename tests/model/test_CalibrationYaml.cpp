/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <mrpt_fog/io/FogLogIO.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

#include "ScaleFactorFixture.h"
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
/** The std::invalid_argument message of parse(text, "cal.yaml"), or "" when it parses. */
template <class Parse>
std::string parseError(Parse parse, const std::string& text)
{
	try
	{
		parse(text, "cal.yaml");
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
std::string errorOf2(const std::string& text)
{
	return parseError([](const std::string& t, const std::string& src) { calibrationSetFromYaml(t, src); }, text);
}
std::string errorOf(const std::string& text)
{
	return parseError([](const std::string& t, const std::string& src) { calibrationFromYaml(t, src); }, text);
}
/** A one-exponential warm-up term: amplitude_dph * exp(-t / tau_s). */
WarmupModel warmupTerm(double amplitude_dph, double tau_s)
{
	WarmupModel w;
	w.amplitude_dph = amplitude_dph;
	w.tau_s = tau_s;
	return w;
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

// The extrapolation policy round-trips; a file without it (written before) reads as the
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
	const auto line = text.rfind('\n', p) + 1;  // the whole line (version 2: indented in bias)
	old.erase(line, text.find('\n', p) - line + 1);
	EXPECT_EQ(calibrationFromYaml(old, "cal.yaml").extrapolation, ExtrapolationPolicy::Linear);
	const std::string e = errorOf(replaced(text, "extrapolation: \"clamp\"", "extrapolation: \"cubic\""));
	EXPECT_NE(e.find("cal.yaml: axes[0].bias.extrapolation:"), std::string::npos) << e;
}

// The stability of the term choice is stored in the bias section and read back.
TEST(CalibrationYaml, SelectionStabilityRoundTrips)
{
	Calibration c = cal();
	c.selection_stability.resamples = 10;
	c.selection_stability.chosen_share = 0.4;
	c.selection_stability.stable = false;
	c.selection_stability.alternatives = {{"T(Ti1)^1 + dT/dt(Ti1)^1", 0.6, 0.0123}};
	const Calibration back = calibrationFromYaml(calibrationToYaml(c), "cal.yaml");
	EXPECT_EQ(back.selection_stability.resamples, 10u);
	EXPECT_EQ(back.selection_stability.chosen_share, 0.4);
	EXPECT_FALSE(back.selection_stability.stable);
	ASSERT_EQ(back.selection_stability.alternatives.size(), 1u);
	EXPECT_EQ(back.selection_stability.alternatives[0].terms, "T(Ti1)^1 + dT/dt(Ti1)^1");
	EXPECT_EQ(back.selection_stability.alternatives[0].share, 0.6);
	EXPECT_EQ(back.selection_stability.alternatives[0].held_out_rms_dph, 0.0123);
}

// The rate-free start-up model is stored in the bias section and read back exactly;
// a calibration without one writes none and reads back without one; a start-up model that reads
// a rate is refused with its field named.
TEST(CalibrationYaml, StartupModelRoundTripsAndIsChecked)
{
	ASSERT_TRUE(cal().startup.has_value());
	const Calibration back = calibrationFromYaml(calibrationToYaml(cal()), "cal.yaml");
	ASSERT_TRUE(back.startup.has_value());
	EXPECT_EQ(back.startup->coef_dph, cal().startup->coef_dph);
	EXPECT_EQ(back.startup->features.termNames(), cal().startup->features.termNames());
	Calibration none = cal();
	none.startup.reset();
	const std::string text = calibrationToYaml(none);
	EXPECT_EQ(text.find("startup_model"), std::string::npos);
	EXPECT_FALSE(calibrationFromYaml(text, "cal.yaml").startup.has_value());
	Calibration bad = cal();
	bad.startup = cal().model;  // reads dT/dt
	const std::string e = errorOf(calibrationToYaml(bad));
	EXPECT_NE(e.find("axes[0].bias.startup_model: reads the rate signal"), std::string::npos) << e;
}

// Every broken field gives "<file>: <field>: <reason>".
TEST(CalibrationYaml, BadFilesGiveFieldErrors)
{
	const std::string good = calibrationToYaml(cal());
	ASSERT_EQ(errorOf(good), "");
	// {text in the good file, its replacement, what the message must name}
	const std::vector<std::array<std::string, 3>> broken = {
		{"format: \"mrpt_fog_calibration\"", "format: \"other\"", "cal.yaml: format"},
		{"version: 2", "version: 7", "version"},
		{"window_s: 60", "window_s: abc", "rate_estimator.window_s: not a number"},
		{"kind: \"causal\"", "kind: \"kalman\"", "rate_estimator"},
		{"selection: \"auto\"", "selection: \"lasso\"", "axes[0].selection: selection must be 'auto' or 'none', got 'lasso'"},
		{"    - name: \"T(Ti1)^2\"", "    - name: \"T(Ti1)^9\"", "model.terms"},
		{"side: \"inner\"", "side: \"middle\"", "sensor.thermistors[0].side"},
		{"  - axis: \"z\"", "  - axis: \"q\"", "axes[0].axis"},
		{"latitude_deg: .nan", "latitude_deg: 91", "cal.yaml: latitude_deg"},
		{"handling: \"in_bias\"", "handling: \"ignored\"", "earth_rate.handling"},
		{"axes:\n", "axes: []\nother:\n", "axes"},
		{"    - name: \"To2\"\n", "    - name: \"Tq\"\n", "not in sensor.thermistors"},
		{"mean_bias_dph:", "mean_bias:", "mean_bias_dph: missing"},
		{"      scale: ", "      scale: -", ".scale"},
	};
	for (const auto& [from, to, named] : broken)
		EXPECT_NE(errorOf(replaced(good, from, to)).find(named), std::string::npos) << from << " -> " << to;
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

namespace
{
std::string dataPath(const std::string& name) { return std::string(FOG_SOURCE_DIR) + "/tests/data/model/" + name; }

/** A compensated CSV an earlier program wrote (time_s, raw, bias, compensated, flags, ...):
 * its time, bias and compensated columns. */
void readStoredCompensation(const std::string& path, std::vector<double>& time_s, std::vector<double>& bias_dph,
							std::vector<double>& comp_dph)
{
	std::ifstream in(path);
	ASSERT_TRUE(in.good()) << path;
	std::string line;
	while (std::getline(in, line))
	{
		if (line.empty() || line[0] == '#' || line[0] == 't') continue;
		std::stringstream ss(line);
		std::string cell;
		std::vector<std::string> cells;
		while (std::getline(ss, cell, ',')) cells.push_back(cell);
		ASSERT_GE(cells.size(), 4u) << path;
		time_s.push_back(std::stod(cells[0]));
		bias_dph.push_back(std::stod(cells[2]));
		comp_dph.push_back(std::stod(cells[3]));
	}
}
ScaleFactorModel someScaleFactor()
{
	ScaleFactorModel m = fogtest::scaleFactorModel("Ti1", {-300.0, 1000.0, 3.5});
	m.covariance_ppm2 = Eigen::MatrixXd::Identity(3, 3) * 0.25;
	m.slope_ppm_per_C = 20.0;
	m.slope_ci95_lo_ppm_per_C = 19.9;
	m.slope_ci95_hi_ppm_per_C = 20.1;
	m.slope_noise_ci95_lo_ppm_per_C = 19.95;
	m.slope_noise_ci95_hi_ppm_per_C = 20.02;
	m.slope_thermistor_min_ppm_per_C = 19.93;
	m.slope_thermistor_max_ppm_per_C = 20.08;
	m.slope_thermistors = 4;
	m.table_rate_min_abs_dph = 3600;
	m.table_rate_max_abs_dph = 36000;
	m.segments = 24;
	m.samples = 12345;
	m.rms_in_sample_ppm = 0.4;
	m.rms_held_out_ppm = 0.5;
	m.held_out_label = "leave-one-temperature-out";
	return m;
}
}  // namespace

// A version 1 file (written by fog-calibrate before version 2, tests/data/model/cal_v1_coil_A.yaml)
// still loads, as a single-axis bias-only calibration with latitude unknown, and compensates
// exactly as that program did (its fog-compensate output on coil_B is stored beside it).
TEST(CalibrationYaml, Version1FileLoadsAndCompensatesAsBefore)
{
	const Calibration v1 = loadCalibrationYaml(dataPath("cal_v1_coil_A.yaml"));
	EXPECT_EQ(v1.axis, GyroAxis::Z);
	EXPECT_TRUE(std::isnan(v1.latitude_deg));
	EXPECT_EQ(v1.earth_rate, EarthRateHandling::InBias);
	EXPECT_FALSE(v1.scale_factor.has_value());
	EXPECT_FALSE(v1.warmup.has_value());
	// the old program's output: time_s, raw, bias, compensated, flags, temperatures
	std::vector<double> time_old, bias_old, comp_old;
	ASSERT_NO_FATAL_FAILURE(readStoredCompensation(dataPath("comp_v1_coil_B.csv"), time_old, bias_old, comp_old));
	const FogSeries b = readFogLog(dataPath("coil_B.csv"));
	const CompensatedSeries now = compensate(v1, b);
	ASSERT_GT(bias_old.size(), 600u);
	std::size_t k = 0;
	for (std::size_t i = 0; i < bias_old.size(); i++)
	{
		while (k < now.time_s.size() && now.time_s[k] < time_old[i]) k++;
		ASSERT_LT(k, now.time_s.size());
		ASSERT_EQ(now.time_s[k], time_old[i]);
		// the CSV holds 17 significant digits: the same double
		ASSERT_EQ(now.bias_dph[k], bias_old[i]) << k;
		ASSERT_EQ(now.compensated_dph[k], comp_old[i]) << k;
	}
	// ... and so does the same calibration written as version 2 and read back.
	const std::string v2 = calibrationToYaml(v1);
	EXPECT_NE(v2.find("version: 2"), std::string::npos);
	const Calibration back = calibrationFromYaml(v2, "v2.yaml");
	EXPECT_EQ(compensate(back, b).compensated_dph, now.compensated_dph);
}

// A version 2 file written before three-axis calibration existed (main 94910e2: bias + scale
// factor + warm-up from the bundled datasets, tests/data/model/cal_v2_full_A.yaml) still loads
// and compensates exactly as that program's fog-compensate did on coil_B (stored beside it),
// and writing it again gives the same text.
TEST(CalibrationYaml, Version2FileFromBeforeTheTriadLoadsAndCompensatesAsBefore)
{
	std::ifstream f(dataPath("cal_v2_full_A.yaml"));
	const std::string text((std::istreambuf_iterator<char>(f)), std::istreambuf_iterator<char>());
	const Calibration v2 = calibrationFromYaml(text, "cal_v2_full_A.yaml");
	EXPECT_EQ(v2.axis, GyroAxis::Z);
	EXPECT_TRUE(v2.scale_factor.has_value());
	EXPECT_TRUE(v2.warmup.has_value());
	EXPECT_EQ(calibrationToYaml(v2), text);
	std::vector<double> time_old, bias_old, comp_old;
	ASSERT_NO_FATAL_FAILURE(readStoredCompensation(dataPath("comp_v2_coil_B.csv"), time_old, bias_old, comp_old));
	const FogSeries b = readFogLog(dataPath("coil_B.csv"));
	const CompensatedSeries now = compensate(v2, b);
	ASSERT_EQ(now.time_s.size(), time_old.size());
	for (std::size_t k = 0; k < time_old.size(); k++)
	{
		ASSERT_EQ(now.time_s[k], time_old[k]);
		ASSERT_EQ(now.bias_dph[k], bias_old[k]) << k;
		ASSERT_EQ(now.compensated_dph[k], comp_old[k]) << k;
	}
	// a set of three such axes (x, y, z) round-trips, each axis compensating as the original
	CalibrationSet set;
	for (GyroAxis a : {GyroAxis::X, GyroAxis::Y, GyroAxis::Z})
	{
		Calibration c = v2;
		c.axis = a;
		set.axes.push_back(c);
	}
	const CalibrationSet back = calibrationSetFromYaml(calibrationSetToYaml(set), "set.yaml");
	ASSERT_EQ(back.axes.size(), 3u);
	EXPECT_EQ(back.axes[1].axis, GyroAxis::Y);
	EXPECT_EQ(calibrationSetToYaml(back), calibrationSetToYaml(set));
}

// The warm-up's optional second term and start-up offset round-trip exactly; a bad second time
// constant is a field error; absent, the file reads as one term and no offset.
TEST(CalibrationYaml, WarmupSecondTermAndStartupOffsetRoundTrip)
{
	Calibration c = cal();
	WarmupModel w = warmupTerm(0.45, 140);
	w.amplitude2_dph = 0.08;
	w.tau2_s = 520;
	w.amplitude2_std_dph = 0.03;
	w.tau2_std_s = 120;
	w.startup_offset_dph = -1.9;
	w.startup_offset_std_dph = 0.008;
	w.startup_samples = 600;
	c.warmup = w;
	const std::string text = calibrationToYaml(c);
	const Calibration back = calibrationFromYaml(text, "c.yaml");
	ASSERT_TRUE(back.warmup);
	EXPECT_EQ(back.warmup->amplitude2_dph, 0.08);
	EXPECT_EQ(back.warmup->tau2_s, 520.0);
	EXPECT_EQ(back.warmup->tau2_std_s, 120.0);
	EXPECT_EQ(back.warmup->startup_offset_dph, -1.9);
	EXPECT_EQ(back.warmup->startup_samples, 600u);
	EXPECT_EQ(calibrationToYaml(back), text);
	EXPECT_DOUBLE_EQ(back.warmup->bias_dph(100.0), 0.45 * std::exp(-100.0 / 140) + 0.08 * std::exp(-100.0 / 520));
	EXPECT_NE(errorOf(replaced(text, "tau2_s: 520", "tau2_s: 0")).find("axes[0].warmup.tau2_s"), std::string::npos);
	c.warmup = warmupTerm(0.1, 600);
	const std::string plain = calibrationToYaml(c);
	EXPECT_EQ(plain.find("tau2_s"), std::string::npos);
	EXPECT_EQ(plain.find("startup_offset_dph"), std::string::npos);
	const Calibration b1 = calibrationFromYaml(plain, "p.yaml");
	EXPECT_FALSE(b1.warmup->hasSecondTerm());
	EXPECT_EQ(b1.warmup->startup_offset_dph, 0.0);
}

// The optional sections round-trip exactly; absent they stay absent.
TEST(CalibrationYaml, ScaleFactorAndWarmupRoundTrip)
{
	Calibration c = cal();
	c.latitude_deg = 40.0;
	c.earth_rate = EarthRateHandling::InTableRate;
	c.scale_factor = someScaleFactor();
	WarmupModel w = warmupTerm(0.1, 600);
	w.amplitude_std_dph = 0.001;
	w.tau_std_s = 12;
	w.fitted_span_s = 5400;
	w.turn_ons = 1;
	w.samples = 54000;
	w.rms_before_dph = 0.03;
	w.rms_after_dph = 0.006;
	c.warmup = w;
	const Calibration back = calibrationFromYaml(calibrationToYaml(c), "c.yaml");
	EXPECT_EQ(back.latitude_deg, 40.0);
	EXPECT_EQ(back.earth_rate, EarthRateHandling::InTableRate);
	ASSERT_TRUE(back.scale_factor && back.warmup);
	const auto& s = *back.scale_factor;
	EXPECT_EQ(s.thermistor, "Ti1");
	EXPECT_EQ(s.coef_ppm, c.scale_factor->coef_ppm);
	EXPECT_EQ(s.covariance_ppm2, c.scale_factor->covariance_ppm2);
	EXPECT_EQ(s.min_C, -40.0);
	EXPECT_EQ(s.slope_ci95_hi_ppm_per_C, 20.1);
	EXPECT_EQ(s.slope_noise_ci95_lo_ppm_per_C, 19.95);
	EXPECT_EQ(s.slope_thermistor_max_ppm_per_C, 20.08);
	EXPECT_EQ(s.slope_thermistors, 4u);
	EXPECT_EQ(s.table_rate_max_abs_dph, 36000.0);
	EXPECT_EQ(s.held_out_label, "leave-one-temperature-out");
	EXPECT_EQ(back.warmup->tau_s, 600.0);
	EXPECT_EQ(back.warmup->amplitude_dph, 0.1);
	EXPECT_EQ(back.warmup->turn_ons, 1u);
	EXPECT_EQ(calibrationToYaml(back), calibrationToYaml(c));
	const Calibration plain = calibrationFromYaml(calibrationToYaml(cal()), "p.yaml");
	EXPECT_FALSE(plain.scale_factor || plain.warmup);
	EXPECT_EQ(calibrationToYaml(cal()).find("scale_factor:"), std::string::npos);
	// broken optional sections give field errors
	const std::string good = calibrationToYaml(c);
	EXPECT_NE(errorOf(replaced(good, "scale_C: 50", "scale_C: 0")).find("axes[0].scale_factor.scale_C"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "thermistor: \"Ti1\"", "thermistor: \"Tx\"")).find("scale_factor.thermistor"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "tau_s: 600", "tau_s: -1")).find("axes[0].warmup.tau_s"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "slope_thermistors: 4", "slope_thermistors: 2.5")).find("scale_factor.slope_thermistors"), std::string::npos);
	// a file from before the widened interval (no slope_thermistors) still loads
	std::string old = good;
	for (const char* key : {"  slope_noise_ci95_ppm_per_C:", "  slope_thermistor_range_ppm_per_C:", "  slope_thermistors:"})
	{
		const auto at = old.find(key);
		ASSERT_NE(at, std::string::npos) << key;
		old.erase(old.rfind('\n', at) + 1, old.find('\n', at) - old.rfind('\n', at));
	}
	const Calibration before = calibrationFromYaml(old, "old.yaml");
	EXPECT_EQ(before.scale_factor->slope_thermistors, 0u);
	EXPECT_EQ(before.scale_factor->slope_ci95_hi_ppm_per_C, 20.1);
	EXPECT_NE(errorOf(replaced(good, "coef_ppm: [-300, 1000, 3.5]", "coef_ppm: [-300, x]")).find("coef_ppm[1]: not a number"), std::string::npos);
}

// A scale factor in a weighted sum of thermistors (the coil temperature estimate fitted from
// table segments in transients) round-trips; its weights must match the thermistors and sum to 1.
TEST(CalibrationYaml, WeightedScaleFactorRoundTripAndErrors)
{
	Calibration c = cal();
	ScaleFactorModel m = someScaleFactor();
	m.thermistor = "weighted";
	for (const auto& t : c.layout) m.thermistors.push_back(t.name);
	ASSERT_GE(m.thermistors.size(), 2u);
	m.weights.assign(m.thermistors.size(), 0.0);
	m.weights[0] = 1.25;
	m.weights[1] = -0.25;
	c.scale_factor = m;
	const std::string good = calibrationToYaml(c);
	const Calibration back = calibrationFromYaml(good, "w.yaml");
	ASSERT_TRUE(back.scale_factor);
	EXPECT_EQ(back.scale_factor->thermistor, "weighted");
	EXPECT_EQ(back.scale_factor->thermistors, m.thermistors);
	EXPECT_EQ(back.scale_factor->weights, m.weights);
	EXPECT_EQ(calibrationToYaml(back), good);
	// the compensator reads T = 1.25 x first - 0.25 x second: equal readings give that reading
	std::vector<double> temps(c.layout.size(), 30.0);
	temps[1] = 34.0;  // T = 1.25 x 30 - 0.25 x 34 = 29
	Compensator comp(back, back.layout);
	const double raw = 36000.0;
	Compensator::Output o{};
	for (int k = 0; k < 200; k++) o = comp.step(k * 1.0, raw, temps.data());
	EXPECT_NEAR((raw - o.bias_dph) / o.compensated_dph - 1.0, 1e-6 * m.evaluate_ppm(29.0), 1e-12);
	const auto at = good.find("weights: [");
	ASSERT_NE(at, std::string::npos);
	const std::string line = good.substr(at, good.find(']', at) + 1 - at);
	EXPECT_NE(errorOf(replaced(good, line, "weights: [1.25, -0.25]" + std::string(m.weights.size() > 2 ? "" : ", 0"))).find("scale_factor.weights"),
			  std::string::npos);
	std::string two_more = "weights: [1.25, 0.25";
	for (std::size_t i = 2; i < m.weights.size(); i++) two_more += ", 0";
	EXPECT_NE(errorOf(replaced(good, line, two_more + "]")).find("must sum to 1"), std::string::npos);
	EXPECT_NE(errorOf(replaced(good, "thermistor: \"weighted\"", "thermistor: \"mean\"")).find("scale_factor.thermistor"),
			  std::string::npos);
}

// Several axes in one file: single-axis loading says which axes there are; by axis it works.
TEST(CalibrationYaml, SeveralAxesInOneFile)
{
	Calibration x = cal(), z = cal();
	x.axis = GyroAxis::X;
	x.scale_factor = someScaleFactor();
	const CalibrationSet set{{x, z}};
	const std::string text = calibrationSetToYaml(set);
	const CalibrationSet back = calibrationSetFromYaml(text, "xz.yaml");
	ASSERT_EQ(back.axes.size(), 2u);
	ASSERT_NE(back.forAxis(GyroAxis::X), nullptr);
	EXPECT_TRUE(back.forAxis(GyroAxis::X)->scale_factor.has_value());
	EXPECT_FALSE(back.forAxis(GyroAxis::Z)->scale_factor.has_value());
	EXPECT_EQ(back.forAxis(GyroAxis::Y), nullptr);
	EXPECT_EQ(calibrationFromYaml(text, "xz.yaml", GyroAxis::Z).model.coef_dph, z.model.coef_dph);
	try
	{
		calibrationFromYaml(text, "xz.yaml");
		ADD_FAILURE() << "no error for a two-axis file read as one axis";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("xz.yaml: axes: holds 2 axes (x, z)"), std::string::npos) << e.what();
	}
	EXPECT_THROW(calibrationFromYaml(text, "xz.yaml", GyroAxis::Y), std::invalid_argument);
	// the same axis twice, or axes that disagree on the sensor, are refused
	EXPECT_THROW(calibrationSetToYaml(CalibrationSet{{z, z}}), std::invalid_argument);
	Calibration other = x;
	other.latitude_deg = 10;
	EXPECT_THROW(calibrationSetToYaml(CalibrationSet{{other, z}}), std::invalid_argument);
	std::string twice = text;
	const std::string x_entry = "  - axis: \"x\"";
	const auto p = twice.find(x_entry);
	ASSERT_NE(p, std::string::npos);
	twice.replace(p, x_entry.size(), "  - axis: \"z\"");
	EXPECT_NE(errorOf2(twice).find("axes[1].axis"), std::string::npos);
}

// The fit records the runs' common latitude (unknown when they disagree or do not say).
TEST(CalibrationYaml, LatitudeFromTheRuns)
{
	FogSeries a = fogtest::makeCoilRun("A", 61), b = fogtest::makeCoilRun("B", 62);
	EXPECT_TRUE(std::isnan(commonLatitude_deg({a})));
	a.setMetadata("latitude_deg", "45.5");
	EXPECT_EQ(commonLatitude_deg({a}), 45.5);
	b.setMetadata("latitude_deg", "45.5");
	EXPECT_EQ(commonLatitude_deg({a, b}), 45.5);
	b.setMetadata("latitude_deg", "30");
	EXPECT_TRUE(std::isnan(commonLatitude_deg({a, b})));
	a.resize(8000);
	const Calibration c = fitCalibration({a}, "M2:Ti1");
	EXPECT_EQ(c.latitude_deg, 45.5);
	EXPECT_EQ(calibrationFromYaml(calibrationToYaml(c), "c.yaml").latitude_deg, 45.5);
}
