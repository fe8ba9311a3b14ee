/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/ThermalFeatureSet.h>

#include <cmath>

using namespace mrpt_fog;

TEST(ThermalFeatureSet, TermNamesRoundTrip)
{
	for (const std::string n : {"1", "T(Ti1)^5", "dT/dt(To2)^3", "dT(Ti1-To1)^2", "d/dt dT(Ti1-To1)^1"})
		EXPECT_EQ(ThermalTerm::parse(n).name(), n);
	EXPECT_EQ(ThermalTerm::parse("dT(Ti1-To1)").name(), "dT(Ti1-To1)^1");
	EXPECT_EQ(ThermalTerm::parse("T(a)").signal.kind, SignalKind::Temp);
	EXPECT_EQ(ThermalTerm::parse("d/dt dT(a-b)^2").signal.kind, SignalKind::DiffRate);
}

TEST(ThermalFeatureSet, BadTermsThrow)
{
	for (const std::string n : {"T(Ti1)^6", "dT/dt(Ti1)^4", "d/dt dT(a-b)^4", "T(Ti 1)", "T(a.b)", "dT(a-a)", "dT(ab)",
								"T(a)^0", "T(a)^x", "T(a", "X(a)", "T(a)2", ""})
		EXPECT_THROW(ThermalTerm::parse(n), std::invalid_argument) << n;
	EXPECT_THROW(ThermalFeatureSet::fromNames({"T(a)^1", "T(a)"}), std::invalid_argument);
}

TEST(ThermalFeatureSet, SignalsThermistorsAndFallbackSubsets)
{
	const auto fs = ThermalFeatureSet::fromNames({"T(Ti1)^1", "T(Ti1)^2", "dT/dt(Ti1)^1", "dT(Ti1-To1)^1", "T(To1)^1"});
	EXPECT_EQ(fs.termCount(), 6u);  // constant added first
	EXPECT_EQ(fs.terms()[0].name(), "1");
	EXPECT_EQ(fs.signals().size(), 4u);
	EXPECT_EQ(fs.thermistors(), (std::vector<std::string>{"Ti1", "To1"}));
	const auto w = fs.without("To1");
	EXPECT_EQ(w.termNames(), (std::vector<std::string>{"1", "T(Ti1)^1", "T(Ti1)^2", "dT/dt(Ti1)^1"}));
	EXPECT_FALSE(w.references("To1"));
}

// z = (v - centre) / scale, term = z^k; clamping to [min, max] counted.
TEST(ThermalFeatureSet, NormalisedFeaturesAndClamping)
{
	auto fs = ThermalFeatureSet::fromNames({"T(a)^1", "T(a)^3", "dT/dt(a)^2", "dT(a-b)^1"});
	// signals: T(a), dT/dt(a), dT(a-b)
	fs.normalisation()[0] = {10.0, 50.0, -40.0, 60.0};
	fs.normalisation()[1] = {0.0, 0.02, -0.02, 0.02};
	fs.normalisation()[2] = {0.0, 2.0, -2.0, 2.0};
	const double temp[2] = {35.0, 34.0}, rate[2] = {0.01, 0.0};
	std::vector<double> v(3), f(fs.termCount());
	fs.signalValues(temp, rate, v.data());
	EXPECT_DOUBLE_EQ(v[2], 1.0);
	EXPECT_EQ(fs.features(v.data(), f.data(), true), 0);
	EXPECT_DOUBLE_EQ(f[0], 1.0);
	EXPECT_DOUBLE_EQ(f[1], 0.5);
	EXPECT_DOUBLE_EQ(f[2], 0.125);
	EXPECT_DOUBLE_EQ(f[3], 0.25);
	EXPECT_DOUBLE_EQ(f[4], 0.5);
	const double hot[2] = {80.0, 70.0};
	fs.signalValues(hot, rate, v.data());
	EXPECT_EQ(fs.features(v.data(), f.data(), true), 2);  // T(a) and dT(a-b) clamped
	EXPECT_DOUBLE_EQ(f[1], 1.0);
	EXPECT_DOUBLE_EQ(f[4], 1.0);
	EXPECT_EQ(fs.features(v.data(), f.data(), false), 0);  // no clamp: extrapolates
	EXPECT_DOUBLE_EQ(f[1], 1.4);
}

TEST(ThermalFeatureSet, LagTermsParseNameAndShareTheirLags)
{
	for (const std::string n : {"dTlag/dt(Ti1,400)^1", "dTlag/dt(To2,12.5)^3"}) EXPECT_EQ(ThermalTerm::parse(n).name(), n);
	const ThermalTerm t = ThermalTerm::parse(" dTlag/dt(Ti1,1600) ");
	EXPECT_EQ(t.signal.kind, SignalKind::LagRate);
	EXPECT_EQ(t.signal.tau_s, 1600.0);
	EXPECT_EQ(t.power, 1);
	EXPECT_STREQ(t.signal.unit(), "degC/s");
	EXPECT_FALSE(t.signal.isRate());  // not a windowed rate: exists from the first reading
	for (const std::string n : {"dTlag/dt(Ti1)", "dTlag/dt(Ti1,0)", "dTlag/dt(Ti1,-5)", "dTlag/dt(Ti1,x)",
								"dTlag/dt(Ti1,)", "dTlag/dt(Ti1,400)^4", "dTlag/dt(Ti 1,400)", "dTlag/dt(Ti1,inf)",
								"dTlag/dt(Ti1,nan)", "dTlag/dt(Ti1,1e300)"})
		EXPECT_THROW(ThermalTerm::parse(n), std::invalid_argument) << n;
	// the same signal at two time constants is two signals; powers of one share its lag
	const auto fs = ThermalFeatureSet::fromNames(
		{"dTlag/dt(To1,100)^1", "T(Ti1)^1", "dTlag/dt(To1,100)^2", "dTlag/dt(Ti1,400)^1", "dTlag/dt(To1,400)^1"});
	EXPECT_EQ(fs.thermistors(), (std::vector<std::string>{"To1", "Ti1"}));
	ASSERT_EQ(fs.lags().size(), 3u);
	EXPECT_EQ(fs.lags()[0], (LagChannel{0, 100.0}));
	EXPECT_EQ(fs.lags()[1], (LagChannel{1, 400.0}));
	EXPECT_EQ(fs.lags()[2], (LagChannel{0, 400.0}));
	const double temp[2] = {5.0, 7.0}, rate[2] = {0.1, 0.2}, lag[3] = {0.01, 0.02, 0.03};
	std::vector<double> v(fs.signals().size());
	fs.signalValues(temp, rate, lag, v.data());
	EXPECT_EQ(v, (std::vector<double>{0.01, 7.0, 0.02, 0.03}));
	EXPECT_THROW(fs.signalValues(temp, rate, v.data()), std::invalid_argument);  // lag values not given
	EXPECT_FALSE(fs.without("To1").references("To1"));
	EXPECT_EQ(fs.without("To1").lags().size(), 1u);
}
