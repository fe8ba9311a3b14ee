/* mrpt_fog: fault injection: one thermistor drops out mid-run. */
#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <limits>

#include "FaultRun.h"

using namespace mrpt_fog;

// Bound: with one thermistor missing for the middle third of the validation run the
// compensator runs its fallback model there, and the 100 s bias stability of the whole run is no
// worse than 2x the 4-thermistor result. Checked for each of the 4 thermistors in turn.
TEST(ThermistorDropout, MidRunDropoutFallbackWithinTwiceFourThermistorStability)
{
	const Calibration& cal = faulttest::calibration();
	const FogSeries& run = faulttest::validationRun();
	const auto& used = cal.model.features.thermistors();  // what the selected main model reads
	ASSERT_GE(used.size(), 2u);
	ASSERT_EQ(cal.fallbacks.size(), used.size());
	const CompensatedSeries clean = compensate(cal, run);
	const double s4 = faulttest::stability100_dph(clean);
	const double raw = biasStats(run.time_s, run.rate_dph[2], 100.0).stability_dph;
	std::cout << "4 thermistors: stability " << s4 << " deg/h (raw " << raw << " deg/h)\n";
	ASSERT_LT(s4, raw);  // the calibration does something on this run
	const std::size_t k0 = run.size() / 3, k1 = 2 * run.size() / 3;
	for (std::size_t i = 0; i < run.thermistorCount(); i++)
	{
		FogSeries faulty = run;
		for (std::size_t k = k0; k < k1; k++) faulty.temp_C[i][k] = std::numeric_limits<double>::quiet_NaN();
		const CompensatedSeries c = compensate(cal, faulty);
		const double s = faulttest::stability100_dph(c);
		std::cout << run.thermistors[i].name << " out for samples " << k0 << ".." << k1 << ": stability " << s
				  << " deg/h (" << s / s4 << " x), fallback samples " << c.counters.fallback_samples << "\n";
		// a thermistor of the model: its fallback runs for the dropout (never the no-model path);
		// one the selection left out: nothing changes
		const bool in_model = std::find(used.begin(), used.end(), run.thermistors[i].name) != used.end();
		EXPECT_GE(c.counters.fallback_samples, in_model ? k1 - k0 : 0u) << run.thermistors[i].name;
		EXPECT_LE(c.counters.fallback_samples, in_model ? k1 - k0 + 2 : 0u) << run.thermistors[i].name;
		if (!in_model) EXPECT_EQ(c.compensated_dph, clean.compensated_dph);
		EXPECT_EQ(c.counters.no_model_samples, clean.counters.no_model_samples);
		for (std::size_t k = 0; k < c.compensated_dph.size(); k++)
			ASSERT_TRUE(std::isfinite(c.compensated_dph[k])) << k;
		EXPECT_LE(s, 2.0 * s4) << run.thermistors[i].name;
		// outside the dropout (after the rate window refills) the output is the clean one
		for (std::size_t k = 0; k < k0; k++) ASSERT_EQ(c.compensated_dph[k], clean.compensated_dph[k]);
	}
}

// Two thermistors out at once: no fitted model applies; the mean calibration bias is used (flag
// NoModel), the output stays finite and the raw-minus-mean output has the raw stability.
TEST(ThermistorDropout, TwoMissingUsesMeanBias)
{
	const Calibration& cal = faulttest::calibration();
	FogSeries faulty = faulttest::validationRun();
	const auto& used = cal.model.features.thermistors();
	ASSERT_GE(used.size(), 2u);
	const int a = faulty.thermistorIndex(used[0]), b = faulty.thermistorIndex(used[1]);
	ASSERT_GE(a, 0);
	ASSERT_GE(b, 0);
	const std::size_t k0 = faulty.size() / 3, k1 = 2 * faulty.size() / 3;
	for (std::size_t k = k0; k < k1; k++)
		faulty.temp_C[a][k] = faulty.temp_C[b][k] = std::numeric_limits<double>::quiet_NaN();
	const CompensatedSeries c = compensate(cal, faulty);
	EXPECT_GE(c.counters.no_model_samples, k1 - k0);
	for (std::size_t k = k0; k < k1; k++)
	{
		ASSERT_TRUE(c.flags[k] & CompensationFlag::NoModel) << k;
		ASSERT_DOUBLE_EQ(c.bias_dph[k], cal.mean_bias_dph) << k;
	}
}
