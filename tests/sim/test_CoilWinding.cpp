/* mrpt_fog: tests of the winding map and the Shupe integral. */
#include <gtest/gtest.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/sim/CoilWinding.h>

#include <cmath>

using namespace mrpt_fog::sim;
using mrpt_fog::units::kRadPerSecToDegPerHour;

namespace
{
// Node rates varying linearly with the node layer, uniform around the coil.
Eigen::VectorXd radialRates(int layers, int sectors, double inner_K_s, double outer_K_s)
{
	Eigen::VectorXd r(layers * sectors);
	for (int i = 0; i < layers; i++)
		for (int j = 0; j < sectors; j++) r(i * sectors + j) = inner_K_s + (outer_K_s - inner_K_s) * (i + 0.5) / layers;
	return r;
}
}  // namespace

TEST(CoilWinding, HelicalLinearRateMatchesClosedForm)
{
	// PHYSICS.md: Omega = n (dn/dT + n alpha) L dTdot / (6 D), ~136 deg/h for L = 1500 m,
	// D = 0.1 m, dTdot = 1 C/min end to end. With one fibre layer per node layer, node i holds
	// z in [i L/N, (i+1) L/N] at the rate of its midpoint: the piecewise-constant integral is
	// the closed form times (1 - 1/N^2) exactly.
	WindingParams p;
	p.pattern = WindingPattern::Helical;
	const int N = 200;
	p.fiber_layers = N;
	CoilWinding w(p, N, 4);
	const double dTdot = 1.0 / 60.0;
	const double n = p.refractive_index;
	const double closed =
		n * (p.dn_dT_per_K + n * p.expansion_per_K) * p.fiber_length_m * dTdot / (6 * p.mean_diameter_m) * kRadPerSecToDegPerHour;
	EXPECT_NEAR(closed, 136.0, 1.0);
	const double got = w.shupeRate_rad_s(radialRates(N, 4, 0.0, dTdot)) * kRadPerSecToDegPerHour;
	EXPECT_NEAR(got, closed * (1.0 - 1.0 / (N * N)), 1e-9 * closed);
	EXPECT_NEAR(got, closed, 1e-4 * closed);
	// A constant added to every rate changes nothing (integral of 2z - L is 0).
	const double shifted = w.shupeRate_rad_s(radialRates(N, 4, 0.3, 0.3 + dTdot)) * kRadPerSecToDegPerHour;
	EXPECT_NEAR(shifted, got, 1e-9 * closed);
}

TEST(CoilWinding, FibreLengthsAddUp)
{
	for (auto pat : {WindingPattern::Helical, WindingPattern::Dipolar, WindingPattern::Quadrupolar, WindingPattern::Octupolar})
	{
		WindingParams p;
		p.pattern = pat;
		p.midpoint_offset_m = 2.5;
		CoilWinding w(p, 8, 8);
		EXPECT_NEAR(w.nodeFiberLength_m().sum(), p.fiber_length_m, 1e-6) << toString(pat);
		EXPECT_NEAR(w.nodeWeights_m2().sum(), 0.0, 1e-6) << toString(pat);  // integral of 2z - L
		for (int k = 0; k < 64; k++) EXPECT_GT(w.nodeFiberLength_m()(k), 0.0);
	}
}

TEST(CoilWinding, UniformRateGivesZeroForPerfectQuadrupole)
{
	WindingParams p;  // quadrupolar, no imperfection
	CoilWinding w(p, 8, 8);
	const Eigen::VectorXd r = Eigen::VectorXd::Constant(64, 1.0 / 60.0);
	EXPECT_NEAR(w.shupeRate_rad_s(r) * kRadPerSecToDegPerHour, 0.0, 1e-9);
}

TEST(CoilWinding, SymmetricWindingsSuppressRadialGradient)
{
	// Same radial rate profile (1 C/min inner to outer): helical >> dipolar > quadrupolar > octupolar.
	auto shupe = [](WindingPattern pat, double offset) {
		WindingParams p;
		p.pattern = pat;
		p.midpoint_offset_m = offset;
		CoilWinding w(p, 8, 8);
		return std::abs(w.shupeRate_rad_s(radialRates(8, 8, 0.0, 1.0 / 60.0)) * kRadPerSecToDegPerHour);
	};
	const double hel = shupe(WindingPattern::Helical, 0), dip = shupe(WindingPattern::Dipolar, 0);
	const double quad = shupe(WindingPattern::Quadrupolar, 0), oct = shupe(WindingPattern::Octupolar, 0);
	EXPECT_GT(hel, 50.0);
	EXPECT_LT(dip, hel / 10);
	EXPECT_LT(quad, dip);
	EXPECT_LE(oct, quad + 1e-12);
	// The midpoint offset (length asymmetry) raises the quadrupole's residual.
	EXPECT_GT(shupe(WindingPattern::Quadrupolar, 2.0), quad);
}

TEST(CoilWinding, MidpointOffsetResidualIsLinearInOffset)
{
	// A length asymmetry d moves every fibre point's weight 2z - L by 2d except for O(d) of
	// fibre near the end: the residual change is linear in d up to terms of relative size d/L.
	auto shupe = [](double offset) {
		WindingParams p;
		p.midpoint_offset_m = offset;
		CoilWinding w(p, 8, 8);
		return w.shupeRate_rad_s(radialRates(8, 8, 0.0, 1.0 / 60.0)) * kRadPerSecToDegPerHour;
	};
	const double s0 = shupe(0.0), s1 = shupe(0.5), s2 = shupe(1.0), s4 = shupe(2.0);
	EXPECT_NE(s1, s0);
	EXPECT_NEAR(s2 - s0, 2 * (s1 - s0), 0.01 * std::abs(s2 - s0));
	EXPECT_NEAR(s4 - s0, 4 * (s1 - s0), 0.01 * std::abs(s4 - s0));
}

TEST(CoilWinding, RejectsBadParameters)
{
	WindingParams p;
	p.midpoint_offset_m = 800;
	EXPECT_THROW(CoilWinding(p, 8, 8), std::invalid_argument);
	EXPECT_THROW(windingPatternFromString("spiral"), std::invalid_argument);
}

// Layer-length mismatch e (residual Shupe from winding imperfections other than the
// midpoint offset). Hand-derived weights for a quadrupolar (ABBA) coil of 4 fibre layers, one per
// node layer, one sector, midpoint at L/2, layer length l = L/4: with w = integral of (2z - L)
// dz and s the distance from the midpoint along a half (A: z = L/2 - s, B: z = L/2 + s),
// a stretch s0..s1 gives -(s1^2 - s0^2) in half A and +(s1^2 - s0^2) in half B:
//   layer 0 (A, 0 .. l(1+e)):            -l^2 (1+e)^2
//   layer 1 (B, 0 .. l(1-e)):            +l^2 (1-e)^2
//   layer 2 (B, l(1-e) .. 2l(1-e)):      +3 l^2 (1-e)^2
//   layer 3 (last: A's remaining l(1-e), s = l(1+e) .. 2l, then B's remaining 2le,
//            s = 2l(1-e) .. 2l):         -(4 l^2 - l^2 (1+e)^2) + (4 l^2 - 4 l^2 (1-e)^2)
TEST(CoilWinding, LayerLengthMismatchMatchesHandDerivedWeights)
{
	for (double e : {0.0, 0.01, 0.03})  // e >= 0: half B never runs out before the last layer
	{
		WindingParams p;
		p.fiber_layers = 4;
		p.layer_length_mismatch = e;
		CoilWinding w(p, 4, 1);
		const double l = p.fiber_length_m / 4, l2 = l * l;
		const double a = (1 + e) * (1 + e), b = (1 - e) * (1 - e);
		const double expect[4] = {-l2 * a, l2 * b, 3 * l2 * b, -(4 * l2 - l2 * a) + (4 * l2 - 4 * l2 * b)};
		for (int k = 0; k < 4; k++) EXPECT_NEAR(w.nodeWeights_m2()(k), expect[k], 1e-9 * 4 * l2) << "e " << e << " layer " << k;
		EXPECT_NEAR(w.nodeFiberLength_m()(0), l * (1 + e), 1e-9 * l);
	}
	WindingParams bad;
	bad.layer_length_mismatch = 0.5;
	EXPECT_THROW(bad.validate(), std::invalid_argument);
}
