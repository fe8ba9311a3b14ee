/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/CandidateEffect.h>
#include "support/SyntheticChamberRun.h"

#include <cmath>
#include <set>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
/** Signals of the synthetic chamber run (default profile unless given), one sample every 20 s. */
RunSignals syntheticSignals(SyntheticProfile profile = SyntheticRunOptions{}.profile)
{
	SyntheticRunOptions o;
	o.profile = profile;
	o.dt_s = 20;
	return computeRunSignals(makeSyntheticChamberRun(o).series);
}
}  // namespace

TEST(CandidateEffect, LibraryHoldsTheStableIds)
{
	std::vector<std::string> ids;
	for (const auto& c : candidateLibrary())
	{
		ids.push_back(c.id);
		EXPECT_FALSE(c.description.empty()) << c.id;
		EXPECT_FALSE(c.excited_by.empty()) << c.id;
		EXPECT_FALSE(c.theta_grid.empty()) << c.id;
	}
	EXPECT_EQ(ids, (std::vector<std::string>{"shupe_rate", "radial_gradient", "gradient_rate", "thermistor_lag",
											 "hysteresis", "warmup", "scale_factor_temp", "magnetic",
											 "temp_poly_order", "heat_source"}));
	EXPECT_EQ(candidateById("heat_source").channel, ResidualChannel::Temperature);
	EXPECT_THROW(candidateById("nonsense"), std::invalid_argument);
	EXPECT_FALSE(separationAdvice("shupe_rate", "thermistor_lag").empty());
	EXPECT_FALSE(separationAdvice("magnetic", "warmup").empty());
}

TEST(CandidateEffect, ColumnsMatchClosedForms)
{
	const auto sig = syntheticSignals();
	CandidateContext ctx;
	ctx.sig = &sig;
	ctx.static_temp_C = sig.temp_mean_C;
	ctx.base_static_order = 3;
	ctx.base_static_dph.assign(sig.size(), 0.0);
	for (std::size_t k = 0; k < sig.size(); ++k) ctx.base_static_dph[k] = 2.0 * sig.temp_mean_C[k];  // f(T) = 2 T

	const auto warm = candidateById("warmup").build(ctx, 600.0);
	const auto lag = candidateById("thermistor_lag").build(ctx, 0.0);
	const auto mag = candidateById("magnetic").build(ctx, 0.0);
	const auto poly = candidateById("temp_poly_order").build(ctx, 0.0);
	ASSERT_EQ(poly.cols(), 2);
	ASSERT_EQ(warm.cols(), 2);
	ASSERT_EQ(sig.power_on_s.size(), 2u);
	for (std::size_t k = 0; k < sig.size(); ++k)
	{
		const auto i = static_cast<Eigen::Index>(k);
		// the run starts powered and has one power cycle: column 1 decays from the start, column 0
		// from the power-on inside the run
		if (sig.usable[k] && sig.time_s[k] < sig.power_on_s.at(1))
		{
			EXPECT_NEAR(warm(i, 1), std::exp(-(sig.time_s[k] - sig.power_on_s[0]) / 600.0), 1e-12);
			EXPECT_EQ(warm(i, 0), 0.0);
		}
		if (sig.usable[k] && sig.time_s[k] >= sig.power_on_s.at(1))
		{
			EXPECT_NEAR(warm(i, 0), std::exp(-(sig.time_s[k] - sig.power_on_s[1]) / 600.0), 1e-12);
			EXPECT_EQ(warm(i, 1), 0.0);
		}
		if (sig.block[k] >= 0) EXPECT_NEAR(lag(i, 0), 2.0 * sig.dtemp_dt_Cpm[k], 1e-9);  // d/dt f(T) = f' dT/dt
		EXPECT_DOUBLE_EQ(mag(i, 0), sig.field_uT[k]);
		if (sig.usable[k])
		{
			const double x = (sig.temp_mean_C[k] - 20.0) / 50.0;
			EXPECT_NEAR(poly(i, 0), std::pow(x, 4), 1e-12);
			EXPECT_NEAR(poly(i, 1), std::pow(x, 5), 1e-12);
		}
	}
}

TEST(CandidateEffect, HysteresisIsPlayTypeAndKeepsItsBranchThroughSoaks)
{
	// heating at 0.5 C/min for 40 min (20 C), soak 20 min, cooling at 0.5 C/min for 10 min (5 C):
	// closed form of the play operator, span 5 C: h = 1 - exp(-dT/5) while heating, kept during
	// the soak, then -1 + (h_top + 1) exp(-dT_down/5) while cooling
	RunSignals s;
	for (int k = 0; k <= 70; ++k)
	{
		const double t = 60.0 * k;
		const double rate = k <= 40 ? 0.5 : (k <= 60 ? 0.0 : -0.5);
		s.time_s.push_back(t);
		s.dtemp_dt_Cpm.push_back(rate);
		s.temp_mean_C.push_back(k <= 40 ? 0.5 * k : (k <= 60 ? 20.0 : 20.0 - 0.5 * (k - 60)));
		s.block.push_back(0);
	}
	// per-sample change = trapezoid of the rates: 0.5 C up to sample 40, 0.25 C into sample 41
	const auto h = hysteresisBranch(s, 5.0);
	for (int k = 0; k <= 40; ++k) EXPECT_NEAR(h[k], 1 - std::exp(-0.5 * k / 5.0), 1e-12) << k;
	const double top = 1 - std::exp(-20.25 / 5.0);
	for (int k = 41; k <= 60; ++k) EXPECT_NEAR(h[k], top, 1e-12) << "soak keeps the branch, k " << k;
	// cooling: 0.25 C into sample 61, then 0.5 C per sample
	EXPECT_NEAR(h[70], -1 + (top + 1) * std::exp(-(0.25 + 0.5 * 9) / 5.0), 1e-12);
	const auto col = candidateById("hysteresis");
	EXPECT_EQ(col.theta_name, "width_C");
	EXPECT_THROW(hysteresisBranch(s, 0.0), std::invalid_argument);
}

TEST(CandidateEffect, HysteresisPlayOperatorIsLinearAfterAReversalUntilItSaturates)
{
	// heat 0 -> 20 C at 0.5 C per sample, soak, cool: the play of half-width w = 2 C follows
	// h = x / w until x = w (4 samples), then stays at 1; cooling from the top it falls by
	// dx / w per sample and reaches -1 after 2 w = 4 C (8 samples), as the backlash definition
	// p <- min(max(p, x - w), x + w), h = (x - p) / w gives by hand
	RunSignals s;
	for (int k = 0; k <= 80; ++k)
	{
		const double rate = k <= 40 ? 0.5 : (k <= 60 ? 0.0 : -0.5);
		s.time_s.push_back(60.0 * k);
		s.dtemp_dt_Cpm.push_back(rate);
		s.temp_mean_C.push_back(k <= 40 ? 0.5 * k : (k <= 60 ? 20.0 : 20.0 - 0.5 * (k - 60)));
		s.block.push_back(0);
	}
	const auto h = hysteresisPlay(s, 2.0);
	// trapezoid of the rates: 0.5 C per sample up to 40, 0.25 C into 41; soak; 0.25 C into 61
	for (int k = 0; k <= 4; ++k) EXPECT_NEAR(h[k], 0.25 * k, 1e-12) << k;
	for (int k = 4; k <= 60; ++k) EXPECT_NEAR(h[k], 1.0, 1e-12) << "saturated and kept through the soak, k " << k;
	EXPECT_NEAR(h[61], 1.0 - 0.25 / 2.0, 1e-12);
	for (int k = 62; k <= 68; ++k) EXPECT_NEAR(h[k], 1.0 - (0.25 + 0.5 * (k - 61)) / 2.0, 1e-12) << k;
	for (int k = 69; k <= 80; ++k) EXPECT_NEAR(h[k], -1.0, 1e-12) << k;
	EXPECT_THROW(hysteresisPlay(s, 0.0), std::invalid_argument);

	// the candidate's parameter carries the shape: > 0 exponential branch, < 0 play
	const auto& c = candidateById("hysteresis");
	EXPECT_EQ(hysteresisColumn(s, -2.0), h);
	EXPECT_EQ(hysteresisColumn(s, 5.0), hysteresisBranch(s, 5.0));
	EXPECT_EQ(c.theta_grid, hysteresisThetaGrid());
	int count[4] = {0, 0, 0, 0};
	for (double th : c.theta_grid) count[static_cast<int>(hysteresisShapeOf(th).kind)]++;
	EXPECT_EQ(count[static_cast<int>(HysteresisShape::Kind::Play)], 6);
	EXPECT_EQ(count[static_cast<int>(HysteresisShape::Kind::ExponentialBranch)], 6);
	EXPECT_EQ(count[static_cast<int>(HysteresisShape::Kind::RateSaturation)], 6);
	EXPECT_EQ(count[static_cast<int>(HysteresisShape::Kind::RateSign)], 1);
	ASSERT_TRUE(static_cast<bool>(c.describe_theta));
	EXPECT_EQ(c.describe_theta(-2.0), "play operator, half-width 2 C");
	EXPECT_EQ(c.describe_theta(5.0), "exponential branch, span 5 C");
	EXPECT_THROW(hysteresisShapeOf(0.0), std::invalid_argument);
	EXPECT_THROW(hysteresisTheta({HysteresisShape::Kind::Play, -1.0}), std::invalid_argument);
}

TEST(CandidateEffect, HysteresisRateShapesSaturateWithTheRateAndVanishAtSoaks)
{
	// coil rate: a ramp of the rate from -1 to +1 C/min over 201 samples, then a soak (rate 0):
	// the rate saturation is tanh(r / w) there by definition, the sign +-1 outside the dead band
	// and 0 inside it, and both return to 0 at the soak (no memory, unlike branch and play)
	RunSignals s;
	for (int k = 0; k <= 260; ++k)
	{
		const double r = k <= 200 ? -1.0 + 0.01 * k : 0.0;
		s.time_s.push_back(10.0 * k);
		s.dtemp_dt_Cpm.push_back(0.5 * r);  // the mean's rate: not the one the shapes read
		s.dtemp_coil_dt_Cpm.push_back(r);
		s.temp_mean_C.push_back(20.0);
		s.temp_coil_C.push_back(20.0);
		s.block.push_back(0);
	}
	s.dtemp_coil_dt_Cpm[5] = NAN;  // a rate not known counts as 0
	const auto t = hysteresisRateSaturation(s, 0.3);
	const auto g = hysteresisRateSign(s, 0.05);
	for (int k = 0; k <= 260; ++k)
	{
		const double r = k == 5 ? 0.0 : (k <= 200 ? -1.0 + 0.01 * k : 0.0);
		EXPECT_NEAR(t[k], std::tanh(r / 0.3), 1e-12) << k;
		EXPECT_EQ(g[k], r >= 0.05 ? 1.0 : (r <= -0.05 ? -1.0 : 0.0)) << k;
	}
	EXPECT_NEAR(t[200], std::tanh(1.0 / 0.3), 1e-12);
	EXPECT_EQ(t[230], 0.0);
	EXPECT_EQ(g[230], 0.0);
	EXPECT_THROW(hysteresisRateSaturation(s, 0.0), std::invalid_argument);
	EXPECT_THROW(hysteresisRateSign(s, -1.0), std::invalid_argument);

	// theta carries shape and width both ways, each kind in its own range and family
	using K = HysteresisShape::Kind;
	for (const HysteresisShape sh : {HysteresisShape{K::ExponentialBranch, 0.5}, HysteresisShape{K::Play, 20.0},
									 HysteresisShape{K::RateSaturation, 0.15}, HysteresisShape{K::RateSign, 0.05}})
	{
		const double th = hysteresisTheta(sh);
		EXPECT_EQ(hysteresisShapeOf(th).kind, sh.kind);
		EXPECT_NEAR(hysteresisShapeOf(th).width, sh.width, 1e-12 * sh.width);
		EXPECT_EQ(hysteresisFamily(th), static_cast<int>(sh.kind));
		EXPECT_EQ(hysteresisShapeOf(th).ratesOnly(), sh.kind == K::RateSaturation || sh.kind == K::RateSign);
	}
	EXPECT_EQ(hysteresisColumn(s, hysteresisTheta({K::RateSaturation, 0.3})), t);
	EXPECT_EQ(hysteresisColumn(s, hysteresisTheta({K::RateSign, 0.05})), g);
	EXPECT_EQ(describeHysteresisTheta(hysteresisTheta({K::RateSaturation, 0.2})), "rate saturation, tanh(dT/dt / 0.2 C/min)");
	EXPECT_EQ(describeHysteresisTheta(hysteresisTheta({K::RateSign, 0.05})), "sign of the rate (dead band 0.05 C/min)");
	EXPECT_THROW(hysteresisTheta({K::RateSaturation, 0.001}), std::invalid_argument);  // below 0.01 C/min
	EXPECT_THROW(hysteresisTheta({K::Play, 150.0}), std::invalid_argument);  // not below 100 C
	EXPECT_EQ(candidateById("hysteresis").theta_family(hysteresisTheta({K::RateSign, 0.05})),
			  static_cast<int>(K::RateSign));
}

TEST(CandidateEffect, ShupeRateHoldsTheMeanRateAndTheRadialRateDifference)
{
	const auto sig = syntheticSignals();
	CandidateContext ctx;
	ctx.sig = &sig;
	const auto c = candidateById("shupe_rate").build(ctx, 0.0);
	ASSERT_EQ(c.cols(), 2);
	for (std::size_t k = 0; k < sig.size(); ++k)
	{
		EXPECT_DOUBLE_EQ(c(static_cast<Eigen::Index>(k), 0), sig.dtemp_dt_Cpm[k]);
		EXPECT_DOUBLE_EQ(c(static_cast<Eigen::Index>(k), 1), sig.dgradient_dt_Cpm[k]);
	}
}

TEST(CandidateEffect, GradientRateThroughAFirstOrderLag)
{
	// the radial-difference rate steps from 0 to 0.4 C/min at sample 10 and back at 50 (10 s
	// samples): through a first-order lag of tau the column is the step response
	// 0.4 (1 - exp(-(t - t_on)/tau)), then decays as exp(-(t - t_off)/tau); lag 0 is the rate
	// itself; a new block (dropout) restarts the filter at its input
	RunSignals s;
	for (int k = 0; k < 80; ++k)
	{
		s.time_s.push_back(10.0 * k);
		s.dgradient_dt_Cpm.push_back(k >= 10 && k < 50 ? 0.4 : 0.0);
		s.block.push_back(k < 70 ? 0 : 1);
	}
	CandidateContext ctx;
	ctx.sig = &s;
	const auto& cand = candidateById("gradient_rate");
	EXPECT_EQ(cand.theta_name, "lag_s");
	EXPECT_EQ(cand.theta_grid.front(), 0.0);
	const auto c0 = cand.build(ctx, 0.0);
	for (int k = 0; k < 80; ++k) EXPECT_DOUBLE_EQ(c0(k, 0), s.dgradient_dt_Cpm[k]);
	const double tau = 240.0;
	const auto c = cand.build(ctx, tau);
	ASSERT_EQ(c.cols(), 1);
	for (int k = 0; k < 10; ++k) EXPECT_NEAR(c(k, 0), 0.0, 1e-15) << k;
	for (int k = 10; k < 50; ++k) EXPECT_NEAR(c(k, 0), 0.4 * (1 - std::exp(-10.0 * (k - 9) / tau)), 1e-12) << k;
	const double top = 0.4 * (1 - std::exp(-400.0 / tau));
	for (int k = 50; k < 70; ++k) EXPECT_NEAR(c(k, 0), top * std::exp(-10.0 * (k - 49) / tau), 1e-12) << k;
	EXPECT_NEAR(c(70, 0), 0.0, 1e-15);  // new block: the filter restarts at its input
	EXPECT_NE(cand.describe_theta(tau).find("240 s"), std::string::npos);
}

TEST(CandidateEffect, UntestableWithoutTheExcitingColumns)
{
	const auto sig = syntheticSignals(SyntheticProfile::Ramp);  // no table rate, no field
	EXPECT_FALSE(candidateById("scale_factor_temp").untestable_reason(sig).empty());
	EXPECT_FALSE(candidateById("magnetic").untestable_reason(sig).empty());
	EXPECT_TRUE(candidateById("shupe_rate").untestable_reason(sig).empty());
	EXPECT_TRUE(candidateById("radial_gradient").untestable_reason(sig).empty());
}
