/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
// The lag bank (LagFilter.h) against the closed-form solutions of dy/dt = (x - y) / tau.
#include <gtest/gtest.h>
#include <mrpt_fog/model/LagFilter.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

using namespace mrpt_fog;

namespace
{
// x(t) = x0 + r t from equilibrium y(0) = x0: y = x0 + r (t - tau (1 - exp(-t / tau))),
// dy/dt = r (1 - exp(-t / tau)).
double rampLagged(double x0, double r, double tau, double t) { return x0 + r * (t - tau * (1 - std::exp(-t / tau))); }
double rampLagRate(double r, double tau, double t) { return r * (1 - std::exp(-t / tau)); }
}  // namespace

TEST(LagFilter, RampFromEquilibriumMatchesTheClosedFormAtIrregularSteps)
{
	const double x0 = 12.5, r = 1.0 / 60.0;  // 1 C/min
	// two channels of the same thermistor, tau 100 s and 1600 s, and one of another (x = -x)
	LagFilterBank bank({{0, 100.0}, {0, 1600.0}, {1, 400.0}});
	const double steps[] = {0.3, 1.0, 2.7, 10.0, 0.01, 45.0};
	double t = 0;
	for (int k = 0; k < 600; k++)
	{
		const double x[2] = {x0 + r * t, -(x0 + r * t)};
		bank.push(t, x);
		EXPECT_NEAR(bank.lagged_C(0), rampLagged(x0, r, 100.0, t), 1e-10) << t;
		EXPECT_NEAR(bank.rate_C_per_s(0), rampLagRate(r, 100.0, t), 1e-13) << t;
		EXPECT_NEAR(bank.rate_C_per_s(1), rampLagRate(r, 1600.0, t), 1e-13) << t;
		EXPECT_NEAR(bank.rate_C_per_s(2), -rampLagRate(r, 400.0, t), 1e-13) << t;
		t += steps[k % 6];
	}
	// after many time constants of the shortest lag: the ramp rate, the lag tau behind
	EXPECT_NEAR(bank.rate_C_per_s(0), r, 1e-12);
}

TEST(LagFilter, DecayAfterTheRampStopsAndDropoutsBridgedByAStraightLine)
{
	const double r = 0.5 / 60.0, tau = 300.0, t1 = 900.0;
	LagFilterBank bank({{0, tau}});
	const double nan = std::numeric_limits<double>::quiet_NaN();
	const double y1 = rampLagged(0.0, r, tau, t1), x1 = r * t1;
	for (double t = 0; t <= 3000; t += 1.0)
	{
		// readings missing over 400..430 s on the ramp (bridged exactly: the reading is linear there)
		const bool missing = t >= 400 && t <= 430;
		const double x = missing ? nan : (t < t1 ? r * t : x1);
		bank.push(t, &x);
		if (missing)
		{
			EXPECT_TRUE(std::isnan(bank.rate_C_per_s(0))) << t;
			continue;
		}
		// after t1: y = x1 + (y(t1) - x1) exp(-(t - t1) / tau)
		const double y = t < t1 ? rampLagged(0.0, r, tau, t) : x1 + (y1 - x1) * std::exp(-(t - t1) / tau);
		EXPECT_NEAR(bank.lagged_C(0), y, 1e-11) << t;
		EXPECT_NEAR(bank.rate_C_per_s(0), (x - y) / tau, 1e-13) << t;
	}
}

TEST(LagFilter, WarmStartResetAndBadTimeConstants)
{
	LagFilterBank bank({{0, 50.0}});
	const double nan = std::numeric_limits<double>::quiet_NaN();
	bank.push(0.0, &nan);  // no valid reading yet: no state
	EXPECT_TRUE(std::isnan(bank.lagged_C(0)));
	EXPECT_TRUE(std::isnan(bank.rate_C_per_s(0)));
	const double a = 20.0;
	bank.push(1.0, &a);  // warm start: at equilibrium with the first valid reading
	EXPECT_EQ(bank.lagged_C(0), 20.0);
	EXPECT_EQ(bank.rate_C_per_s(0), 0.0);
	const double b = 30.0;
	bank.push(1.0, &b);  // no time passed: the state stays, the reading is held
	EXPECT_EQ(bank.lagged_C(0), 20.0);
	EXPECT_DOUBLE_EQ(bank.rate_C_per_s(0), 10.0 / 50.0);
	bank.reset();
	bank.push(5.0, &b);
	EXPECT_EQ(bank.lagged_C(0), 30.0);
	for (const double tau : {0.0, -1.0, nan, std::numeric_limits<double>::infinity()})
		EXPECT_THROW(LagFilterBank({{0, tau}}), std::invalid_argument) << tau;
}
