/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* Completeness of the effect registry: every effect has every part of its descriptor, its
 * coefficient key names the device field the descriptor points at, and its additive simulator
 * term is linear in that coefficient. */
#include <gtest/gtest.h>
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/ErrorEffects.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <cmath>
#include <map>
#include <set>
#include <string>

using namespace mrpt_fog::sim;

TEST(EffectRegistry, OneDescriptorPerEnumeratorInTheStableIdOrder)
{
	// allEffectIds() is the documented contract (test_ErrorEffects.cpp checks its order) and is
	// read from this table: enumerator i is descriptor i.
	ASSERT_EQ(allEffectIds().size(), kEffectCount);
	for (std::size_t i = 0; i < kEffectCount; ++i)
	{
		const auto& d = effectDescriptors()[i];
		EXPECT_EQ(allEffectIds()[i], d.id);
		EXPECT_EQ(static_cast<std::size_t>(d.effect), i) << d.id;
		EXPECT_EQ(effectFromId(d.id), d.effect);
		EXPECT_STREQ(toString(d.effect), d.id);
	}
	EXPECT_THROW(effectFromId("no_such_effect"), std::invalid_argument);
}

TEST(EffectRegistry, EveryDescriptorIsComplete)
{
	std::map<std::string, std::string> device;  // "device.<section>.<field>" -> value
	for (const auto& [k, v] : FogDevice::defaultDevice().describe()) device[k] = v;
	std::set<std::string> ids;
	for (const auto& d : effectDescriptors())
	{
		SCOPED_TRACE(d.id);
		EXPECT_TRUE(ids.insert(d.id).second) << "duplicate id";
		EXPECT_GT(std::string(d.summary).size(), 10u);
		EXPECT_FALSE(std::string(d.coefficient_key).empty());
		EXPECT_FALSE(std::string(d.coefficient_unit).empty());
		if (d.identified_in != IdentifiedIn::NotIdentified)
			EXPECT_FALSE(std::string(d.identified_by).empty()) << "what data identifies it?";
		if (d.identified_in == IdentifiedIn::Bias)
			EXPECT_FALSE(std::string(d.trial_scaling).empty()) << "how do the proof trials scale it?";
		if (*d.calibration_parameter)
		{
			// a simulator calibration can move it: a slot in the device, a step, this parameter
			FogDevice dev = FogDevice::defaultDevice();
			EXPECT_GE(calibrationSlotCount(d, dev), 1u) << "no slot for " << d.calibration_parameter;
			EXPECT_GT(d.calibration.fd_step, 0.0);
			EXPECT_EQ(descriptorOfCalibrationParameter(d.calibration_parameter), &d);
		}
		else
		{
			FogDevice dev = FogDevice::defaultDevice();
			EXPECT_EQ(calibrationSlot(d, dev, 0), nullptr);
		}
		for (const auto& shape : d.shape_fields)
			if (shape.key)
			{
				// a shape field is a device field holding the member's value
				const auto it = device.find(std::string("device.errors.") + shape.key);
				ASSERT_NE(it, device.end()) << shape.key << " is not a device field";
				const double member = FogDevice::defaultDevice().errors.*shape.member;
				EXPECT_NEAR(std::stod(it->second), member, 1e-9 * std::max(1.0, std::abs(member)));
			}
		FogDevice dev = FogDevice::defaultDevice();
		if (d.default_coefficient)
		{
			// the key is the device field holding the effect's coefficient, whose default is the
			// descriptor's
			const auto it = device.find(std::string("device.") + d.coefficient_key);
			ASSERT_NE(it, device.end()) << d.coefficient_key << " is not a device field";
			const double value = *d.default_coefficient;
			EXPECT_NEAR(std::stod(it->second), value, 1e-9 * std::max(1.0, std::abs(value)));
			EXPECT_EQ(dev.errors.coefficient(d.effect), value);
			EXPECT_EQ(coefficientIn(d, dev.errors), &dev.errors.coefficient(d.effect));
		}
		else
		{
			EXPECT_EQ(coefficientIn(d, dev.errors), nullptr);
			EXPECT_EQ(d.bias_per_coefficient, nullptr) << "a term per coefficient needs a coefficient";
		}
		EXPECT_FALSE(d.bias_per_coefficient && d.add_bias_term_dph) << "one simulator term, not two";
	}
}

TEST(EffectRegistry, AdditiveTermsAreLinearInTheirCoefficientAndZeroWithoutIt)
{
	EffectTermInputs in;
	in.gradient_C = 1.7;
	in.time_since_power_on_s = 300.0;
	in.field_uT = 45.0;
	in.electronics_C = 41.0;
	// the term as the simulator adds it (FogSimulator::advance)
	auto term = [&](const EffectDescriptor& d, const ErrorCoefficients& e)
	{
		double sum = 0;
		if (d.bias_per_coefficient) sum += e.coefficient(d.effect) * d.bias_per_coefficient(in, e);
		if (d.add_bias_term_dph) d.add_bias_term_dph(in, e, sum);
		return sum;
	};
	int terms = 0;
	for (const auto& d : effectDescriptors())
	{
		if (!d.bias_per_coefficient && !d.add_bias_term_dph) continue;
		SCOPED_TRACE(d.id);
		++terms;
		ErrorCoefficients e;
		const double one = term(d, e);
		if (double* c = coefficientIn(d, e))
		{
			const double per_coefficient = d.bias_per_coefficient(in, e);
			*c *= 2;
			EXPECT_NEAR(term(d, e), 2 * one, 1e-12 * std::abs(one));
			EXPECT_EQ(d.bias_per_coefficient(in, e), per_coefficient) << "the term per coefficient must not read it";
			*c = 0;
		}
		else
			e.temp_poly_dph.assign(e.temp_poly_dph.size(), 0.0);
		EXPECT_NE(one, 0.0);
		EXPECT_EQ(term(d, e), 0.0);
	}
	EXPECT_EQ(terms, 4);  // radial_gradient, warmup, magnetic, temp_poly_order
	// closed forms of three of them
	const ErrorCoefficients e;
	EXPECT_DOUBLE_EQ(term(descriptorOf(Effect::Warmup), e), e.warmup_dph() * std::exp(-300.0 / e.warmup_tau_s));
	EXPECT_DOUBLE_EQ(term(descriptorOf(Effect::Magnetic), e), 2e-4 * 45.0);
	EXPECT_NEAR(term(descriptorOf(Effect::TempPolyOrder), e), 1e-3 * 16.0 + 1e-5 * 256.0, 1e-15);  // default {1e-3, 1e-5}, x = 41 - 25
}
