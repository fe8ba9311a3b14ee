/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The third generator's own checks (tests/support/ShellCoilGenerator.h): what it writes is the
 * truth it reports, its noise has the stated white level, bad options are refused. */
#include <gtest/gtest.h>

#include <cmath>

#include "support/ShellCoilGenerator.h"

using namespace fogtest;

TEST(ShellCoilGenerator, HiddenEffectIsTheDifferenceToItsNullTwin)
{
	// same seed, with and without the effect: identical noise, so the rate differs by the
	// effect's truth (up to the output's angle quantum per sample)
	ShellCoilOptions o;
	o.dt_s = 10.0;
	o.seed = 3;
	const auto null = makeShellCoilRun(o);
	o.hidden["radial_gradient"] = 2.0;
	const auto with = makeShellCoilRun(o);
	const auto& e = with.effect_dph.at("radial_gradient");
	const double quantum_dph = o.angle_quantum_arcsec / o.dt_s;  // arcsec/s = deg/h
	double rms = 0;
	std::size_t n = 0;
	for (std::size_t k = 0; k < e.size(); ++k)
	{
		if (!with.series.gyroOn(k)) continue;
		EXPECT_NEAR(with.series.rate_dph[2][k] - null.series.rate_dph[2][k], e[k], 2.0 * quantum_dph + 1e-9) << k;
		rms += e[k] * e[k];
		++n;
	}
	ASSERT_GT(n, 1000u);
	EXPECT_GT(std::sqrt(rms / n), 0.5 * 2.0 * with.noise_100s_dph);  // its unexplained part is 2x the noise
	EXPECT_TRUE(null.effect_dph.empty());
}

TEST(ShellCoilGenerator, WhiteNoiseHasTheStatedAngleRandomWalk)
{
	// first differences at 2 s are dominated by the white part: sd / sqrt(2) = ARW x 60 / sqrt(dt)
	ShellCoilOptions o;
	o.dt_s = 2.0;
	o.seed = 4;
	const auto run = makeShellCoilRun(o);
	double s = 0;
	std::size_t n = 0;
	for (std::size_t k = 1; k < run.series.size(); ++k)
		if (run.series.gyroOn(k) && run.series.gyroOn(k - 1))
		{
			const auto& table = run.series.table_rate_dph;  // the bias, not the applied table rate
			const double d = (run.series.rate_dph[2][k] - table[k]) - (run.series.rate_dph[2][k - 1] - table[k - 1]);
			s += d * d;
			++n;
		}
	const double white = std::sqrt(s / n / 2.0);
	EXPECT_NEAR(white, o.arw_dpsh * 60.0 / std::sqrt(o.dt_s), 0.05 * o.arw_dpsh * 60.0 / std::sqrt(o.dt_s));
	EXPECT_GT(run.noise_100s_dph, 0.006);  // white alone gives 0.006 deg/h over 100 s; flicker and walk add
	EXPECT_LT(run.noise_100s_dph, 0.02);
}

TEST(ShellCoilGenerator, BadOptionsAreRefused)
{
	ShellCoilOptions o;
	o.dt_s = 0.001;
	EXPECT_THROW(makeShellCoilRun(o), std::invalid_argument);
	o.dt_s = 10;
	o.hidden["no_such"] = 1;
	EXPECT_THROW(makeShellCoilRun(o), std::invalid_argument);
	o.hidden = {{"magnetic", -1.0}};
	EXPECT_THROW(makeShellCoilRun(o), std::invalid_argument);
}
