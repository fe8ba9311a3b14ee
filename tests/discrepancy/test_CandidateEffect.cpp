/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/CandidateEffect.h>
#include <mrpt_fog/discrepancy/SyntheticChamberRun.h>

#include <cmath>
#include <set>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

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
	SyntheticRunOptions o;
	o.dt_s = 20;
	const auto run = makeSyntheticChamberRun(o);
	const auto sig = computeRunSignals(run.series);
	CandidateContext ctx;
	ctx.sig = &sig;
	ctx.static_temp_C = sig.temp_mean_C;
	ctx.base_static_order = 3;
	ctx.base_static_dph.assign(sig.size(), 0.0);
	for (std::size_t k = 0; k < sig.size(); ++k) ctx.base_static_dph[k] = 2.0 * sig.temp_mean_C[k];  // f(T) = 2 T

	const auto warm = candidateById("warmup").build(ctx, 600.0);
	const auto lag = candidateById("thermistor_lag").build(ctx, 0.0);
	const auto hyst = candidateById("hysteresis").build(ctx, 0.0);
	const auto mag = candidateById("magnetic").build(ctx, 0.0);
	const auto poly = candidateById("temp_poly_order").build(ctx, 0.0);
	ASSERT_EQ(poly.cols(), 2);
	for (std::size_t k = 0; k < sig.size(); ++k)
	{
		const auto i = static_cast<Eigen::Index>(k);
		if (sig.usable[k] && sig.time_s[k] < sig.power_on_s.at(1))
			EXPECT_NEAR(warm(i, 0), std::exp(-(sig.time_s[k] - sig.power_on_s[0]) / 600.0), 1e-12);
		if (sig.block[k] >= 0) EXPECT_NEAR(lag(i, 0), 2.0 * sig.dtemp_dt_Cpm[k], 1e-9);  // d/dt f(T) = f' dT/dt
		EXPECT_NEAR(hyst(i, 0), std::tanh(sig.dtemp_dt_Cpm[k] / 0.05), 1e-12);
		EXPECT_DOUBLE_EQ(mag(i, 0), sig.field_uT[k]);
		if (sig.usable[k])
		{
			const double x = (sig.temp_mean_C[k] - 20.0) / 50.0;
			EXPECT_NEAR(poly(i, 0), std::pow(x, 4), 1e-12);
			EXPECT_NEAR(poly(i, 1), std::pow(x, 5), 1e-12);
		}
	}
}

TEST(CandidateEffect, UntestableWithoutTheExcitingColumns)
{
	SyntheticRunOptions o;
	o.profile = "ramp";  // no table rate, no field
	o.dt_s = 20;
	const auto run = makeSyntheticChamberRun(o);
	const auto sig = computeRunSignals(run.series);
	EXPECT_FALSE(candidateById("scale_factor_temp").untestable_reason(sig).empty());
	EXPECT_FALSE(candidateById("magnetic").untestable_reason(sig).empty());
	EXPECT_TRUE(candidateById("shupe_rate").untestable_reason(sig).empty());
	EXPECT_TRUE(candidateById("radial_gradient").untestable_reason(sig).empty());
}
