/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The second, independent test generator (tests/support/LumpedCoilGenerator.h): layout, power-off
 * rows, noise level, effect scaling, determinism, refusals. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>

#include <cmath>
#include <filesystem>

#include "LumpedCoilGenerator.h"

using fogtest::LumpedCoilOptions;
using fogtest::makeLumpedCoilRun;

TEST(LumpedCoilGenerator, LabProfileHasPowerOffRowsTableFieldAndTwoTurnOns)
{
	const auto run = makeLumpedCoilRun({});
	const auto& s = run.series;
	EXPECT_NO_THROW(s.validate());
	EXPECT_EQ(s.size(), 27001u);  // 27000 s at 1 s
	EXPECT_EQ(s.thermistorCount(), 3u);
	std::size_t off = 0;
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		off += s.gyroOn(k) ? 0 : 1;
		EXPECT_EQ(std::isnan(s.rate_dph[2][k]), !s.gyroOn(k)) << k;
		for (const auto& col : s.temp_C) EXPECT_TRUE(std::isfinite(col[k])) << k;  // thermistors always log
	}
	EXPECT_EQ(off, 1800u);  // 600 s before the first turn-on + a 1200 s power cycle
	EXPECT_EQ(s.turnOnSamples().size(), 2u);
	EXPECT_FALSE(s.table_rate_dph.empty());
	EXPECT_FALSE(s.field_uT.empty());
	// self-heating: after the turn-on the housing warms above the 25 C chamber (steady state +3 C)
	const int hs = s.thermistorIndex("Hs");
	EXPECT_NEAR(s.temp_C[hs][0], 25.0, 0.02);
	EXPECT_GT(s.temp_C[hs][600 + 2400], 26.0);
}

TEST(LumpedCoilGenerator, NoiseIsWhitePlusWanderOfTheStatedSize)
{
	LumpedCoilOptions o;
	o.seed = 3;
	const auto run = makeLumpedCoilRun(o);
	const auto& s = run.series;
	double sum = 0, sum2 = 0, n = 0, d2 = 0, nd = 0;
	double prev = NAN;
	for (std::size_t k = 0; k < s.size(); ++k)
	{
		if (!s.gyroOn(k))
		{
			prev = NAN;
			continue;
		}
		const double e = s.rate_dph[2][k] - s.table_rate_dph[k] - run.base_bias_dph[k];
		sum += e;
		sum2 += e * e;
		n += 1;
		if (std::isfinite(prev))
		{
			d2 += (e - prev) * (e - prev);
			nd += 1;
		}
		prev = e;
	}
	const double var = sum2 / n - (sum / n) * (sum / n);
	// total: white 0.01 + wander 0.01 -> sd 0.0141 (wander over ~14 time constants: +-25 %)
	EXPECT_NEAR(std::sqrt(var), run.noise_rms_dph, 0.25 * run.noise_rms_dph);
	EXPECT_NEAR(run.noise_rms_dph, std::hypot(0.01, 0.01), 1e-12);
	// first differences: 2 white^2 + (tiny wander increments) -> white sd 0.01 within 3 %
	EXPECT_NEAR(std::sqrt(d2 / nd / 2.0), 0.01, 0.0003);
}

TEST(LumpedCoilGenerator, EffectsScaleLinearlyAndVanishWhereTheGyroIsOff)
{
	for (const auto& id : fogtest::lumpedCoilEffects())
	{
		LumpedCoilOptions a, b;
		a.hidden[id] = 1.0;
		b.hidden[id] = 3.0;
		const auto ra = makeLumpedCoilRun(a), rb = makeLumpedCoilRun(b);
		const auto& ea = ra.effect_dph.at(id);
		const auto& eb = rb.effect_dph.at(id);
		double peak = 0;
		for (std::size_t k = 0; k < ea.size(); ++k)
		{
			EXPECT_NEAR(eb[k], 3.0 * ea[k], 1e-12 + 1e-9 * std::abs(eb[k])) << id << " " << k;
			if (!ra.series.gyroOn(k)) EXPECT_EQ(ea[k], 0.0) << id;
			peak = std::max(peak, std::abs(ea[k]));
		}
		EXPECT_GT(peak, 0.0) << id;
		// same seed, same noise: the rate differs by exactly the extra effect
		for (std::size_t k = 0; k < ea.size(); k += 997)
			if (ra.series.gyroOn(k))
				EXPECT_NEAR(rb.series.rate_dph[2][k] - ra.series.rate_dph[2][k], 2.0 * ea[k], 1e-9) << id;
	}
}

TEST(LumpedCoilGenerator, DeterministicPerSeedAndDifferentAcrossSeeds)
{
	LumpedCoilOptions o;
	o.profile = "short";
	const auto a = makeLumpedCoilRun(o), b = makeLumpedCoilRun(o);
	o.seed = 2;
	const auto c = makeLumpedCoilRun(o);
	EXPECT_EQ(a.series.rate_dph[2], b.series.rate_dph[2]);
	EXPECT_NE(a.series.rate_dph[2], c.series.rate_dph[2]);
}

TEST(LumpedCoilGenerator, CoolingProfileIsMonotonicAndRefusesEffectsItCannotExcite)
{
	LumpedCoilOptions o;
	o.profile = "cooling";
	const auto run = makeLumpedCoilRun(o);
	const auto& ca = run.series.temp_C[0];
	// the place temperature never rises by more than the quantum + noise
	double lowest = ca.front();
	for (double v : ca)
	{
		EXPECT_LE(v, lowest + 0.03);
		lowest = std::min(lowest, v);
	}
	EXPECT_LT(ca.back(), ca.front() - 7.0);  // 24 -> 16 C air (+3 C self-heating at both ends)
	for (const char* id : {"magnetic", "scale_factor_temp", "warmup"})
	{
		o.hidden = {{id, 1.0}};
		EXPECT_THROW(makeLumpedCoilRun(o), std::invalid_argument) << id;
	}
	o.hidden = {{"no_such_effect", 1.0}};
	EXPECT_THROW(makeLumpedCoilRun(o), std::invalid_argument);
	o.hidden.clear();
	o.profile = "nope";
	EXPECT_THROW(makeLumpedCoilRun(o), std::invalid_argument);
}

TEST(LumpedCoilGenerator, CsvRoundTripKeepsThePowerOffRows)
{
	const auto run = makeLumpedCoilRun({});
	const auto path = (std::filesystem::temp_directory_path() / "lumped_coil_roundtrip.csv").string();
	mrpt_fog::writeFogCsv(path, run.series);
	const auto back = mrpt_fog::readFogCsv(path);
	std::filesystem::remove(path);
	ASSERT_EQ(back.size(), run.series.size());
	EXPECT_EQ(back.power, run.series.power);
	EXPECT_EQ(back.turnOnSamples(), run.series.turnOnSamples());
	for (std::size_t k = 0; k < back.size(); k += 101)
	{
		EXPECT_EQ(std::isnan(back.rate_dph[2][k]), std::isnan(run.series.rate_dph[2][k]));
		if (!std::isnan(back.rate_dph[2][k])) EXPECT_EQ(back.rate_dph[2][k], run.series.rate_dph[2][k]);
	}
}
