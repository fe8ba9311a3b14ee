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
// The additive bias terms that depend only on this step's inputs: per unit of their coefficient
// [deg/h per coefficient unit] when linear in it, else added in place [deg/h].
double radialGradientPerCoefficient(const EffectTermInputs& in, const ErrorCoefficients&) { return in.gradient_C; }
double warmupPerCoefficient(const EffectTermInputs& in, const ErrorCoefficients& e)
{
	return std::isfinite(in.time_since_power_on_s) ? std::exp(-in.time_since_power_on_s / e.warmup_tau_s) : 0.0;
}
double magneticPerCoefficient(const EffectTermInputs& in, const ErrorCoefficients&) { return in.field_uT; }
void tempPolyTerm(const EffectTermInputs& in, const ErrorCoefficients& e, double& sum)
{
	const double x = in.electronics_C - e.temp_poly_ref_C;
	double xp = 1;
	for (double c : e.temp_poly_dph) sum += c * (xp *= x);
}

// Calibration slots that are not the scalar coefficient.
double* windingAsymmetrySlot(FogDevice& d, std::size_t i) { return i == 0 ? &d.winding.midpoint_offset_m : nullptr; }
double* tempPolySlot(FogDevice& d, std::size_t i)
{
	return i < d.errors.temp_poly_dph.size() ? &d.errors.temp_poly_dph[i] : nullptr;
}
double* electronicsPowerSlot(FogDevice& d, std::size_t i)
{
	return i == 0 ? &d.thermal.electronics_power_W : nullptr;
}

using EC = ErrorCoefficients;
constexpr auto kBias = IdentifiedIn::Bias;
constexpr double kInf = std::numeric_limits<double>::infinity();

// Each row: effect, id, summary, coefficient key and unit, default coefficient, calibration
// parameter, residual that identifies it, the data that do, proof-trial scaling, simulator term
// (per coefficient, or in place), shape fields, calibration slots.
constexpr std::array<EffectDescriptor, kEffectCount> kTable = {{
	{Effect::ShupeRate, "shupe_rate", "Shupe term from the node temperature rates (CoilWinding)",
	 "coil.dn_dT_per_K, coil.expansion_per_K, coil.midpoint_offset_m", "deg/h", std::nullopt, "winding_asymmetry_m",
	 kBias, "temperature steps and a sine sweep (rates of several sizes)", "coil.dn_dT_per_K and coil.expansion_per_K",
	 nullptr, nullptr,
	 {}, {0.05, -kInf, false, windingAsymmetrySlot}},
	// Default 0.12 (no source): one of the two knobs FITTED to the seed's uncompensated figures
	// and its M1 figure by scripts/fit_seed_knobs.py (docs/sim.md).
	{Effect::RadialGradient, "radial_gradient", "elasto-optic bias proportional to Tin - Tout (coil layer means)",
	 "errors.radial_gradient_dph_per_C", "deg/h per degC", 0.12, "radial_gradient_dph_per_C", kBias,
	 "a sine sweep near the coil's radial time constant, soaks after fast steps",
	 "errors.radial_gradient_dph_per_C", radialGradientPerCoefficient, nullptr,
	 {}, {1e-3, -kInf, false, nullptr}},
	{Effect::GradientRate, "gradient_rate", "bias proportional to d(Tin - Tout)/dt",
	 "errors.gradient_rate_dph_per_C_per_min", "deg/h per degC/min", 0.1 /* estimate */,
	 "gradient_rate_dph_per_C_per_min", kBias, "temperature steps and a sine sweep near the radial time constant",
	 "errors.gradient_rate_dph_per_C_per_min", nullptr, nullptr,
	 {}, {1e-3, -kInf, false, nullptr}},
	{Effect::ThermistorLag, "thermistor_lag", "first-order lag of the thermistors (off: they read the node instantly)",
	 "thermistors[*].tau_s", "s", std::nullopt, "", kBias,
	 "steps and ramps in several temperature bands (scales with the static bias curve's slope)",
	 "thermistors[*].tau_s", nullptr, nullptr,
	 {}, {}},
	{Effect::Hysteresis, "hysteresis", "heating vs cooling offset (rate-independent play over a temperature span)",
	 "errors.hysteresis_dph", "deg/h", 0.02 /* estimate */, "hysteresis_dph", kBias,
	 "heating and cooling ramps through the same temperatures", "errors.hysteresis_dph", nullptr, nullptr,
	 {{{"hysteresis_span_C", &EC::hysteresis_span_C}}}, {1e-3, 0.0, false, nullptr}},
	{Effect::Warmup, "warmup", "decaying exponential after each power-on", "errors.warmup_dph", "deg/h",
	 0.1 /* estimate */, "warmup_dph", kBias, "power cycles at constant chamber temperature", "errors.warmup_dph",
	 warmupPerCoefficient, nullptr,
	 {{{"warmup_tau_s", &EC::warmup_tau_s}}}, {1e-3, -kInf, false, nullptr}},
	// Default 20 ppm/degC: PHYSICS.md gives tens to hundreds.
	{Effect::ScaleFactorTemp, "scale_factor_temp",
	 "scale factor vs coil temperature, acting on applied rate and Earth rate", "errors.sf_ppm_per_C", "ppm/degC",
	 20.0, "sf_ppm_per_C", kBias, "rate-table segments at several temperatures", "errors.sf_ppm_per_C",
	 nullptr, nullptr,
	 {{{"sf_ref_C", &EC::sf_ref_C}}}, {0.1, -kInf, false, nullptr}},
	{Effect::Magnetic, "magnetic", "axial magnetic field sensitivity", "errors.magnetic_dph_per_uT", "deg/h per uT",
	 2e-4 /* shielded coil, estimate */, "magnetic_dph_per_uT", kBias,
	 "field segments (axial field switched on and off)", "errors.magnetic_dph_per_uT", magneticPerCoefficient,
	 nullptr,
	 {}, {1e-5, -kInf, false, nullptr}},
	{Effect::TempPolyOrder, "temp_poly_order", "static bias polynomial in the electronics (source) temperature",
	 "errors.temp_poly_dph", "deg/h per degC^k", std::nullopt, "temp_poly_dph", kBias,
	 "soaks at several temperature levels across the full range", "errors.temp_poly_dph (x^4 and x^5 terms)",
	 nullptr, tempPolyTerm,
	 {{{"temp_poly_ref_C", &EC::temp_poly_ref_C}}}, {1e-5, -kInf, true, tempPolySlot}},
	{Effect::HeatSource, "heat_source", "electronics self-heating (off: zero power into the thermal network)",
	 "thermal.electronics_power_W", "W", std::nullopt, "electronics_power_W", IdentifiedIn::Temperature,
	 "power cycles", "", nullptr, nullptr,
	 {}, {0.05, 1e-6, false, electronicsPowerSlot}},
	{Effect::EarthRate, "earth_rate", "vertical Earth rate at the device latitude", "latitude_deg", "deg",
	 std::nullopt, "", IdentifiedIn::NotIdentified, "", "", nullptr, nullptr,
	 {}, {}},
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
