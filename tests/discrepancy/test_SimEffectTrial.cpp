/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** The real-simulator trial harness: the hidden effect is scaled to the requested
 * effect-to-noise ratio, its truth is what the simulator adds, and bad input is refused. */
#include <gtest/gtest.h>
#include "support/SimEffectTrial.h"

#include <cmath>

using namespace mrpt_fog::discrepancy;

namespace
{
SimTrialSpec spec(const std::string& id, double ratio)
{
	SimTrialSpec s;
	s.hidden = id;
	s.ratio = ratio;
	s.seed = 3;
	s.rate_hz = 0.05;
	return s;
}
}  // namespace

TEST(SimEffectTrial, LinearEffectHitsTheRatioExactly)
{
	for (const std::string id : {"radial_gradient", "magnetic", "hysteresis"})
		for (double ratio : {1.0, 3.0})
		{
			const auto r = makeSimTrialRuns(spec(id, ratio));
			ASSERT_GT(r.analysed.noise_rms_dph, 0.0);
			// the simulator's terms are linear in these coefficients: the scaled run hits the ratio
			EXPECT_NEAR(r.analysed.effect_rms_dph / r.analysed.noise_rms_dph, ratio, 1e-6 * ratio) << id;
			// the confirmation run has the same device, so a similar (not equal) share
			EXPECT_NEAR(r.confirm.effect_rms_dph / r.analysed.effect_rms_dph, 1.0, 0.25) << id;
		}
}

TEST(SimEffectTrial, ThermistorLagReachesTheRatioAfterSecantSteps)
{
	const auto r = makeSimTrialRuns(spec("thermistor_lag", 3.0));
	EXPECT_NEAR(r.analysed.effect_rms_dph / r.analysed.noise_rms_dph, 3.0, 0.15);
	EXPECT_GT(r.device.parameter_value, 0.0);
}

TEST(SimEffectTrial, MagneticTruthIsCoefficientTimesField)
{
	// closed form: the simulator's magnetic term is k x field, k the scaled coefficient
	const auto r = makeSimTrialRuns(spec("magnetic", 3.0));
	const double k = r.device.parameter_value;
	ASSERT_EQ(r.analysed.effect_dph.size(), r.analysed.series.size());
	ASSERT_EQ(r.analysed.series.field_uT.size(), r.analysed.series.size());
	double peak = 0;
	for (std::size_t i = 0; i < r.analysed.series.size(); ++i)
	{
		if (r.analysed.series.power[i] < 0.5) continue;
		EXPECT_NEAR(r.analysed.effect_dph[i], k * r.analysed.series.field_uT[i], 1e-12);
		peak = std::max(peak, std::fabs(r.analysed.effect_dph[i]));
	}
	EXPECT_GT(peak, 0.0);
}

TEST(SimEffectTrial, NullRunsCarryNoEffect)
{
	const auto r = makeSimTrialRuns(spec("", 1.0));
	EXPECT_TRUE(r.analysed.effect_dph.empty());
	EXPECT_GT(r.analysed.noise_rms_dph, 0.0);
	EXPECT_NE(r.analysed.series.rate_dph[2], r.confirm.series.rate_dph[2]);  // other seed
}

TEST(SimEffectTrial, BadInputIsRefused)
{
	EXPECT_THROW(makeSimTrialRuns(spec("heat_source", 1.0)), std::invalid_argument);
	EXPECT_THROW(makeSimTrialRuns(spec("no_such_effect", 1.0)), std::invalid_argument);
	EXPECT_THROW(makeSimTrialRuns(spec("magnetic", 0.0)), std::invalid_argument);
	auto s = spec("magnetic", 1.0);
	s.profile = "no_such_profile";
	EXPECT_THROW(makeSimTrialRuns(s), std::invalid_argument);
}
