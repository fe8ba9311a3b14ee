/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The model-gap workflow's side of the effect registry: every effect the registry says a
 * residual identifies has a candidate (its column builder) on that channel, every candidate is
 * a registry effect, and every calibration parameter a descriptor names is a free parameter of
 * a simulator configuration. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/CandidateEffect.h>
#include <mrpt_fog/discrepancy/SimulatorConfig.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <algorithm>
#include <cmath>

using namespace mrpt_fog;

TEST(EffectRegistryCandidates, EveryIdentifiableEffectHasItsCandidate)
{
	for (const auto& d : sim::effectDescriptors())
	{
		SCOPED_TRACE(d.id);
		if (d.identified_in == sim::IdentifiedIn::NotIdentified)
		{
			EXPECT_THROW(discrepancy::candidateById(d.id), std::invalid_argument);
			continue;
		}
		const auto& c = discrepancy::candidateById(d.id);
		EXPECT_EQ(c.channel, d.identified_in == sim::IdentifiedIn::Bias ? discrepancy::ResidualChannel::Bias
																		  : discrepancy::ResidualChannel::Temperature);
		EXPECT_TRUE(static_cast<bool>(c.build));
		EXPECT_TRUE(static_cast<bool>(c.untestable_reason));
		if (*d.calibration_parameter)
		{
			const auto& free = discrepancy::freeParameterIds();
			EXPECT_NE(std::find(free.begin(), free.end(), d.calibration_parameter), free.end());
			EXPECT_EQ(discrepancy::coefficientParameterOf(d.id), d.calibration_parameter);
		}
	}
	for (const auto& c : discrepancy::candidateLibrary()) EXPECT_NO_THROW(sim::effectFromId(c.id)) << c.id;
}

namespace
{
/** A powered run of n samples at 10 s: a radial gradient that swings, a field switched on for
 * the middle third, a turn-on at 100 s (the first ten samples are before it). */
discrepancy::RunSignals poweredRun(std::size_t n)
{
	discrepancy::RunSignals s;
	for (std::size_t k = 0; k < n; ++k)
	{
		s.time_s.push_back(10.0 * static_cast<double>(k));
		s.gradient_C.push_back(0.3 * std::sin(0.05 * static_cast<double>(k)));
		s.field_uT.push_back(k >= n / 3 && k < 2 * n / 3 ? 50.0 : 0.0);
		s.power.push_back(1.0);
		s.usable.push_back(1);
		s.block.push_back(0);
	}
	s.power_on_s = {100.0};
	s.has_field = s.has_inner_outer = true;
	return s;
}
}  // namespace

TEST(EffectRegistryCandidates, CandidateFromTheSimulatorTermIsItsColumn)
{
	// An effect without a hand-written candidate gets its simulator term per coefficient as its
	// column. Checked against the hand-written magnetic candidate (that column) and closed forms.
	const auto s = poweredRun(90);
	discrepancy::CandidateContext ctx;
	ctx.sig = &s;
	for (const auto effect : {sim::Effect::Magnetic, sim::Effect::RadialGradient})
	{
		const auto& d = sim::descriptorOf(effect);
		SCOPED_TRACE(d.id);
		const auto derived = discrepancy::candidateFromTerm(d);
		EXPECT_EQ(derived.id, d.id);
		EXPECT_EQ(derived.channel, discrepancy::ResidualChannel::Bias);
		EXPECT_EQ(derived.coefficient_unit, d.coefficient_unit);
		const Eigen::MatrixXd a = derived.build(ctx, 0.0);
		ASSERT_EQ(a.rows(), 90);
		ASSERT_EQ(a.cols(), 1);
		const auto& truth = effect == sim::Effect::Magnetic ? s.field_uT : s.gradient_C;
		for (std::size_t k = 0; k < 90; ++k) EXPECT_EQ(a(static_cast<Eigen::Index>(k), 0), truth[k]) << k;
		EXPECT_EQ(derived.untestable_reason(s), "");
	}
	EXPECT_EQ(discrepancy::candidateFromTerm(sim::descriptorOf(sim::Effect::Magnetic)).build(ctx, 0.0),
			  discrepancy::candidateById("magnetic").build(ctx, 0.0));
	// warm-up: exp(-(t - 100 s) / 600 s) after the turn-on, 0 before it (no turn-on yet: +inf)
	const auto w = discrepancy::candidateFromTerm(sim::descriptorOf(sim::Effect::Warmup)).build(ctx, 0.0);
	for (std::size_t k = 0; k < 90; ++k)
		EXPECT_DOUBLE_EQ(w(static_cast<Eigen::Index>(k), 0), k < 10 ? 0.0 : std::exp(-(10.0 * k - 100.0) / 600.0)) << k;
	// no field in the run: the magnetic term's column is zero, so the run cannot test it
	auto no_field = s;
	no_field.field_uT.assign(90, 0.0);
	EXPECT_NE(discrepancy::candidateFromTerm(sim::descriptorOf(sim::Effect::Magnetic)).untestable_reason(no_field), "");
	// an effect whose term needs the simulator's state has none to derive from
	EXPECT_THROW(discrepancy::candidateFromTerm(sim::descriptorOf(sim::Effect::Hysteresis)), std::invalid_argument);
}
