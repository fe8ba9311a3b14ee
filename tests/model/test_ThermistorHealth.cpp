/* mrpt_fog: unit tests of ThermistorHealth on hand-made sequences (the fault-injection tests on
 * simulated runs are in tests/faults/). */
#include <gtest/gtest.h>
#include <mrpt_fog/model/ThermistorHealth.h>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace mrpt_fog;

namespace
{
/** Quantised to the 0.01 degC of the thermistor ADC. */
double quantised(double x) { return std::round(x * 100.0) / 100.0; }

/** Runs a two-thermistor sequence sampled every dt_s through the screening; returns per sample
 * whether thermistor 0 was flagged Stuck. a(t), b(t) give the true temperatures. */
template <class A, class B>
std::vector<bool> stuckFlags(double dt_s, std::size_t n, A a, B b, const ThermistorHealthSettings& s = {})
{
	ThermistorHealth h(2, s);
	std::vector<bool> out;
	for (std::size_t k = 0; k < n; k++)
	{
		const double t = static_cast<double>(k) * dt_s;
		double v[2] = {quantised(a(t)), quantised(b(t))};
		h.step(t, v);
		out.push_back(h.state(0) == ThermistorState::Stuck);
	}
	return out;
}

/** The inner thermistor ramps at 0.01 degC/s from 25 degC and freezes at freeze_s (the outer
 * one keeps moving): expects no flag before sample first_flagged and a Stuck flag from there on. */
void expectStuckFrom(double dt_s, std::size_t n, double freeze_s, std::size_t first_flagged)
{
	const auto frozen = [&](double t) { return 25.0 + 0.01 * std::min(t, freeze_s); };
	const auto outer = [](double t) { return 20.0 + 0.03 * t; };
	const auto flags = stuckFlags(dt_s, n, frozen, outer);
	for (std::size_t k = 0; k < n; k++) EXPECT_EQ(flags[k], k >= first_flagged) << "sample " << k;
}
}  // namespace

// A slow (0.1 Hz) quantised log at a temperature turnaround: the inner thermistor sits on one
// quantised value for 40 s (a parabola's flat top: 1e-5 degC/s^2 x 20^2 s^2 = 0.004 degC, under
// one 0.01 degC step) while the outer one, on the other side of the turnaround, still moves
// 0.03 degC/s x 40 s = 1.2 degC. Four equal readings are not a stuck sensor: no flag.
TEST(ThermistorHealth, SlowLogTurnaroundIsNotStuck)
{
	const auto inner = [](double t) { return 30.0 - 1e-5 * (t - 500.0) * (t - 500.0); };
	const auto outer = [](double t) { return 20.0 + 0.03 * t; };
	const auto flags = stuckFlags(10.0, 100, inner, outer);
	for (std::size_t k = 0; k < flags.size(); k++) EXPECT_FALSE(flags[k]) << "sample " << k;
}

// The same slow log with the inner thermistor frozen from sample 30: flagged once it has held
// its value for stuck_min_samples (10) readings = 90 s after freezing at 0.1 Hz (the 30 s window
// alone would have allowed 30 s), and from then on until the end.
TEST(ThermistorHealth, SlowLogStuckNeedsMinSamples) { expectStuckFrom(10.0, 100, 300.0, 39); }

// At 1 Hz the 30 s window is the binding condition: frozen at t = 100 s, flagged at t = 130 s.
TEST(ThermistorHealth, FastLogStuckAfterWindow) { expectStuckFrom(1.0, 200, 100.0, 130); }

TEST(ThermistorHealth, BadSettingsNameTheField)
{
	ThermistorHealthSettings s;
	s.stuck_min_samples = 1;
	try
	{
		ThermistorHealth h(2, s);
		FAIL() << "no exception";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("stuck_min_samples"), std::string::npos) << e.what();
	}
}
