/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/NumberText.h>

#include <cmath>
#include <cstring>
#include <random>

using namespace mrpt_fog::io;

TEST(NumberText, ShortestFormReadsBackExactly)
{
	EXPECT_EQ(formatNumber(0.1), "0.1");
	EXPECT_EQ(formatNumber(25.0), "25");
	EXPECT_EQ(formatNumber(-1e-7), "-1e-07");
	EXPECT_EQ(formatNumber(1700000000.0), "1700000000");
	EXPECT_EQ(formatNumber(1700000000.25), "1700000000.25");
	EXPECT_EQ(formatNumber(0.00012), "0.00012");
	std::mt19937_64 rng(7);
	for (int i = 0; i < 100000; i++)
	{
		uint64_t bits = rng();
		double v;
		std::memcpy(&v, &bits, sizeof v);
		if (!std::isfinite(v)) continue;
		const auto back = parseNumber(formatNumber(v));
		ASSERT_TRUE(back.has_value()) << formatNumber(v);
		ASSERT_EQ(*back, v) << formatNumber(v);
	}
}

TEST(NumberText, ParseIsStrict)
{
	EXPECT_EQ(parseNumber(" +2.5 ").value(), 2.5);
	EXPECT_EQ(parseNumber("-3e2").value(), -300.0);
	EXPECT_TRUE(std::isnan(parseNumber("nan").value()));
	for (const char* bad : {"", " ", "1.2.3", "0.x3", "12abc", "+-1", "1,5", "--1", "1e999"})
		EXPECT_FALSE(parseNumber(bad).has_value()) << bad;
}
