/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// Calibration with hysteresis signals (hyst(a,play|branch,w), HysteresisFilter.h): a
// one-thermistor run whose bias is a known function of the reading and of a play operator of
// it (computed here, on the closed form of the play: p follows the reading at distance w);
// fit, compensator, batch vs streaming, the two kernel builds and the calibration file.
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/CompensatorKernel.h>  // internal: detail::cpuHasAvx2

#include <algorithm>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "PiecewiseHistory.h"

using namespace mrpt_fog;

namespace
{
constexpr double kWidth_C = 2.0, kHystCoef = 0.3;  // play half-width [degC], bias per unit output [deg/h]

using fogtest::piecewise;

/** 1 Hz run of one thermistor Ti1 following `knots`; bias = 0.8 + 0.004 T + kHystCoef h with h
 * the play of half-width kWidth_C, p = T(0) at the start: h = (T - p) / w, p clamped to
 * [T - w, T + w] (written out here, not the filter under test). */
FogSeries hystRun(const std::vector<std::pair<double, double>>& knots)
{
	FogSeries s;
	s.sensor_label = "FOG";
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}};
	s.has_axis = {{false, false, true}};
	s.temp_C.assign(1, {});
	double p = piecewise(knots, 0);
	for (int k = 0; k <= knots.back().first; k++)
	{
		const double x = piecewise(knots, k);
		if (p < x - kWidth_C) p = x - kWidth_C;
		if (p > x + kWidth_C) p = x + kWidth_C;
		s.time_s.push_back(k);
		s.temp_C[0].push_back(x);
		s.rate_dph[2].push_back(0.8 + 0.004 * x + kHystCoef * (x - p) / kWidth_C);
	}
	return s;
}

// A: 25 -> -10 C, soak, -> 40 C, soak, -> 20 C (three reversals). B: a +-5 C triangle wave and
// small +-1 C reversals inside the play: another history, held out.
FogSeries runA() { return hystRun({{0, 25}, {2100, -10}, {5700, -10}, {8700, 40}, {12300, 40}, {13500, 20}, {15000, 20}}); }
FogSeries runB()
{
	return hystRun({{0, 10}, {900, 40}, {2700, 40}, {5100, 20}, {5700, 25}, {6300, 15}, {6900, 25}, {7500, 15},
					{7700, 16}, {7900, 15}, {8100, 16}, {9000, 16}});
}

Calibration fitted(const std::string& terms)
{
	FitOptions o;
	o.selection = TermSelection::None;
	return fitCalibration({runA()}, "terms:" + terms, o);
}

/** Independent evaluation of a model on a series: the feature set's generic signal path, with a
 * hysteresis bank fed here sample by sample (no compensator kernel, no Horner). */
std::vector<double> featureBias(const BiasModel& m, const FogSeries& s)
{
	const auto& fs = m.features;
	HysteresisFilterBank bank(fs.hystereses());
	std::vector<double> out, temp(fs.thermistors().size()), rate(temp.size(), 0.0), h(fs.hystereses().size()),
		v(fs.signals().size()), f(fs.termCount());
	for (std::size_t k = 0; k < s.size(); k++)
	{
		for (std::size_t i = 0; i < temp.size(); i++) temp[i] = s.temp_C[s.thermistorIndex(fs.thermistors()[i])][k];
		bank.push(temp.data());
		for (std::size_t i = 0; i < h.size(); i++) h[i] = bank.value(i);
		fs.signalValues(temp.data(), rate.data(), nullptr, h.data(), v.data());
		fs.features(v.data(), f.data(), false);
		double b = 0;
		for (std::size_t i = 0; i < f.size(); i++) b += m.coef_dph[i] * f[i];
		out.push_back(b);
	}
	return out;
}
}  // namespace

TEST(HysteresisCalibration, TermNamesParseAndPrint)
{
	for (const std::string n : {"hyst(Ti1,play,2C)^1", "hyst(To2,branch,0.5C)^1", "hyst(Ca,play,12.25C)^1"})
		EXPECT_EQ(ThermalTerm::parse(n).name(), n);
	const ThermalTerm t = ThermalTerm::parse(" hyst(Ti1,branch,5C) ");
	EXPECT_EQ(t.signal.kind, SignalKind::Hysteresis);
	EXPECT_EQ(t.signal.hyst_op, HysteresisOperator::Branch);
	EXPECT_EQ(t.signal.width_C, 5.0);
	EXPECT_EQ(t.power, 1);
	EXPECT_STREQ(t.signal.unit(), "1");
	EXPECT_FALSE(t.signal.isRate());
	EXPECT_EQ(ThermalTerm::hysteresis("Ti1", HysteresisOperator::Play, 2.0).name(), "hyst(Ti1,play,2C)^1");
	// the shortest text that reads back exactly: 1.92 (not %.17g's 1.9199999999999999)
	EXPECT_EQ(ThermalTerm::hysteresis("Ti1", HysteresisOperator::Branch, 1.92).name(), "hyst(Ti1,branch,1.92C)^1");
	for (const double w : {2.1102106565298242, 0.1 + 0.2, 1.0 / 3.0})
		EXPECT_EQ(ThermalTerm::parse(ThermalTerm::hysteresis("Ti1", HysteresisOperator::Play, w).name()).signal.width_C, w);
	for (const std::string n : {"hyst(Ti1)", "hyst(Ti1,play)", "hyst(Ti1,play,2)", "hyst(Ti1,play,0C)", "hyst(Ti1,play,-1C)",
								"hyst(Ti1,lag,2C)", "hyst(Ti1,play,xC)", "hyst(Ti1,play,2C)^2", "hyst(Ti 1,play,2C)",
								"hyst(Ti1,play,infC)", "hyst(Ti1,play,nanC)", "hyst(Ti1,play,2K)", "hyst(Ti1,play,1e9C)"})
		EXPECT_THROW(ThermalTerm::parse(n), std::invalid_argument) << n;
	// one operator per (thermistor, operator, width); the same width as play and branch are two
	const auto fs = ThermalFeatureSet::fromNames({"hyst(To1,play,2C)", "T(Ti1)^1", "hyst(Ti1,play,2C)", "hyst(To1,branch,2C)"});
	ASSERT_EQ(fs.hystereses().size(), 3u);
	EXPECT_EQ(fs.hystereses()[0], (HysteresisChannel{0, HysteresisOperator::Play, 2.0}));
	EXPECT_EQ(fs.hystereses()[1], (HysteresisChannel{1, HysteresisOperator::Play, 2.0}));
	EXPECT_EQ(fs.hystereses()[2], (HysteresisChannel{0, HysteresisOperator::Branch, 2.0}));
	const double temp[2] = {5.0, 7.0}, rate[2] = {0, 0}, h[3] = {0.25, -0.5, 1.0};
	std::vector<double> v(fs.signals().size());
	fs.signalValues(temp, rate, nullptr, h, v.data());
	EXPECT_EQ(v, (std::vector<double>{0.25, 7.0, -0.5, 1.0}));
	EXPECT_THROW(fs.signalValues(temp, rate, v.data()), std::invalid_argument);  // hysteresis values not given
	EXPECT_EQ(fs.without("To1").hystereses().size(), 1u);
}

TEST(HysteresisCalibration, FixedTermsRecoverTheCoefficientAndCompensateAnotherHistory)
{
	const Calibration cal = fitted("T(Ti1)^1;hyst(Ti1,play,2C)^1");
	const auto& fs = cal.model.features;
	ASSERT_EQ(fs.termNames(), (std::vector<std::string>{"1", "T(Ti1)^1", "hyst(Ti1,play,2C)^1"}));
	// normalisation: the operator's own range, centre 0, scale 1
	EXPECT_EQ(fs.normalisation()[1].centre, 0.0);
	EXPECT_EQ(fs.normalisation()[1].scale, 1.0);
	EXPECT_EQ(fs.normalisation()[1].min, -1.0);
	EXPECT_EQ(fs.normalisation()[1].max, 1.0);
	EXPECT_NEAR(cal.model.coef_dph[1] / fs.normalisation()[0].scale, 0.004, 1e-9);
	EXPECT_NEAR(cal.model.coef_dph[2], kHystCoef, 1e-9);
	// the compensator's operator (carried sample to sample) on a history the fit never saw
	const FogSeries b = runB();
	const FitFigures fb = evaluateCalibration(cal, b, "B", 100.0);
	EXPECT_LT(fb.rms_dph, 1e-9);
	// and == the independent evaluation of the fitted feature set, sample by sample
	const auto c = compensate(cal, b);
	const auto ref = featureBias(cal.model, b);
	for (std::size_t k = 0; k < b.size(); k++) ASSERT_NEAR(c.bias_dph[k], ref[k], 1e-12) << k;
	EXPECT_EQ(c.counters.clamped_samples, 0u);  // the output never leaves [-1, 1]
	// without the term the heating/cooling offset stays in the residual
	EXPECT_GT(evaluateCalibration(fitted("T(Ti1)^1"), b, "B", 100.0).rms_dph, 0.05);
}

TEST(HysteresisCalibration, FileVersion3RoundTripsExactlyAndOlderVersionsRefuseHysteresis)
{
	const Calibration cal = fitted("T(Ti1)^1;dT/dt(Ti1)^1;hyst(Ti1,play,2C)^1;hyst(Ti1,branch,5C)^1");
	const std::string text = calibrationToYaml(cal);
	EXPECT_NE(text.find("\nversion: 3\n"), std::string::npos);
	EXPECT_NE(text.find("hysteresis_filter: \"play_and_branch, warm_start_first_reading_h0, branch_dead_band_0.05C\""),
			  std::string::npos);
	EXPECT_EQ(text.find("lag_filter"), std::string::npos);
	const Calibration back = calibrationFromYaml(text, "cal.yaml");
	EXPECT_EQ(calibrationToYaml(back), text);
	const FogSeries b = runB();
	const auto c1 = compensate(cal, b), c2 = compensate(back, b);
	for (std::size_t k = 0; k < b.size(); k++) ASSERT_EQ(c1.bias_dph[k], c2.bias_dph[k]) << k;
	for (const char* v : {"2"})  // version 1 (no axes list): VersionOneFileReadingHysteresisIsRefused
	{
		std::string old = text;
		old.replace(old.find("\nversion: 3\n"), 12, std::string("\nversion: ") + v + "\n");
		try
		{
			calibrationFromYaml(old, "cal.yaml");
			ADD_FAILURE() << "version " << v << " with a hysteresis signal accepted";
		}
		catch (const std::invalid_argument& e)
		{
			EXPECT_NE(std::string(e.what()).find("reads hysteresis signals (hyst), which need file version 3"), std::string::npos)
				<< e.what();
		}
	}
	std::string other = text;
	other.replace(other.find("branch_dead_band_0.05C"), 22, "branch_dead_band_0.1C");
	EXPECT_THROW(calibrationFromYaml(other, "cal.yaml"), std::invalid_argument);
	std::string out_of_range = text;
	const auto at = out_of_range.find("max: 1\n", out_of_range.find("name: \"hyst(Ti1,play,2C)\""));
	ASSERT_NE(at, std::string::npos);
	out_of_range.replace(at, 7, "max: 2\n");
	EXPECT_THROW(calibrationFromYaml(out_of_range, "cal.yaml"), std::invalid_argument);
	// without hysteresis the file stays version 2
	EXPECT_NE(calibrationToYaml(fitted("T(Ti1)^1;dT/dt(Ti1)^1")).find("\nversion: 2\n"), std::string::npos);
}

TEST(HysteresisCalibration, DropoutFallsBackAndTheOperatorResumesFromItsState)
{
	const Calibration cal = fitted("T(Ti1)^1;hyst(Ti1,play,2C)^1");
	FogSeries b = runB();
	for (std::size_t k = 1000; k < 1010; k++) b.temp_C[0][k] = std::nan("");  // on the falling ramp
	const auto c = compensate(cal, b);
	for (std::size_t k = 1000; k < 1010; k++) EXPECT_TRUE(c.flags[k] & (CompensationFlag::Fallback | CompensationFlag::NoModel)) << k;
	for (std::size_t k = 1010; k < b.size(); k++) ASSERT_NEAR(c.compensated_dph[k], 0.0, 1e-9) << k;
}

TEST(HysteresisCalibration, BatchEqualsStreamingAndAvx2EqualsPortableBitwise)
{
	const Calibration cal = fitted("T(Ti1)^1;T(Ti1)^2;dT/dt(Ti1)^1;hyst(Ti1,play,2C)^1;hyst(Ti1,branch,5C)^1");
	FogSeries b = runB();
	for (std::size_t k = 3000; k < 3200; k += 7) b.temp_C[0][k] = std::nan("");
	for (std::size_t k = 4000; k < 4010; k++) b.temp_C[0][k] += 80.0;  // out of T's range: clamped/extrapolated
	std::vector<KernelBuild> builds{KernelBuild::Portable};
	if (detail::cpuHasAvx2()) builds.push_back(KernelBuild::Avx2);
	std::vector<std::vector<double>> per_build;
	for (const KernelBuild build : builds)
	{
		Compensator streaming(cal, b.thermistors, build), batch(cal, b.thermistors, build);
		std::vector<Compensator::Output> out(b.size());
		const std::size_t half = b.size() / 2;
		for (std::size_t k = 0; k < half; k++) out[k] = batch.step(b.time_s[k], b.rate_dph[2][k], &b.temp_C[0][k]);
		batch.stepBatch(b.size() - half, &b.time_s[half], &b.rate_dph[2][half], &b.temp_C[0][half], 1, &out[half]);
		std::vector<double> bias;
		for (std::size_t k = 0; k < b.size(); k++)
		{
			const auto o = streaming.step(b.time_s[k], b.rate_dph[2][k], &b.temp_C[0][k]);
			ASSERT_EQ(std::memcmp(&o.bias_dph, &out[k].bias_dph, sizeof(double)), 0) << k;
			ASSERT_EQ(o.flags, out[k].flags) << k;
			bias.push_back(o.bias_dph);
		}
		EXPECT_EQ(std::memcmp(&streaming.counters(), &batch.counters(), sizeof(CompensationCounters)), 0);
		EXPECT_GT(streaming.counters().clamped_samples, 0u);
		EXPECT_GT(streaming.counters().no_model_samples + streaming.counters().fallback_samples +
					  streaming.counters().rate_free_samples,
				  0u);
		per_build.push_back(bias);
	}
	if (per_build.size() == 2)
		for (std::size_t k = 0; k < b.size(); k++)
			ASSERT_EQ(std::memcmp(&per_build[0][k], &per_build[1][k], sizeof(double)), 0) << k;
}

TEST(HysteresisCalibration, VersionOneFileReadingHysteresisIsRefused)
{
	// the stored version-1 file, its term dT/dt(To1)^1 replaced by hyst(To1,play,2C)^1 (with that
	// signal's normalisation) in every model that reads it
	std::ifstream in(std::string(FOG_SOURCE_DIR) + "/tests/data/model/cal_v1_coil_A.yaml");
	std::stringstream ss;
	ss << in.rdbuf();
	std::string text = ss.str();
	ASSERT_NE(text.find("\nversion: 1\n"), std::string::npos);
	std::size_t renamed = 0;
	const std::string term = "- name: \"dT/dt(To1)^1\"";
	for (auto at = text.find(term); at != std::string::npos; at = text.find(term, at), renamed++)
		text.replace(at, term.size(), "- name: \"hyst(To1,play,2C)^1\"");
	for (auto at = text.find("- name: \"dT/dt(To1)\"\n"); at != std::string::npos;
		 at = text.find("- name: \"dT/dt(To1)\"\n", at))
	{
		const std::string indent = text.substr(text.rfind('\n', at) + 1, at - text.rfind('\n', at) - 1);
		const std::string block = "- name: \"hyst(To1,play,2C)\"\n" + indent + "  unit: \"1\"\n" + indent + "  centre: 0\n" +
								  indent + "  scale: 1\n" + indent + "  min: -1\n" + indent + "  max: 1\n" + indent;
		text.insert(at, block);
		at += block.size() + 1;
	}
	ASSERT_GE(renamed, 1u);
	try
	{
		calibrationFromYaml(text, "v1.yaml");
		ADD_FAILURE() << "version 1 with a hysteresis signal accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("v1.yaml: model: reads hysteresis signals (hyst), which need file version 3 (the file says 1)"),
				  std::string::npos)
			<< e.what();
	}
}
