/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::sim
{
namespace
{
using EC = ErrorCoefficients;
constexpr auto kBias = IdentifiedIn::Bias;
constexpr double kInf = std::numeric_limits<double>::infinity();

// One descriptor per row of EffectTable.inc, in its order (= enumerator order).
constexpr std::array<EffectDescriptor, kEffectCount> kTable = {{
#define FOG_EFFECT(enumerator, ...) {Effect::enumerator, __VA_ARGS__},
#include <mrpt_fog/sim/EffectTable.inc>
#undef FOG_EFFECT
}};

constexpr bool inEnumeratorOrder()
{
	for (std::size_t i = 0; i < kTable.size(); ++i)
		if (indexOf(kTable[i].effect) != i) return false;
	return true;
}
static_assert(inEnumeratorOrder(), "effect registry: descriptor i must be enumerator i (one descriptor each)");
}  // namespace

const std::array<EffectDescriptor, kEffectCount>& effectDescriptors() { return kTable; }

const EffectDescriptor& descriptorOf(Effect effect) { return kTable.at(static_cast<std::size_t>(effect)); }

const EffectDescriptor* descriptorOfCalibrationParameter(const std::string& parameter)
{
	for (const auto& d : kTable)
		if (*d.calibration_parameter && parameter == d.calibration_parameter) return &d;
	return nullptr;
}

double* calibrationSlot(const EffectDescriptor& effect, FogDevice& device, std::size_t index)
{
	if (!*effect.calibration_parameter) return nullptr;
	if (effect.calibration.slot) return effect.calibration.slot(device, index);
	return index == 0 ? coefficientIn(effect, device.errors) : nullptr;
}

double* coefficientIn(const EffectDescriptor& effect, ErrorCoefficients& e)
{
	return effect.default_coefficient ? &e.coefficient(effect.effect) : nullptr;
}

std::array<double, kEffectCount> defaultCoefficients()
{
	std::array<double, kEffectCount> c;
	for (const auto& d : kTable) c[indexOf(d.effect)] = d.default_coefficient.value_or(std::numeric_limits<double>::quiet_NaN());
	return c;
}

std::size_t calibrationSlotCount(const EffectDescriptor& effect, const FogDevice& device)
{
	FogDevice& d = const_cast<FogDevice&>(device);  // only counted, not written
	std::size_t n = 0;
	while (calibrationSlot(effect, d, n)) ++n;
	return n;
}

Effect effectFromId(const std::string& id)
{
	for (const auto& d : kTable)
		if (id == d.id) return d.effect;
	std::string list;
	for (const auto& d : kTable) list += (list.empty() ? "" : ", ") + std::string(d.id);
	throw std::invalid_argument("unknown effect '" + id + "' (known: " + list + ")");
}

}  // namespace mrpt_fog::sim
