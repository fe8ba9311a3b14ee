/* mrpt_fog: fault injection: spikes and out-of-range readings on the thermistors. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/ThermistorHealth.h>

#include <iostream>
#include <limits>
#include <random>

#include "FaultRun.h"

using namespace mrpt_fog;

// Bound: spikes of 2-40 degC (single samples and 3-sample bursts, 0.5 % of the readings of every
// thermistor) are all removed by the screening and no clean reading is touched; compensated with
// the screening, the 100 s stability is within 1.5x the clean result (unscreened it is printed).
TEST(ThermistorSpikes, SpikesRemovedAndStabilityKept)
{
	const Calibration& cal = faulttest::calibration();
	const FogSeries& clean = faulttest::validationRun();
	const double s_clean = faulttest::stability100_dph(compensate(cal, clean));
	FogSeries faulty = clean;
	std::mt19937_64 rng(7);
	std::uniform_real_distribution<double> amp(2.0, 40.0);
	std::bernoulli_distribution sign(0.5), burst(0.3);
	std::vector<std::vector<bool>> spiked(clean.thermistorCount(), std::vector<bool>(clean.size(), false));
	std::size_t n_spiked = 0;
	for (std::size_t i = 0; i < clean.thermistorCount(); i++)
	{
		std::uniform_int_distribution<std::size_t> pos(100, clean.size() - 10);
		for (std::size_t e = 0; e < clean.size() / 200; e++)
		{
			const std::size_t k = pos(rng);
			const double a = sign(rng) ? amp(rng) : -amp(rng);
			for (std::size_t b = 0; b < (burst(rng) ? 3u : 1u); b++)
			{
				if (!spiked[i][k + b]) n_spiked++;
				spiked[i][k + b] = true;
				faulty.temp_C[i][k + b] = clean.temp_C[i][k + b] + a;
			}
		}
	}
	const double s_unscreened = faulttest::stability100_dph(compensate(cal, faulty));
	const ThermistorScreening sc = screenThermistors(faulty);
	EXPECT_EQ(sc.rejected_readings, n_spiked);
	for (std::size_t i = 0; i < clean.thermistorCount(); i++)
	{
		EXPECT_EQ(sc.counters[i].level_changes, 0u);
		for (std::size_t k = 0; k < clean.size(); k++)
		{
			if (spiked[i][k])
				ASSERT_TRUE(std::isnan(faulty.temp_C[i][k])) << i << " " << k;
			else
				ASSERT_EQ(faulty.temp_C[i][k], clean.temp_C[i][k]) << i << " " << k;
		}
	}
	const CompensatedSeries c = compensate(cal, faulty);
	const double s = faulttest::stability100_dph(c);
	std::cout << n_spiked << " spiked readings: stability screened " << s << " deg/h (" << s / s_clean
			  << " x clean " << s_clean << "), unscreened " << s_unscreened << " deg/h (" << s_unscreened / s_clean
			  << " x)\n";
	for (double v : c.compensated_dph) ASSERT_TRUE(std::isfinite(v));
	EXPECT_LE(s, 1.5 * s_clean);
}

// Non-finite and out-of-range readings are dropouts; a lasting jump (a re-seated sensor) is
// accepted as a new level after spike_max_duration_s.
TEST(ThermistorSpikes, OutOfRangeAndLevelChange)
{
	ThermistorHealth h(1);
	double x = 20.0;
	h.step(0, &x);
	for (double bad : {std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), -273.15,
					   1e6, 151.0})
	{
		x = bad;
		static double t = 1;
		EXPECT_TRUE(h.step(t++, &x));
		EXPECT_TRUE(std::isnan(x));
		EXPECT_EQ(h.state(0), ThermistorState::OutOfRange);
	}
	x = std::nan("");
	EXPECT_FALSE(h.step(10, &x));
	EXPECT_EQ(h.state(0), ThermistorState::Dropout);
	// +10 degC for good from t = 100 s: spikes for 20 s, then the new level
	ThermistorHealth g(1);
	int accepted_at = -1;
	for (int k = 0; k < 200; k++)
	{
		x = (k >= 100 ? 30.0 : 20.0);
		g.step(k, &x);
		if (k >= 100 && accepted_at < 0 && !std::isnan(x)) accepted_at = k;
		if (k > 100 && k < 120) EXPECT_EQ(g.state(0), ThermistorState::Spike) << k;
	}
	EXPECT_EQ(accepted_at, 120);
	EXPECT_EQ(g.counters(0).level_changes, 1u);
	EXPECT_EQ(g.counters(0).spike, 20u);
}
