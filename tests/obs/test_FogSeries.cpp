/* Tests of mrpt_fog::FogSeries: invariants and the errors that name the bad column/sample. */
#include <gtest/gtest.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <cmath>

using namespace mrpt_fog;

namespace
{
FogSeries twoThermistorSeries(std::size_t n)
{
	FogSeries s;
	s.thermistors = {{"Ti1", CoilSide::Inner, 0.0}, {"To1", CoilSide::Outer, 0.0}};
	s.resize(n);
	for (std::size_t k = 0; k < n; k++)
	{
		s.time_s[k] = 0.1 * static_cast<double>(k);
		s.rate_dph[2][k] = 1.0;
		s.temp_C[0][k] = 20.0;
		s.temp_C[1][k] = 21.0;
	}
	return s;
}

std::string validationMessage(const FogSeries& s)
{
	try
	{
		s.validate();
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace

TEST(FogSeries, ValidSeriesPasses)
{
	auto s = twoThermistorSeries(10);
	EXPECT_NO_THROW(s.validate());
	EXPECT_EQ(s.thermistorIndex("To1"), 1);
	EXPECT_EQ(s.thermistorIndex("nope"), -1);
	EXPECT_EQ(s.primaryAxis(), GyroAxis::Z);
}

TEST(FogSeries, DropoutIsNaNAndAllowed)
{
	auto s = twoThermistorSeries(5);
	s.temp_C[1][2] = std::nan("");
	EXPECT_NO_THROW(s.validate());
}

TEST(FogSeries, NonMonotonicTimeNamesSample)
{
	auto s = twoThermistorSeries(5);
	s.time_s[3] = s.time_s[2];
	const auto msg = validationMessage(s);
	EXPECT_NE(msg.find("not strictly increasing at sample 3"), std::string::npos) << msg;
}

TEST(FogSeries, ColumnSizeMismatchNamesColumn)
{
	auto s = twoThermistorSeries(5);
	s.temp_C[1].pop_back();
	const auto msg = validationMessage(s);
	EXPECT_NE(msg.find("temp_To1_C"), std::string::npos) << msg;
}

TEST(FogSeries, NonFiniteRateRejected)
{
	auto s = twoThermistorSeries(5);
	s.rate_dph[2][4] = std::nan("");
	const auto msg = validationMessage(s);
	EXPECT_NE(msg.find("rate_z_dph at sample 4"), std::string::npos) << msg;
}

TEST(FogSeries, BadAndDuplicateNamesRejected)
{
	auto s = twoThermistorSeries(3);
	s.thermistors[1].name = "Ti1";
	EXPECT_NE(validationMessage(s).find("duplicate"), std::string::npos);
	s.thermistors[1].name = "bad name";
	EXPECT_NE(validationMessage(s).find("invalid thermistor name"), std::string::npos);
}

TEST(FogSeries, CoilSideParsing)
{
	EXPECT_EQ(coilSideFromString("Inner"), CoilSide::Inner);
	EXPECT_EQ(coilSideFromString("outer"), CoilSide::Outer);
	EXPECT_THROW(coilSideFromString("middle"), std::invalid_argument);
	EXPECT_STREQ(toString(CoilSide::Outer), "outer");
}

TEST(FogSeries, MetadataKeepsOrderAndReplaces)
{
	FogSeries s;
	s.setMetadata("latitude_deg", "40");
	s.setMetadata("custom", "x");
	s.setMetadata("latitude_deg", "41");
	ASSERT_EQ(s.metadata.size(), 2u);
	EXPECT_EQ(s.metadataValue("latitude_deg"), "41");
	EXPECT_EQ(s.metadataValue("absent", "dflt"), "dflt");
}
