/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// Calibration with lag-rate signals (dTlag/dt, LagFilter.h): a one-thermistor run whose bias is
// a known function of the reading and of its lag's rate, the lag integrated here by RK4 (not by
// the filter under test); fit, selection, compensator and calibration file checked against it.
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "PiecewiseHistory.h"

using namespace mrpt_fog;

namespace
{
constexpr double kTau_s = 400.0, kLagCoef = 45.0;  // bias per lag rate [deg/h per degC/s]

using fogtest::piecewise;

/** 1 Hz run of one thermistor following `knots`; bias = 0.8 + 0.004 T + kLagCoef dy/dt with
 * dy/dt = (T - y) / kTau_s integrated by RK4 (0.25 s steps) from y(0) = T(0). */
FogSeries lagRun(const std::vector<std::pair<double, double>>& knots)
{
	FogSeries s;
	s.sensor_label = "FOG";
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}};
	s.has_axis = {{false, false, true}};
	s.temp_C.assign(1, {});
	const auto x = [&](double t) { return piecewise(knots, t); };
	const auto f = [&](double t, double y) { return (x(t) - y) / kTau_s; };
	double y = x(0), t = 0;
	const double h = 0.25;
	for (int k = 0; t <= knots.back().first; k++)
	{
		t = k;
		if (k > 0)
			for (int j = 0; j < 4; j++)
			{
				const double ts = t - 1 + j * h;
				const double k1 = f(ts, y), k2 = f(ts + h / 2, y + h / 2 * k1), k3 = f(ts + h / 2, y + h / 2 * k2),
							 k4 = f(ts + h, y + h * k3);
				y += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
			}
		s.time_s.push_back(t);
		s.temp_C[0].push_back(x(t));
		s.rate_dph[2].push_back(0.8 + 0.004 * x(t) + kLagCoef * (x(t) - y) / kTau_s);
	}
	return s;
}

// A: 25 -> -10 C at 1 C/min, 1 h soak, -> 40 C at 1 C/min, 1 h soak. B: 2 C/min and 0.5 C/min
// ramps and a 20 min triangle wave of +-5 C: another history, held out.
FogSeries lagRunA() { return lagRun({{0, 25}, {2100, -10}, {5700, -10}, {8700, 40}, {12300, 40}}); }
FogSeries lagRunB()
{
	return lagRun({{0, 10}, {900, 40}, {2700, 40}, {5100, 20}, {5700, 25}, {6300, 15}, {6900, 25}, {7500, 15}, {9000, 15}});
}
}  // namespace

TEST(LagCalibration, FixedTermsRecoverTheLagCoefficientAndCompensateAnotherHistory)
{
	FitOptions o;
	o.selection = TermSelection::None;
	const Calibration cal = fitCalibration({lagRunA()}, "terms:T(Ti1)^1;dTlag/dt(Ti1,400)^1", o);
	const auto& fs = cal.model.features;
	ASSERT_EQ(cal.model.features.termNames(), (std::vector<std::string>{"1", "T(Ti1)^1", "dTlag/dt(Ti1,400)^1"}));
	// physical slopes: coefficient of z = (v - centre) / scale over scale
	EXPECT_NEAR(cal.model.coef_dph[1] / fs.normalisation()[0].scale, 0.004, 1e-9);
	EXPECT_NEAR(cal.model.coef_dph[2] / fs.normalisation()[1].scale, kLagCoef, 1e-6);
	// the compensator's lag (carried sample to sample) on a history the fit never saw
	const FitFigures b = evaluateCalibration(cal, lagRunB(), "B", 100.0);
	EXPECT_GT(b.raw_stability_dph, 0.05);
	EXPECT_LT(b.rms_dph, 1e-7);
	// a model without the lag leaves the Shupe-like term on B
	FitOptions plain;
	plain.selection = TermSelection::None;
	EXPECT_GT(evaluateCalibration(fitCalibration({lagRunA()}, "multipoint@1/1", plain), lagRunB(), "B", 100.0).rms_dph, 1e-3);
}

TEST(LagCalibration, SelectionUsesTheLagsOnlyWithOneThermistor)
{
	// the default: with one thermistor the three lags (100, 400, 1600 s) start in the linear base
	const Calibration cal = fitCalibration({lagRunA()}, "multipoint", FitOptions{});
	const auto names = cal.model.features.termNames();
	for (const char* n : {"dTlag/dt(Ti1,100)^1", "dTlag/dt(Ti1,400)^1", "dTlag/dt(Ti1,1600)^1"})
		EXPECT_NE(std::find(names.begin(), names.end(), n), names.end()) << n;
	FitOptions no_lags;
	no_lags.lag_taus_s.clear();
	const double b_lags = evaluateCalibration(cal, lagRunB(), "B", 100.0).rms_dph;
	const double b_plain = evaluateCalibration(fitCalibration({lagRunA()}, "multipoint", no_lags), lagRunB(), "B", 100.0).rms_dph;
	std::printf("  B compensated RMS: with the lags %.3g, without %.3g deg/h\n", b_lags, b_plain);
	EXPECT_LT(b_lags, 1e-6);  // the true term is in the lags' span (start-up model included)
	EXPECT_GT(b_plain, 0.1);  // without them no term holds it
	// as forward steps: the true time constant is the one taken
	FitOptions steps;
	steps.lag_in_base = false;
	const Calibration st = fitCalibration({lagRunA()}, "multipoint", steps);
	const auto sn = st.model.features.termNames();
	EXPECT_NE(std::find(sn.begin(), sn.end(), "dTlag/dt(Ti1,400)^1"), sn.end());
	EXPECT_LT(st.held_out.rms_dph, 1e-3);
	EXPECT_LT(evaluateCalibration(st, lagRunB(), "B", 100.0).rms_dph, 1e-3);
	// with two thermistors the candidates are not offered (FitOptions::lag_max_thermistors)
	FogSeries two = lagRunA();
	two.thermistors.push_back({"To1", CoilSide::Outer, 0});
	two.temp_C.push_back(two.temp_C[0]);
	for (double& v : two.temp_C[1]) v += 0.5;
	const Calibration with_two = fitCalibration({two}, "multipoint", FitOptions{});  // named: signals() refers into it
	for (const auto& sig : with_two.model.features.signals()) EXPECT_FALSE(sig.isLag());
	// "none": every preset term and nothing else (the seed's method)
	FitOptions none;
	none.selection = TermSelection::None;
	const Calibration seed_method = fitCalibration({lagRunA()}, "multipoint", none);
	for (const auto& sig : seed_method.model.features.signals()) EXPECT_FALSE(sig.isLag());
	FitOptions bad;
	bad.lag_taus_s = {0.0};
	EXPECT_THROW(fitCalibration({lagRunA()}, "multipoint", bad), std::invalid_argument);
}

TEST(LagCalibration, FileVersion3RoundTripsAndOlderVersionsRefuseLags)
{
	FitOptions o;
	o.selection = TermSelection::None;
	const Calibration cal = fitCalibration({lagRunA()}, "terms:T(Ti1)^1;dT/dt(Ti1)^1;dTlag/dt(Ti1,400)^1", o);
	const std::string text = calibrationToYaml(cal);
	EXPECT_NE(text.find("\nversion: 3\n"), std::string::npos);
	EXPECT_NE(text.find("lag_filter: \"first_order_hold, warm_start_first_reading\""), std::string::npos);
	const Calibration back = calibrationFromYaml(text, "cal.yaml");
	const FogSeries b = lagRunB();
	const auto c1 = compensate(cal, b), c2 = compensate(back, b);
	for (std::size_t k = 0; k < b.size(); k++) ASSERT_EQ(c1.bias_dph[k], c2.bias_dph[k]) << k;
	// a version 2 file cannot hold a lag (a build that reads only version 2 says so instead)
	std::string v2 = text;
	v2.replace(v2.find("\nversion: 3\n"), 12, "\nversion: 2\n");
	try
	{
		calibrationFromYaml(v2, "cal.yaml");
		ADD_FAILURE() << "version 2 with a lag accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("cal.yaml: axes[0].bias: reads lag signals"), std::string::npos) << e.what();
	}
	std::string other = text;
	other.replace(other.find("first_order_hold, warm_start_first_reading"), 42, "zero_order_hold");
	EXPECT_THROW(calibrationFromYaml(other, "cal.yaml"), std::invalid_argument);
	// without lags the file stays version 2
	FitOptions none;
	none.selection = TermSelection::None;
	EXPECT_NE(calibrationToYaml(fitCalibration({lagRunA()}, "multipoint@1/1", none)).find("\nversion: 2\n"), std::string::npos);
}

TEST(LagCalibration, DropoutFallsBackAndTheLagResumesFromTheBridgedState)
{
	FitOptions o;
	o.selection = TermSelection::None;
	const Calibration cal = fitCalibration({lagRunA()}, "terms:T(Ti1)^1;dTlag/dt(Ti1,400)^1", o);
	FogSeries b = lagRunB();
	for (std::size_t k = 1000; k < 1010; k++) b.temp_C[0][k] = std::nan("");  // on the 2 C/min ramp: bridged exactly
	const auto c = compensate(cal, b);
	for (std::size_t k = 1000; k < 1010; k++) EXPECT_TRUE(c.flags[k] & (CompensationFlag::Fallback | CompensationFlag::NoModel)) << k;
	for (std::size_t k = 1010; k < b.size(); k++) ASSERT_NEAR(c.compensated_dph[k], 0.0, 1e-7) << k;
}
