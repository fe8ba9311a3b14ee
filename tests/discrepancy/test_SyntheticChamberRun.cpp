/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include "support/SyntheticChamberRun.h"

#include <Eigen/Dense>
#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

TEST(SyntheticChamberRun, HiddenEffectHasTheRequestedUnexplainedShare)
{
	const auto r = makeSyntheticChamberRun(20, 1, {{"radial_gradient", 3.0}});
	r.series.validate();
	const auto& e = r.effect_dph.at("radial_gradient");
	ASSERT_EQ(e.size(), r.series.size());
	// unexplained part (vs cubic in the true mean temperature): recompute with the thermistor mean
	// (true mean + 0.005 C offset + 0.002 C noise) -> close to 3 x noise RMS
	std::vector<std::size_t> rows;
	for (std::size_t k = 0; k < e.size(); ++k)
		if (r.series.power[k] > 0.5) rows.push_back(k);
	Eigen::MatrixXd X(rows.size(), 4);
	Eigen::VectorXd y(rows.size());
	for (std::size_t i = 0; i < rows.size(); ++i)
	{
		double T = 0;
		for (int j = 0; j < 4; ++j) T += 0.25 * r.series.temp_C[j][rows[i]];
		const double x = (T - 20) / 50;
		X.row(i) << 1, x, x * x, x * x * x;
		y(i) = e[rows[i]];
	}
	const Eigen::VectorXd res = y - X * X.colPivHouseholderQr().solve(y);
	EXPECT_NEAR(std::sqrt(res.squaredNorm() / rows.size()) / r.noise_rms_dph, 3.0, 0.05);
}

TEST(SyntheticChamberRun, ProfilesAndConfounders)
{
	SyntheticRunOptions o;
	o.dt_s = 20;
	o.gap = true;
	o.outliers = 4;
	o.thermistor_quantum_C = 0.01;
	const auto r = makeSyntheticChamberRun(o);
	r.series.validate();
	bool gapSeen = false;
	for (std::size_t k = 1; k < r.series.size(); ++k) gapSeen = gapSeen || r.series.time_s[k] - r.series.time_s[k - 1] > 1000;
	EXPECT_TRUE(gapSeen);
	const double q = r.series.temp_C[0][10] / 0.01;
	EXPECT_NEAR(q, std::round(q), 1e-6);
	EXPECT_FALSE(r.series.table_rate_dph.empty());
	EXPECT_FALSE(r.series.field_uT.empty());
	o.profile = SyntheticProfile::Ramp;
	const auto ramp = makeSyntheticChamberRun(o);
	EXPECT_TRUE(ramp.series.table_rate_dph.empty());
	o.profile = SyntheticProfile::AllConditions;
	o.hidden["heat_source"] = 1;
	EXPECT_THROW(makeSyntheticChamberRun(o), std::invalid_argument);
}

TEST(SyntheticChamberRun, ThermistorLagIsAppliedAndReported)
{
	const auto r = makeSyntheticChamberRun(20, 1, {{"thermistor_lag", 1.0}});
	EXPECT_GT(r.thermistor_tau_s, 1.0);
	EXPECT_LT(r.thermistor_tau_s, 2000.0);
}
