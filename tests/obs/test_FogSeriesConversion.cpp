/* Tests of FogSeries <-> CObservationFOG conversion. */
#include <gtest/gtest.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>

#include <cmath>

using namespace mrpt_fog;

TEST(FogSeriesConversion, RoundTripKeepsValuesAndDropouts)
{
	FogSeries s;
	s.sensor_label = "FOG_A";
	s.epoch_s = 1.7e9;
	s.thermistors = {{"Ti1", CoilSide::Inner, 0.0}, {"To2", CoilSide::Outer, 180.0}};
	s.has_axis = {true, false, true};
	s.table_rate_dph = {0.0, 0.0, 0.0};
	s.resize(3);
	for (std::size_t k = 0; k < 3; k++)
	{
		s.time_s[k] = 0.125 * static_cast<double>(k);  // exact in binary and in the clock's 100 ns ticks
		s.rate_dph[0][k] = -1.5 + static_cast<double>(k);
		s.rate_dph[2][k] = 10.25 * static_cast<double>(k);
		s.temp_C[0][k] = 20.0 + 0.01 * static_cast<double>(k);
		s.temp_C[1][k] = (k == 1) ? std::nan("") : -40.0;
		s.table_rate_dph[k] = 15.0 * static_cast<double>(k);
	}
	const auto obs = observationsFromSeries(s);
	ASSERT_EQ(obs.size(), 3u);
	EXPECT_FALSE(obs[1]->tempValid[1]);
	const FogSeries r = seriesFromObservations(obs);
	EXPECT_EQ(r.sensor_label, "FOG_A");
	EXPECT_TRUE(r.sameLayout(s));
	EXPECT_DOUBLE_EQ(r.epoch_s, s.epoch_s);
	for (std::size_t k = 0; k < 3; k++)
	{
		EXPECT_NEAR(r.time_s[k], s.time_s[k], 1e-6);
		EXPECT_EQ(r.rate_dph[0][k], s.rate_dph[0][k]);
		EXPECT_EQ(r.rate_dph[2][k], s.rate_dph[2][k]);
		EXPECT_EQ(r.temp_C[0][k], s.temp_C[0][k]);
		EXPECT_EQ(std::isnan(r.temp_C[1][k]), k == 1);
		EXPECT_EQ(r.table_rate_dph[k], s.table_rate_dph[k]);
	}
	EXPECT_TRUE(r.field_uT.empty());
	EXPECT_TRUE(r.power.empty());
}

TEST(FogSeriesConversion, LayoutChangeIsAnError)
{
	FogSeries s;
	s.thermistors = {{"Ti1", CoilSide::Inner, 0.0}};
	s.resize(2);
	s.time_s = {0.0, 1.0};
	auto obs = observationsFromSeries(s);
	obs[1]->thermistors[0].name = "Tx";
	EXPECT_THROW(seriesFromObservations(obs), std::invalid_argument);
}

TEST(FogSeriesConversion, InvalidSeriesRejected)
{
	FogSeries s;
	s.resize(2);
	s.time_s = {1.0, 1.0};
	EXPECT_THROW(observationsFromSeries(s), std::invalid_argument);
}
