/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The common unit slips on a gyro log whose truth is known: white rate noise of a stated angle
 * random walk (std::mt19937, not the simulator), a rate table turning at known rates, thermistors
 * near room temperature. Each slip is made by hand on the numbers, as a user's file would hold
 * them, and must be named; the correct units must give no finding. */
#include <gtest/gtest.h>
#include <mrpt_fog/io/UnitPlausibility.h>

#include <cmath>
#include <random>

using namespace mrpt_fog;

namespace
{
constexpr double kPi = 3.14159265358979323846;

struct Truth
{
	double arw_dpsh = 0.001;  // deg/sqrt(h), a navigation-grade FOG
	double rate_hz = 10;
	double duration_s = 2000;
	bool table = false;  // +-36 000 deg/h (10 deg/s) every other 100 s
	bool triad = false;
};

/** Samples in native units (s, deg/h, degC). */
std::vector<FogSample> makeLog(const Truth& t, unsigned seed = 7)
{
	std::mt19937 rng(seed);
	std::normal_distribution<double> g(0, 1);
	const double dt = 1 / t.rate_hz;
	const double sigma_dph = 60 * t.arw_dpsh / std::sqrt(dt);
	std::vector<FogSample> out;
	for (double time = 0; time < t.duration_s; time += dt)
	{
		FogSample x;
		x.time_s = time;
		x.table_rate_dph = t.table ? (static_cast<int>(time / 100) % 2 ? 36000.0 : -36000.0) : NAN;
		const double table = t.table ? x.table_rate_dph : 0;
		x.rate_dph = {NAN, NAN, 0.7 + 11.5 + table + sigma_dph * g(rng)};  // bias + Earth's vertical component
		if (t.triad)
		{
			x.rate_dph[0] = 0.3 + 9.7 + sigma_dph * g(rng);
			x.rate_dph[1] = -0.2 + 0.0 + sigma_dph * g(rng);
		}
		x.temp_C = {22 + 0.001 * time, 23 + 0.001 * time};
		out.push_back(x);
	}
	return out;
}

std::vector<UnitFinding> judge(const std::vector<FogSample>& log, const DeclaredUnits& d = DeclaredUnits::native())
{
	UnitPlausibility p(d);
	for (const auto& x : log) p.add(x);
	return p.findings();
}

std::string all(const std::vector<UnitFinding>& f)
{
	std::string s;
	for (const auto& x : f) s += x.message() + "\n";
	return s;
}
}  // namespace

TEST(UnitPlausibility, CorrectUnitsGiveNoFinding)
{
	for (double arw : {0.0003, 0.001, 0.05, 0.5})
	{
		Truth t;
		t.arw_dpsh = arw;
		EXPECT_TRUE(judge(makeLog(t)).empty()) << arw << "\n" << all(judge(makeLog(t)));
	}
	Truth table;
	table.table = true;
	EXPECT_TRUE(judge(makeLog(table)).empty()) << all(judge(makeLog(table)));
	Truth triad;
	triad.triad = true;
	EXPECT_TRUE(judge(makeLog(triad)).empty()) << all(judge(makeLog(triad)));
}

// deg/s written under a deg/h column: every rate 3600 times too small.
TEST(UnitPlausibility, DegPerSecondAsDegPerHourIsNamed)
{
	auto log = makeLog({});
	for (auto& x : log) x.rate_dph[2] /= 3600;
	const auto f = judge(log);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_EQ(f[0].quantity, UnitQuantity::Rate);
	EXPECT_EQ(f[0].column, "rate_z_dph");
	EXPECT_EQ(f[0].declared_unit, "deg/h");
	EXPECT_EQ(f[0].likely_unit, "deg/s");
	EXPECT_NE(f[0].message().find("likely deg/s"), std::string::npos) << f[0].message();
}

// rad/s declared as deg/s (a format file's slip): the values read are 57.3 times too small.
TEST(UnitPlausibility, RadPerSecondAsDegPerSecondIsNamed)
{
	DeclaredUnits d;
	d.rate[2] = RateUnit::deg_per_s;
	d.rate_column[2] = "Gyro Z [deg/s]";
	// without a table: from the noise (a navigation-grade FOG)
	auto log = makeLog({});
	for (auto& x : log) x.rate_dph[2] *= kPi / 180;  // the file's rad/s number read as deg/s
	auto f = judge(log, d);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_EQ(f[0].likely_unit, "rad/s") << f[0].message();
	// with a rate table, for any gyro grade: from the slope on the table's rate
	Truth t;
	t.table = true;
	t.arw_dpsh = 0.1;
	log = makeLog(t);
	for (auto& x : log) x.rate_dph[2] *= kPi / 180;
	f = judge(log, d);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_EQ(f[0].likely_unit, "rad/s") << f[0].message();
	EXPECT_NE(f[0].evidence.find("table"), std::string::npos);
}

// A rate table turning at 36 000 deg/h that the gyro reads as 10: deg/s under deg/h, found from
// the table even for a gyro whose noise alone would not tell (a MEMS-grade 0.3 deg/sqrt(h)).
TEST(UnitPlausibility, TableReadAsTenIsNamed)
{
	Truth t;
	t.table = true;
	t.arw_dpsh = 0.3;
	auto log = makeLog(t);
	for (auto& x : log) x.rate_dph[2] /= 3600;
	const auto f = judge(log);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_EQ(f[0].likely_unit, "deg/s") << f[0].message();
}

// Earth rate: a triad whose mean rate vector is 3600 times below Earth's 15 deg/h.
TEST(UnitPlausibility, TriadBelowEarthRateIsNamed)
{
	Truth t;
	t.triad = true;
	t.arw_dpsh = 0.3;  // too noisy for the noise check to tell
	auto log = makeLog(t);
	for (auto& x : log)
		for (auto& r : x.rate_dph) r /= 3600;
	const auto f = judge(log);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_NE(f[0].evidence.find("Earth"), std::string::npos) << f[0].message();
	EXPECT_EQ(f[0].likely_unit, "deg/s") << f[0].message();
}

// Milliseconds under a seconds column: a 10 Hz log looks sampled every 100 s.
TEST(UnitPlausibility, MillisecondsAsSecondsIsNamed)
{
	auto log = makeLog({});
	for (auto& x : log) x.time_s *= 1000;
	const auto f = judge(log);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_EQ(f[0].quantity, UnitQuantity::Time);
	EXPECT_EQ(f[0].likely_unit, "ms") << f[0].message();
}

// Kelvin under a Celsius column, and the reverse.
TEST(UnitPlausibility, KelvinAsCelsiusIsNamed)
{
	auto log = makeLog({});
	for (auto& x : log)
		for (auto& t : x.temp_C) t += 273.15;
	auto f = judge(log);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_EQ(f[0].quantity, UnitQuantity::Temperature);
	EXPECT_EQ(f[0].likely_unit, "K");
	DeclaredUnits d;
	d.temperature = TemperatureUnit::K;
	log = makeLog({});
	for (auto& x : log)
		for (auto& t : x.temp_C) t -= 273.15;  // Celsius numbers read as kelvin
	f = judge(log, d);
	ASSERT_EQ(f.size(), 1u) << all(f);
	EXPECT_EQ(f[0].likely_unit, "C");
}

// A quantised output that rarely changes (median difference 0): the noise check cannot tell and
// says nothing rather than guessing.
TEST(UnitPlausibility, QuantisedOutputCannotTell)
{
	auto log = makeLog({});
	for (auto& x : log) x.rate_dph[2] = std::round(x.rate_dph[2] / 5) * 5;
	EXPECT_TRUE(judge(log).empty()) << all(judge(log));
}
