/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/ModelPreset.h>

using namespace mrpt_fog;

namespace
{
const std::vector<ThermistorInfo> kLayout = {{"Ti1", CoilSide::Inner, 0}, {"To1", CoilSide::Outer, 0},
											 {"Ti2", CoilSide::Inner, 180}, {"To2", CoilSide::Outer, 180}};
std::size_t terms(const std::string& p) { return presetFeatures(parseModelPreset(p, kLayout)).termCount(); }
}  // namespace

// Term counts follow the seed's equations (constant included).
TEST(ModelPreset, SeedEquationsTermCounts)
{
	EXPECT_EQ(terms("multipoint"), 33u);  // 4 x (5 + 3) + 1: seed eq. 2
	EXPECT_EQ(terms("multipoint:Ti1,To1"), 17u);
	EXPECT_EQ(terms("multipoint@3/1"), 17u);
	EXPECT_EQ(terms("M1"), 6u);  // eq. 3
	EXPECT_EQ(terms("M2:To2"), 9u);  // eq. 4
	EXPECT_EQ(terms("M3"), 12u);  // eq. 5
	EXPECT_EQ(terms("M4:Ti2,To2"), 7u);  // eq. 6
	EXPECT_EQ(terms("terms:T(Ti1)^1;dT(Ti1-To1)^2"), 3u);
	EXPECT_EQ(parseModelPreset("points:2", kLayout).points_k, 2);
}

TEST(ModelPreset, DefaultsPickInnerAndNearestOuter)
{
	const auto p = parseModelPreset("M3", kLayout);
	EXPECT_EQ(p.thermistors, (std::vector<std::string>{"Ti1", "To1"}));
	const auto f = presetFeatures(parseModelPreset("M4:Ti2,To2", kLayout));
	EXPECT_EQ(f.termNames()[1], "dT(Ti2-To2)^1");
	EXPECT_EQ(f.termNames().back(), "d/dt dT(Ti2-To2)^3");
	EXPECT_EQ(parseModelPreset("M1", kLayout).thermistors, (std::vector<std::string>{"Ti1"}));
}

// Orders written @T set the temperature order only ("M1:imu@3" was refused); M1 has
// no rate terms, so a rate order other than 0 is refused with the reason, not silently ignored.
TEST(ModelPreset, TemperatureOrderAloneAndM1WithoutRates)
{
	const auto m1 = parseModelPreset("M1:Ti2@3", kLayout);
	EXPECT_EQ(m1.temp_order, 3);
	EXPECT_EQ(m1.thermistors, (std::vector<std::string>{"Ti2"}));
	EXPECT_EQ(presetFeatures(m1).termCount(), 4u);
	EXPECT_EQ(parseModelPreset("M1@3/0", kLayout).temp_order, 3);
	const auto mp = parseModelPreset("multipoint@2", kLayout);
	EXPECT_EQ(mp.temp_order, 2);
	EXPECT_EQ(mp.rate_order, 3);
	try
	{
		parseModelPreset("M1:Ti1@3/1", kLayout);
		ADD_FAILURE() << "M1 with a rate order accepted";
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("no rate terms"), std::string::npos) << e.what();
	}
}

TEST(ModelPreset, BadPresetsThrowWithReason)
{
	for (const std::string p : {"", "multi", "multipoint:Tx", "M1:Ti1,To1", "M3:Ti1", "M3:Ti1,Ti1", "points:0", "points:5",
								"points:x", "points", "multipoint@6/3", "multipoint@5/4", "multipoint@", "multipoint@5/", "M1@3/1", "terms:",
								"terms:T(Tx)^1", "multipoint:Ti1,Ti1"})
		EXPECT_THROW(parseModelPreset(p, kLayout), std::invalid_argument) << p;
	try
	{
		parseModelPreset("multipoint:Tx", kLayout);
	}
	catch (const std::invalid_argument& e)
	{
		EXPECT_NE(std::string(e.what()).find("Ti1, To1, Ti2, To2"), std::string::npos) << e.what();
	}
	EXPECT_THROW(parseModelPreset("M3", {{"A", CoilSide::Inner, 0}}), std::invalid_argument);  // no outer
}
