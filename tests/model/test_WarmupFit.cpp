/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// fitWarmup on synthetic runs made here from a closed form (not by the code under test): a
// static bias linear in the thermistor temperature (fitted from a slow chamber ramp), then a
// turn-on run at constant temperature whose output adds A exp(-(t - t_on) / tau) + white noise.
#include <gtest/gtest.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/WarmupFit.h>

#include <cmath>
#include <random>

using namespace mrpt_fog;

namespace
{
constexpr double kBias0_dph = 0.3, kBiasPerC = 0.004;

double staticBias(double T) { return kBias0_dph + kBiasPerC * (T - 25.0); }

FogSeries emptyRun()
{
	FogSeries s;
	s.sensor_label = "FOG";
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}, {"To1", CoilSide::Outer, 0}};
	s.temp_C.resize(2);
	return s;
}

void push(FogSeries& s, std::mt19937_64& rng, double t, double T, double rate_dph, bool on)
{
	std::normal_distribution<double> n01;
	s.time_s.push_back(t);
	s.rate_dph[2].push_back(on ? rate_dph + 0.05 * n01(rng) : std::nan(""));
	s.temp_C[0].push_back(T + 0.005 * n01(rng));
	s.temp_C[1].push_back(T + 0.2 + 0.005 * n01(rng));
	s.power.push_back(on ? 1.0 : 0.0);
}

Calibration biasCalibration()
{
	std::mt19937_64 rng(5);
	FogSeries s = emptyRun();
	for (int k = 0; k < 20000; k++)
	{
		const double T = -20.0 + 60.0 * k / 20000.0;
		push(s, rng, k, T, staticBias(T), true);
	}
	return fitCalibration({s}, "M1:Ti1@1/0");
}

struct Phase
{
	double off_s, on_s, T;
};

/** Phases of gyro off then on at temperature T, with the warm-up A exp(-dt / tau) after each
 * turn-on. */
FogSeries phasesRun(unsigned seed, double A, double tau, const std::vector<Phase>& phases)
{
	std::mt19937_64 rng(seed);
	FogSeries s = emptyRun();
	double t = 0;
	for (const auto& p : phases)
	{
		for (int k = 0; k < static_cast<int>(p.off_s); k++, t += 1) push(s, rng, t, p.T, 0.0, false);
		const double t_on = t;
		for (int k = 0; k < static_cast<int>(p.on_s); k++, t += 1)
			push(s, rng, t, p.T, staticBias(p.T) + A * std::exp(-(t - t_on) / tau), true);
	}
	return s;
}

FogSeries turnOnRun(unsigned seed, double A, double tau, double T = 23.0, double off_s = 300, double on_s = 7200)
{
	return phasesRun(seed, A, tau, {{off_s, on_s, T}});
}
/** A turn-on after off_s at temperature T whose output adds two exponentials (closed form). */
FogSeries twoTermRun(unsigned seed, double A1, double tau1, double A2, double tau2, double on_s = 10800)
{
	std::mt19937_64 rng(seed);
	FogSeries s = emptyRun();
	double t = 0;
	for (int k = 0; k < 300; k++, t += 1) push(s, rng, t, 23.0, 0.0, false);
	const double t_on = t;
	for (int k = 0; k < static_cast<int>(on_s); k++, t += 1)
		push(s, rng, t, 23.0, staticBias(23.0) + A1 * std::exp(-(t - t_on) / tau1) + A2 * std::exp(-(t - t_on) / tau2),
			 true);
	return s;
}
}  // namespace

// Two time constants (a fast and a slow settling) come back from two turn-on runs, and the held-out
// choice (each run left out in turn) takes two terms; with one true term it keeps one. A model
// without rates has no start-up model: no start-up offset is fitted.
TEST(WarmupFit, TwoTimeConstantsChosenByHeldOutError)
{
	const Calibration cal = biasCalibration();
	const std::vector<FogSeries> two = {twoTermRun(11, 0.3, 150, 0.1, 1500), twoTermRun(12, 0.3, 150, 0.1, 1500)};
	const WarmupTermsChoice ch = selectWarmupTerms(two, cal);
	EXPECT_TRUE(ch.judged);
	EXPECT_EQ(ch.exponentials, 2u) << ch.why;
	WarmupFitOptions o;
	o.exponentials = 2;
	const WarmupModel w = fitWarmup(two, cal, o);
	ASSERT_TRUE(w.hasSecondTerm());
	EXPECT_NEAR(w.amplitude_dph, 0.3, std::max(3 * w.amplitude_std_dph, 0.03));
	EXPECT_NEAR(w.tau_s, 150.0, std::max(3 * w.tau_std_s, 15.0));
	EXPECT_NEAR(w.amplitude2_dph, 0.1, std::max(3 * w.amplitude2_std_dph, 0.01));
	EXPECT_NEAR(w.tau2_s, 1500.0, std::max(3 * w.tau2_std_s, 150.0));
	EXPECT_EQ(w.startup_samples, 0u);
	EXPECT_EQ(w.startup_offset_dph, 0.0);
	// one true term: one kept; one run: not judged, one term
	const std::vector<FogSeries> one = {turnOnRun(13, 0.1, 600, 23.0, 300, 10800), turnOnRun(14, 0.1, 600, 23.0, 300, 10800)};
	EXPECT_EQ(selectWarmupTerms(one, cal).exponentials, 1u) << selectWarmupTerms(one, cal).why;
	const WarmupTermsChoice single = selectWarmupTerms({two[0]}, cal);
	EXPECT_FALSE(single.judged);
	EXPECT_EQ(single.exponentials, 1u);
	o.exponentials = 3;
	EXPECT_THROW(fitWarmup(two, cal, o), std::invalid_argument);
}

// Amplitude and time constant come back within their reported uncertainty (3 sigma) and 10 %.
TEST(WarmupFit, RecoversAmplitudeAndTimeConstantFromAPowerStep)
{
	const Calibration cal = biasCalibration();
	WarmupFitReport rep;
	const WarmupModel w = fitWarmup({turnOnRun(1, 0.1, 600)}, cal, {}, &rep);
	EXPECT_EQ(w.turn_ons, 1u);
	ASSERT_EQ(rep.spans.size(), 1u);
	EXPECT_EQ(rep.spans[0].t_on_s, 300.0);
	EXPECT_NEAR(w.amplitude_dph, 0.1, std::max(3 * w.amplitude_std_dph, 0.01));
	EXPECT_NEAR(w.tau_s, 600.0, std::max(3 * w.tau_std_s, 60.0));
	EXPECT_GT(w.amplitude_std_dph, 0.0);
	EXPECT_LT(w.amplitude_std_dph, 0.02);
	EXPECT_LT(w.rms_after_dph, w.rms_before_dph);
	EXPECT_NEAR(rep.spans[0].offset_dph, 0.0, 0.005) << "the bias model is exact here";
}

// Two turn-ons (a power cycle) at different temperatures share (A, tau), each with its offset;
// the turn-on may also be given by metadata power_on_time_s for a run that starts powered.
TEST(WarmupFit, PowerCyclesAndMetadataTurnOn)
{
	const Calibration cal = biasCalibration();
	const FogSeries a = phasesRun(2, -0.08, 400, {{300, 5000, 10.0}, {600, 5000, 35.0}});
	// a cold start logged from the turn-on: no power column, metadata says t = 0
	FogSeries c = turnOnRun(4, -0.08, 400, 0.0, 0);
	c.power.clear();
	c.setMetadata("power_on_time_s", "0");
	WarmupFitReport rep;
	const WarmupModel w = fitWarmup({a, c}, cal, {}, &rep);
	EXPECT_EQ(w.turn_ons, 3u);
	EXPECT_NEAR(w.amplitude_dph, -0.08, std::max(3 * w.amplitude_std_dph, 0.008));
	EXPECT_NEAR(w.tau_s, 400.0, std::max(3 * w.tau_std_s, 40.0));
	// applied by the compensator from the turn-on on, the transient is gone
	Calibration full = cal;
	full.warmup = w;
	const CompensatedSeries out = compensate(full, c);
	double early = 0;
	for (std::size_t k = 0; k < 600; k++) early += out.compensated_dph[k] / 600.0;
	EXPECT_NEAR(early, 0.0, 0.01) << "first 10 min after the turn-on, was about -0.05 deg/h uncompensated";
}

// Runs that cannot support the fit are refused with the reason.
TEST(WarmupFit, RefusesRunsWithoutATurnOnOrADecay)
{
	const Calibration cal = biasCalibration();
	auto why = [&](const FogSeries& run) -> std::string {
		try
		{
			fitWarmup({run}, cal);
		}
		catch (const WarmupFitError& e)
		{
			return e.what();
		}
		return "";
	};
	FogSeries powered = turnOnRun(5, 0.1, 600, 23.0, 0);
	powered.power.clear();  // on from the start, no metadata: no turn-on
	EXPECT_NE(why(powered).find("no turn-on"), std::string::npos);
	EXPECT_NE(why(turnOnRun(6, 0.1, 600, 23.0, 300, 400)).find("stays on for"), std::string::npos);
	// no transient at all: no amplitude resolved
	EXPECT_NE(why(turnOnRun(7, 0.0, 600)).find("no turn-on transient"), std::string::npos);
	// metadata says on at t = 0 but the power column says off there: no powered span
	FogSeries off_first = turnOnRun(9, 0.1, 600, 23.0, 300, 400);
	off_first.setMetadata("power_on_time_s", "0");
	EXPECT_NE(why(off_first).find("stays on for 0 s"), std::string::npos) << why(off_first);
	FogSeries bad = turnOnRun(8, 0.1, 600);
	bad.power.clear();
	bad.setMetadata("power_on_time_s", "soon");
	EXPECT_NE(why(bad).find("power_on_time_s"), std::string::npos);
}
