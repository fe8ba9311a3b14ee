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
