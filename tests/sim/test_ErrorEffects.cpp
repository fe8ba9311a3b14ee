/* mrpt_fog: tests of effect selection. */
#include <gtest/gtest.h>
#include <mrpt_fog/sim/ErrorEffects.h>

using namespace mrpt_fog::sim;

TEST(ErrorEffects, StableIdsAndSelection)
{
	// The ids are a contract with the model-gap workflow.
	const std::vector<std::string> expected = {"shupe_rate", "radial_gradient", "gradient_rate", "thermistor_lag",
											   "hysteresis", "warmup", "scale_factor_temp", "magnetic",
											   "temp_poly_order", "heat_source", "earth_rate"};
	EXPECT_EQ(allEffectIds(), expected);
	EXPECT_EQ(effectsFromSelection({}), defaultEffects());
	EXPECT_EQ(effectsFromSelection({"shupe_rate", "magnetic"}), (EffectSet{"shupe_rate", "magnetic"}));
	EffectSet minus = defaultEffects();
	minus.erase("warmup");
	EXPECT_EQ(effectsFromSelection({"-warmup"}), minus);
	EXPECT_EQ(effectsFromSelection({"none", "+earth_rate"}), (EffectSet{"earth_rate"}));
	EXPECT_EQ(effectsToString({}), "none");
	EXPECT_EQ(effectsToString({"warmup", "shupe_rate"}), "shupe_rate,warmup");
	EXPECT_THROW(effectsFromSelection({"shupe"}), std::invalid_argument);
	EXPECT_THROW(effectsFromSelection({"-nope"}), std::invalid_argument);
}
