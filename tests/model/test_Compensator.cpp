/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/CompensatorKernel.h>  // internal: detail::cpuHasAvx2

#include <cmath>
#include <cstring>
#include <random>

#include "SyntheticCoil.h"

using namespace mrpt_fog;

namespace
{
const Calibration& calA()
{
	static const Calibration cal = fitCalibration({fogtest::makeCoilRun("A", 51)}, "multipoint");
	return cal;
}

/** Independent batch evaluation: per-column causal rates (CausalRateEstimator) and the generic
 * ThermalFeatureSet feature path, no clamping, no Horner. */
std::vector<double> batchBias(const BiasModel& m, const FogSeries& s, const RateEstimatorSettings& est)
{
	const auto& fs = m.features;
	std::vector<std::vector<double>> rates;
	std::vector<int> cols;
	for (const auto& n : fs.thermistors())
	{
		cols.push_back(s.thermistorIndex(n));
		rates.push_back(makeRateEstimator(est)->estimate(s.time_s, s.temp_C[cols.back()]));
	}
	std::vector<double> out(s.size(), std::nan("")), temp(cols.size()), rate(cols.size()), v(fs.signals().size());
	for (std::size_t k = 0; k < s.size(); k++)
	{
		for (std::size_t i = 0; i < cols.size(); i++)
		{
			temp[i] = s.temp_C[cols[i]][k];
			rate[i] = rates[i][k];
		}
		fs.signalValues(temp.data(), rate.data(), v.data());
		out[k] = m.evaluate(v.data(), false);
	}
	return out;
}
}  // namespace

// Streaming compensator == batch model, sample for sample (1e-9 deg/h: only the order of
// floating-point operations differs), on the calibration run itself (nothing is clamped there).
TEST(Compensator, StreamingEqualsBatchModel)
{
	const FogSeries A = fogtest::makeCoilRun("A", 51);
	const CompensatedSeries c = compensate(calA(), A);
	const auto ref = batchBias(calA().model, A, calA().rate_estimator);
	ASSERT_TRUE(calA().startup.has_value());
	const auto ref_startup = batchBias(*calA().startup, A, calA().rate_estimator);
	// The rate-free start-up model until the rate window covers half its length: for regular
	// samples dt apart, k + 1 samples span sqrt(12 var(t)) = dt sqrt((k + 1)^2 - 1).
	const double dt = A.time_s[1] - A.time_s[0], half = 0.5 * calA().rate_estimator.window_s;
	std::size_t compared = 0, startup = 0;
	for (std::size_t k = 0; k < A.size(); k++)
	{
		const double n = static_cast<double>(k + 1);
		const bool warming = k < 1000 && dt * std::sqrt(n * n - 1.0) < half * (1 - 1e-9);
		ASSERT_EQ((c.flags[k] & CompensationFlag::RateFree) != 0, warming) << k;
		ASSERT_EQ(c.compensated_dph[k], c.raw_dph[k] - c.bias_dph[k]);
		if (warming)
		{
			ASSERT_NEAR(c.bias_dph[k], ref_startup[k], 1e-9) << k;
			startup++;
			continue;
		}
		ASSERT_NEAR(c.bias_dph[k], ref[k], 1e-9) << k;
		compared++;
	}
	EXPECT_GT(startup, 0u);
	EXPECT_EQ(compared + startup, A.size());
	EXPECT_EQ(c.counters.clamped_samples, 0u);
	EXPECT_EQ(c.counters.fallback_samples, 0u);
	EXPECT_EQ(c.counters.no_model_samples, 0u);  // the first sample (no rate yet): the start-up model
	EXPECT_EQ(c.counters.rate_free_samples, startup);
	EXPECT_EQ(c.counters.warmup_samples, 0u);
	// sample by sample through the class gives the same numbers as compensate()
	Compensator comp(calA(), A.thermistors);
	std::vector<double> temps(4);
	for (std::size_t k = 0; k < 2000; k++)
	{
		for (int i = 0; i < 4; i++) temps[i] = A.temp_C[i][k];
		ASSERT_EQ(comp.step(A.time_s[k], A.rate_dph[2][k], temps.data()).bias_dph, c.bias_dph[k]);
	}
}

// A thermistor dropout switches to its fallback model for exactly the dropout samples, the
// output stays finite, then the rate-free start-up model runs while the returning sensor's rate
// window (emptied by the 600 s dropout) covers less than half its length, and the main model
// returns after that: for regular samples dt apart, m samples span dt sqrt(m^2 - 1).
TEST(Compensator, DropoutUsesFallbackAndSwitchesBack)
{
	FogSeries B = fogtest::makeCoilRun("A", 52);
	const std::string used = calA().model.features.thermistors().front();
	const int col = B.thermistorIndex(used);
	for (std::size_t k = 6000; k < 6600; k++) B.temp_C[col][k] = std::nan("");
	const CompensatedSeries c = compensate(calA(), B);
	const auto fb = batchBias(*calA().fallbackFor(used), B, calA().rate_estimator);
	const double dt = B.time_s[1] - B.time_s[0], half = 0.5 * calA().rate_estimator.window_s;
	std::size_t back = 6600;
	while (dt * std::sqrt(std::pow(static_cast<double>(back - 6600 + 1), 2) - 1.0) < half * (1 - 1e-9)) back++;
	for (std::size_t k = 5000; k < 8000; k++)
	{
		const bool in = k >= 6000 && k < 6600;
		ASSERT_EQ((c.flags[k] & CompensationFlag::Fallback) != 0, in) << k;
		ASSERT_EQ((c.flags[k] & CompensationFlag::RateFree) != 0, k >= 6600 && k < back) << k;
		ASSERT_TRUE(std::isfinite(c.compensated_dph[k]));
		if (in) ASSERT_NEAR(c.bias_dph[k], fb[k], 1e-9) << k;
	}
	EXPECT_EQ(c.counters.fallback_samples, 600u);
	// start-up -> main at start, main -> fallback -> start-up -> main
	EXPECT_EQ(c.counters.model_switches, 4u);
	// two thermistors missing at once: no model, mean bias, flagged
	const std::string other = calA().model.features.thermistors().back();
	for (std::size_t k = 6100; k < 6200; k++) B.temp_C[B.thermistorIndex(other)][k] = std::nan("");
	const CompensatedSeries c2 = compensate(calA(), B);
	if (calA().fallbackFor(used)->features.references(other) || calA().model.features.references(other))
	{
		EXPECT_EQ(c2.flags[6150] & CompensationFlag::NoModel, CompensationFlag::NoModel);
		EXPECT_EQ(c2.bias_dph[6150], calA().mean_bias_dph);
	}
}

// Outside the calibrated range the compensator clamps (flags, counts) instead of extrapolating:
// the bias at T far beyond the range equals the bias at the range edge.
TEST(Compensator, OutOfRangeTemperaturesAreClampedAndCounted)
{
	FogSeries hot = fogtest::makeCoilRun("A", 53);
	hot.resize(3000);
	for (auto& col : hot.temp_C)
		for (std::size_t k = 1000; k < 1500; k++) col[k] += 200.0;  // +200 C for 500 samples
	Calibration clampCal = calA();
	clampCal.extrapolation = ExtrapolationPolicy::Clamp;
	const CompensatedSeries c = compensate(clampCal, hot);
	EXPECT_GE(c.counters.clamped_samples, 500u);
	EXPECT_GE(c.counters.temp_outside_samples, 500u);
	double excursion = 0;  // the largest temperature beyond its calibrated maximum, from the data
	for (std::size_t sg = 0; sg < calA().model.features.signals().size(); sg++)
	{
		const auto& sig = calA().model.features.signals()[sg];
		if (sig.kind != SignalKind::Temp) continue;
		for (std::size_t k = 0; k < hot.size(); k++)
			excursion = std::max(excursion, hot.temp_C[hot.thermistorIndex(sig.a)][k] - calA().model.features.normalisation()[sg].max);
	}
	EXPECT_GT(excursion, 100.0);
	EXPECT_NEAR(c.counters.max_temp_excursion_C, excursion, 1e-9);
	for (std::size_t k = 1100; k < 1400; k++) ASSERT_TRUE(c.flags[k] & CompensationFlag::Clamped) << k;
	// Independent check at k = 1300 (step out of the rate window): the model evaluated with
	// the temperatures clamped to the calibrated maximum and the column-wise causal rates.
	const auto& m = calA().model;
	const std::size_t k = 1300;
	std::vector<double> temp, rate, v(m.features.signals().size());
	for (const auto& n : m.features.thermistors())
	{
		const int col = hot.thermistorIndex(n);
		temp.push_back(hot.temp_C[col][k]);
		rate.push_back(makeRateEstimator(calA().rate_estimator)->estimate(hot.time_s, hot.temp_C[col])[k]);
	}
	m.features.signalValues(temp.data(), rate.data(), v.data());
	int clamped = 0;
	const double edge = m.evaluate(v.data(), true, &clamped);
	EXPECT_GE(clamped, 4);  // every temperature signal
	EXPECT_NEAR(c.bias_dph[k], edge, 1e-9);
	// The Polynomial policy (studies only) evaluates the raw polynomial beyond the range: the
	// compensator's rare-path correction must give the generic feature path's unclamped value.
	const double extrapolated = m.evaluate(v.data(), false);
	Calibration polyCal = calA();
	polyCal.extrapolation = ExtrapolationPolicy::Polynomial;
	EXPECT_NEAR(compensate(polyCal, hot).bias_dph[k], extrapolated, 1e-9 * (1 + std::abs(extrapolated)));
}

// Linear extrapolation: beyond the range each signal's polynomial continues along its tangent at
// the edge. Checked against a finite-difference tangent of the fitted model (not the code's own
// edge slopes): the bias at k equals the clamped value plus, for every temperature signal,
// (p(edge) - p(edge - h)) / h x (T - edge) to O(h).
TEST(Compensator, OutOfRangeTemperaturesLinearPolicyContinuesTheEdgeTangent)
{
	FogSeries hot = fogtest::makeCoilRun("A", 53);
	hot.resize(3000);
	for (auto& col : hot.temp_C)
		for (std::size_t k = 1000; k < 1500; k++) col[k] += 80.0;
	Calibration cal = calA();
	cal.extrapolation = ExtrapolationPolicy::Linear;
	const CompensatedSeries c = compensate(cal, hot);
	EXPECT_GE(c.counters.temp_outside_samples, 400u);
	const auto& m = cal.model;
	const std::size_t k = 1300;
	std::vector<double> temp, rate, v(m.features.signals().size());
	for (const auto& n : m.features.thermistors())
	{
		const int col = hot.thermistorIndex(n);
		temp.push_back(hot.temp_C[col][k]);
		rate.push_back(makeRateEstimator(cal.rate_estimator)->estimate(hot.time_s, hot.temp_C[col])[k]);
	}
	m.features.signalValues(temp.data(), rate.data(), v.data());
	double expected = m.evaluate(v.data(), true);  // every signal clamped
	const double h = 1e-4;
	int outside = 0;
	for (std::size_t s = 0; s < v.size(); s++)
	{
		const auto& nm = m.features.normalisation()[s];
		if (v[s] <= nm.max && v[s] >= nm.min) continue;
		outside++;
		const double edge = v[s] > nm.max ? nm.max : nm.min;
		const double inward = v[s] > nm.max ? -h : h;
		std::vector<double> a(v), b(v);
		for (std::size_t q = 0; q < v.size(); q++)  // others clamped as in the model
		{
			const auto& nq = m.features.normalisation()[q];
			a[q] = b[q] = std::min(std::max(v[q], nq.min), nq.max);
		}
		a[s] = edge;
		b[s] = edge + inward;
		const double slope = (m.evaluate(a.data(), false) - m.evaluate(b.data(), false)) / -inward;
		expected += slope * (v[s] - edge);
	}
	EXPECT_GE(outside, 4);
	EXPECT_NEAR(c.bias_dph[k], expected, 1e-4 * (1 + std::abs(expected)));
	EXPECT_NEAR(c.bias_dph[k], m.evaluate(v.data(), ExtrapolationPolicy::Linear), 1e-9);
}

TEST(Compensator, LayoutMismatchAndNonCausalCalibrationRefused)
{
	FogSeries s = fogtest::makeCoilRun("A", 54);
	s.resize(100);
	FogSeries renamed = s;
	renamed.thermistors[0].name = "T_inner_1";
	try
	{
		compensate(calA(), renamed);
		ADD_FAILURE() << "layout mismatch accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("another sensor layout"), std::string::npos) << e.what();
	}
	FogSeries moved = s;
	moved.thermistors[0].angle_deg = 90;
	moved.thermistors[1].angle_deg = 90;
	moved.thermistors[2].angle_deg = 90;
	moved.thermistors[3].angle_deg = 90;
	EXPECT_THROW(compensate(calA(), moved), std::invalid_argument);
	FogSeries xaxis = s;
	xaxis.has_axis = {{true, false, false}};
	xaxis.rate_dph[0] = xaxis.rate_dph[2];
	xaxis.rate_dph[2].clear();
	EXPECT_THROW(compensate(calA(), xaxis), std::invalid_argument);
	Calibration sg = calA();
	sg.rate_estimator = {RateEstimatorKind::SavitzkyGolay, 60, 2};
	EXPECT_THROW(Compensator(sg, s.thermistors), std::invalid_argument);
}

// A model that kept only the constant (nothing lowered the held-out error enough) still
// compensates: the bias is the constant, no thermistor is tracked.
TEST(Compensator, ConstantOnlyModel)
{
	FogSeries s = fogtest::makeCoilRun("A", 55);
	FitOptions o;
	o.min_relative_gain = 0.99;  // no group can lower the held-out RMS by 99 %
	o.linear_base = false;  // search from the constant (the default starts from the linear model)
	const Calibration cal = fitCalibration({s}, "multipoint", o);
	ASSERT_EQ(cal.model.features.termCount(), 1u);
	EXPECT_TRUE(cal.fallbacks.empty());
	s.resize(500);
	const CompensatedSeries c = compensate(cal, s);
	for (std::size_t k = 0; k < c.bias_dph.size(); k++) ASSERT_EQ(c.bias_dph[k], cal.model.coef_dph[0]);
	EXPECT_EQ(c.counters.no_model_samples, 0u);
}

namespace
{
/** A hostile log: irregular sampling with gaps longer than the rate window, single-sample and
 * 150-sample dropouts on every thermistor (often two at once), temperature spikes of +-300 C
 * and steps that drive the rates out of range. */
FogSeries stressRun(unsigned seed, std::size_t n)
{
	FogSeries s = fogtest::makeCoilRun("A", seed);
	s.resize(n);
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(0.0, 1.0);
	const std::vector<double> t0 = s.time_s;
	for (std::size_t k = 1; k < n; k++)
		s.time_s[k] = s.time_s[k - 1] + (t0[k] - t0[k - 1]) * (0.3 + 1.4 * u(rng)) + (u(rng) < 0.001 ? 90.0 : 0.0);
	for (auto& col : s.temp_C)
		for (std::size_t k = 0; k < n; k++)
		{
			if (u(rng) < 0.003) col[k] = std::nan("");
			if (u(rng) < 0.0005)
				for (std::size_t j = k; j < std::min(n, k + 150); j++) col[j] = std::nan("");
			if (u(rng) < 0.003) col[k] += u(rng) < 0.5 ? -300.0 : 300.0;
			if (u(rng) < 0.0005)
				for (std::size_t j = k; j < std::min(n, k + 40); j++) col[j] += 15.0;  // a 15 C step: large rates
		}
	return s;
}

const Calibration& calPlain()  // the benchmark's model: 33 terms, 4 thermistors, fallbacks
{
	static const Calibration cal = [] {
		FitOptions o;
		o.selection = TermSelection::None;
		o.fallbacks = true;
		return fitCalibration({fogtest::makeCoilRun("A", 51)}, "multipoint", o);
	}();
	return cal;
}

/** Hysteresis signals (play and branch, HysteresisFilter.h) beside the kernel's T and dT/dt terms
 * and a difference, with fallbacks: the filter bank's path through both builds. */
const Calibration& calHyst()
{
	static const Calibration cal = [] {
		FitOptions o;
		o.selection = TermSelection::None;
		o.fallbacks = true;
		return fitCalibration({fogtest::makeCoilRun("A", 51)},
							  "terms:T(Ti1)^1;T(Ti1)^2;dT/dt(Ti1)^1;T(To1)^1;dT/dt(To1)^1;dT(Ti2-To2)^1;"
							  "hyst(Ti1,play,2C)^1;hyst(To1,branch,1C)^1;hyst(Ti2,play,0.5C)^1",
							  o);
	}();
	return cal;
}

CompensatedSeries runSteps(const Calibration& cal, const FogSeries& s, KernelBuild build)
{
	Compensator comp(cal, s.thermistors, build);
	CompensatedSeries out;
	std::vector<double> temps(s.thermistorCount());
	for (std::size_t k = 0; k < s.size(); k++)
	{
		for (std::size_t i = 0; i < temps.size(); i++) temps[i] = s.temp_C[i][k];
		const auto o = comp.step(s.time_s[k], s.rate_dph[2][k], temps.data());
		out.bias_dph.push_back(o.bias_dph);
		out.compensated_dph.push_back(o.compensated_dph);
		out.flags.push_back(o.flags);
	}
	out.counters = comp.counters();
	return out;
}
}  // namespace

// The AVX2 build of the per-sample code (selected at run time) gives bitwise the numbers of the
// portable one, on a log with every rare path (dropouts, fallbacks, no model, clamping, gaps,
// irregular steps), for the plain 33-term model and the default (selected, 3-thermistor) one,
// and with the layout's columns in another order than the calibration's.
TEST(Compensator, Avx2BuildEqualsPortableBitwise)
{
	if (!detail::cpuHasAvx2()) GTEST_SKIP() << "this CPU has no AVX2";
	FogSeries s = stressRun(61, 12000);
	FogSeries swapped = s;
	std::swap(swapped.thermistors[0], swapped.thermistors[3]);
	std::swap(swapped.temp_C[0], swapped.temp_C[3]);
	for (const Calibration* cal : {&calPlain(), &calA(), &calHyst()})
		for (const FogSeries* series : {&s, &swapped})
		{
			const CompensatedSeries p = runSteps(*cal, *series, KernelBuild::Portable);
			const CompensatedSeries a = runSteps(*cal, *series, KernelBuild::Avx2);
			EXPECT_STREQ(Compensator(*cal, series->thermistors, KernelBuild::Avx2).kernelBuild(), "avx2");
			for (std::size_t k = 0; k < s.size(); k++)
			{
				ASSERT_EQ(std::memcmp(&a.bias_dph[k], &p.bias_dph[k], sizeof(double)), 0) << k;
				ASSERT_EQ(a.flags[k], p.flags[k]) << k;
			}
			EXPECT_EQ(std::memcmp(&a.counters, &p.counters, sizeof a.counters), 0);
			// the log does exercise the rare paths
			EXPECT_GT(p.counters.fallback_samples, 100u);
			EXPECT_GT(p.counters.no_model_samples, 10u);
			EXPECT_GT(p.counters.clamped_samples, 100u);
		}
}

// The compensator (folded normalisation, 4-lane kernel, steady-state tracker path) against an
// independent evaluation of the same documented rules on the hostile log: per-column causal
// rates (CausalRateEstimator), the model choice (main; else the fallback without the first
// missing thermistor of the main model if it reads no missing one; else the mean bias), and
// BiasModel::evaluate with clamping. Bias to 1e-9 deg/h (only the order of the floating-point
// operations differs), flags and clamp counts exactly.
TEST(Compensator, HostileLogMatchesIndependentReference)
{
	const FogSeries s = stressRun(62, 12000);
	for (const Calibration* cal : {&calPlain(), &calA()})
	{
		const CompensatedSeries c = compensate(*cal, s);
		std::vector<std::vector<double>> rate(s.thermistorCount());
		for (std::size_t i = 0; i < rate.size(); i++)
			rate[i] = makeRateEstimator(cal->rate_estimator)->estimate(s.time_s, s.temp_C[i]);
		std::size_t clamped_signals = 0, fallback = 0, none = 0;
		for (std::size_t k = 0; k < s.size(); k++)
		{
			const auto noReading = [&](const std::string& n) { return std::isnan(s.temp_C[s.thermistorIndex(n)][k]); };
			const auto noRate = [&](const std::string& n) { return std::isnan(rate[s.thermistorIndex(n)][k]); };
			// a rate window covering less than half its length: sqrt(12 var) of the times of the
			// channel's valid samples in (t - window, t]
			const auto warming = [&](const std::string& n) {
				const int i = s.thermistorIndex(n);
				const double t = s.time_s[k], w = cal->rate_estimator.window_s;
				double m1 = 0, m2 = 0, cnt = 0;
				for (std::size_t j = k + 1; j-- > 0 && s.time_s[j] > t - w;)
					if (!std::isnan(s.temp_C[i][j]))
					{
						m1 += s.time_s[j] - t;
						m2 += (s.time_s[j] - t) * (s.time_s[j] - t);
						cnt++;
					}
				if (cnt < 2) return true;
				const double var = m2 / cnt - (m1 / cnt) * (m1 / cnt);
				return 12.0 * var < 0.25 * w * w;
			};
			const auto readsRate = [](const BiasModel& m, const std::string& n) {
				for (const auto& sig : m.features.signals())
					if ((sig.kind == SignalKind::Rate || sig.kind == SignalKind::DiffRate) && sig.references(n)) return true;
				return false;
			};
			// a model lacks a thermistor whose reading it needs and is NaN, or whose rate it reads and is NaN
			const auto lacking = [&](const BiasModel& m) {
				for (const auto& n : m.features.thermistors())
					if (noReading(n) || (readsRate(m, n) && noRate(n))) return n;
				return std::string();
			};
			// with a start-up model, a model also waits for a rate it reads whose window covers
			// less than half its length
			const auto firstWarming = [&](const BiasModel& bm) {
				if (!cal->startup) return std::string();
				for (const auto& n : bm.features.thermistors())
					if (readsRate(bm, n) && warming(n)) return n;
				return std::string();
			};
			bool readings = true;
			for (const auto& n : cal->model.features.thermistors()) readings &= !noReading(n);
			// main unless it lacks a reading or rate or waits for one; else, when every reading of
			// the main model is there, the start-up model; else the fallback without the first
			// thermistor it lacks (or waits for) if that fallback lacks nothing; else the main
			// model if it lacks nothing (waiting); else none
			const BiasModel* m = nullptr;
			const std::string lack = lacking(cal->model), wait = firstWarming(cal->model);
			if (lack.empty() && wait.empty())
				m = &cal->model;
			else if (cal->startup && readings && lacking(*cal->startup).empty())
				m = &*cal->startup;
			else
			{
				const BiasModel* fb = cal->fallbackFor(lack.empty() ? wait : lack);
				if (fb && lacking(*fb).empty())
					m = fb;
				else if (lack.empty())
					m = &cal->model;
			}
			double expected = cal->mean_bias_dph;
			int clamped = 0;
			if (m)
			{
				std::vector<double> temp, rt, v(m->features.signals().size());
				for (const auto& n : m->features.thermistors())
				{
					temp.push_back(s.temp_C[s.thermistorIndex(n)][k]);
					rt.push_back(rate[s.thermistorIndex(n)][k]);
				}
				m->features.signalValues(temp.data(), rt.data(), v.data());
				expected = m->evaluate(v.data(), cal->extrapolation, &clamped);
			}
			ASSERT_NEAR(c.bias_dph[k], expected, 1e-9) << k;
			const bool is_startup = cal->startup && m == &*cal->startup;
			ASSERT_EQ((c.flags[k] & CompensationFlag::Fallback) != 0, m && m != &cal->model && !is_startup) << k;
			ASSERT_EQ((c.flags[k] & CompensationFlag::RateFree) != 0, is_startup) << k;
			ASSERT_EQ((c.flags[k] & CompensationFlag::NoModel) != 0, m == nullptr) << k;
			ASSERT_EQ((c.flags[k] & CompensationFlag::Clamped) != 0, clamped > 0) << k;
			clamped_signals += static_cast<std::size_t>(clamped);
			fallback += m && m != &cal->model && !is_startup;
			none += m == nullptr;
		}
		EXPECT_EQ(c.counters.clamped_signals, clamped_signals);
		EXPECT_EQ(c.counters.fallback_samples, fallback);
		EXPECT_EQ(c.counters.no_model_samples, none);
		EXPECT_GT(fallback, 100u);
		EXPECT_GT(clamped_signals, 100u);
	}
}

TEST(Compensator, Avx2RequestedWithoutAvx2IsRefused)
{
	FogSeries s = fogtest::makeCoilRun("A", 56);
	s.resize(10);
	if (detail::cpuHasAvx2())
		EXPECT_STREQ(Compensator(calA(), s.thermistors, KernelBuild::Avx2).kernelBuild(), "avx2");
	else
		EXPECT_THROW(Compensator(calA(), s.thermistors, KernelBuild::Avx2), std::invalid_argument);
	EXPECT_STREQ(Compensator(calA(), s.thermistors, KernelBuild::Portable).kernelBuild(), "portable");
}

// The batch form (stepBatch, which compensate() uses) is the streaming loop: bitwise the same
// outputs and counters as step() sample by sample, in both builds, also when the two are mixed.
TEST(Compensator, BatchEqualsStreamingBitwise)
{
	const FogSeries s = stressRun(63, 9000);
	const std::size_t n = s.size(), nt = s.thermistorCount();
	std::vector<double> rows(n * nt);
	for (std::size_t k = 0; k < n; k++)
		for (std::size_t i = 0; i < nt; i++) rows[k * nt + i] = s.temp_C[i][k];
	std::vector<KernelBuild> builds{KernelBuild::Portable};
	if (detail::cpuHasAvx2()) builds.push_back(KernelBuild::Avx2);
	for (const Calibration* cal : {&calPlain(), &calA(), &calHyst()})
		for (const KernelBuild build : builds)
		{
			const CompensatedSeries ref = runSteps(*cal, s, build);
			Compensator comp(*cal, s.thermistors, build);
			std::vector<Compensator::Output> out(n);
			const std::size_t half = n / 2;
			for (std::size_t k = 0; k < half; k++) out[k] = comp.step(s.time_s[k], s.rate_dph[2][k], &rows[k * nt]);
			comp.stepBatch(n - half, &s.time_s[half], &s.rate_dph[2][half], &rows[half * nt], nt, &out[half]);
			for (std::size_t k = 0; k < n; k++)
			{
				ASSERT_EQ(std::memcmp(&out[k].bias_dph, &ref.bias_dph[k], sizeof(double)), 0) << k;
				ASSERT_EQ(out[k].compensated_dph, s.rate_dph[2][k] - out[k].bias_dph) << k;
				ASSERT_EQ(out[k].flags, ref.flags[k]) << k;
			}
			EXPECT_EQ(std::memcmp(&comp.counters(), &ref.counters, sizeof ref.counters), 0);
		}
}
