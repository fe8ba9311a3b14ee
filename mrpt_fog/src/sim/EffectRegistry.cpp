/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/sim/EffectRegistry.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::sim
{
namespace
{
// The additive bias terms [deg/h] that depend only on this step's inputs.
void radialGradientTerm(const EffectTermInputs& in, const ErrorCoefficients& e, double& sum)
{
	sum += e.radial_gradient_dph_per_C * in.gradient_C;
}
void warmupTerm(const EffectTermInputs& in, const ErrorCoefficients& e, double& sum)
{
	if (std::isfinite(in.time_since_power_on_s)) sum += e.warmup_dph * std::exp(-in.time_since_power_on_s / e.warmup_tau_s);
}
void magneticTerm(const EffectTermInputs& in, const ErrorCoefficients& e, double& sum)
{
	sum += e.magnetic_dph_per_uT * in.field_uT;
}
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

const std::array<EffectDescriptor, kEffectCount> kTable = {{
	{Effect::ShupeRate, "shupe_rate", "Shupe term from the node temperature rates (CoilWinding)",
	 "coil.dn_dT_per_K, coil.expansion_per_K, coil.midpoint_offset_m", "deg/h", nullptr, "winding_asymmetry_m", kBias,
	 "temperature steps and a sine sweep (rates of several sizes)", "coil.dn_dT_per_K and coil.expansion_per_K",
	 nullptr,
	 {}, {0.05, -kInf, false, windingAsymmetrySlot}},
	{Effect::RadialGradient, "radial_gradient", "elasto-optic bias proportional to Tin - Tout (coil layer means)",
	 "errors.radial_gradient_dph_per_C", "deg/h per degC", &EC::radial_gradient_dph_per_C,
	 "radial_gradient_dph_per_C", kBias, "a sine sweep near the coil's radial time constant, soaks after fast steps",
	 "errors.radial_gradient_dph_per_C", radialGradientTerm,
	 {}, {1e-3, -kInf, false, nullptr}},
	{Effect::GradientRate, "gradient_rate", "bias proportional to d(Tin - Tout)/dt",
	 "errors.gradient_rate_dph_per_C_per_min", "deg/h per degC/min", &EC::gradient_rate_dph_per_C_per_min,
	 "gradient_rate_dph_per_C_per_min", kBias, "temperature steps and a sine sweep near the radial time constant",
	 "errors.gradient_rate_dph_per_C_per_min", nullptr,
	 {}, {1e-3, -kInf, false, nullptr}},
	{Effect::ThermistorLag, "thermistor_lag", "first-order lag of the thermistors (off: they read the node instantly)",
	 "thermistors[*].tau_s", "s", nullptr, "", kBias,
	 "steps and ramps in several temperature bands (scales with the static bias curve's slope)",
	 "thermistors[*].tau_s", nullptr,
	 {}, {}},
	{Effect::Hysteresis, "hysteresis", "heating vs cooling offset (rate-independent play over a temperature span)",
	 "errors.hysteresis_dph", "deg/h", &EC::hysteresis_dph, "hysteresis_dph", kBias,
	 "heating and cooling ramps through the same temperatures", "errors.hysteresis_dph", nullptr,
	 {{{"hysteresis_span_C", &EC::hysteresis_span_C}}}, {1e-3, 0.0, false, nullptr}},
	{Effect::Warmup, "warmup", "decaying exponential after each power-on", "errors.warmup_dph", "deg/h",
	 &EC::warmup_dph, "warmup_dph", kBias, "power cycles at constant chamber temperature", "errors.warmup_dph",
	 warmupTerm,
	 {{{"warmup_tau_s", &EC::warmup_tau_s}}}, {1e-3, -kInf, false, nullptr}},
	{Effect::ScaleFactorTemp, "scale_factor_temp",
	 "scale factor vs coil temperature, acting on applied rate and Earth rate", "errors.sf_ppm_per_C", "ppm/degC",
	 &EC::sf_ppm_per_C, "sf_ppm_per_C", kBias, "rate-table segments at several temperatures", "errors.sf_ppm_per_C",
	 nullptr,
	 {{{"sf_ref_C", &EC::sf_ref_C}}}, {0.1, -kInf, false, nullptr}},
	{Effect::Magnetic, "magnetic", "axial magnetic field sensitivity", "errors.magnetic_dph_per_uT", "deg/h per uT",
	 &EC::magnetic_dph_per_uT, "magnetic_dph_per_uT", kBias, "field segments (axial field switched on and off)",
	 "errors.magnetic_dph_per_uT", magneticTerm,
	 {}, {1e-5, -kInf, false, nullptr}},
	{Effect::TempPolyOrder, "temp_poly_order", "static bias polynomial in the electronics (source) temperature",
	 "errors.temp_poly_dph", "deg/h per degC^k", nullptr, "temp_poly_dph", kBias,
	 "soaks at several temperature levels across the full range", "errors.temp_poly_dph (x^4 and x^5 terms)",
	 tempPolyTerm,
	 {{{"temp_poly_ref_C", &EC::temp_poly_ref_C}}}, {1e-5, -kInf, true, tempPolySlot}},
	{Effect::HeatSource, "heat_source", "electronics self-heating (off: zero power into the thermal network)",
	 "thermal.electronics_power_W", "W", nullptr, "electronics_power_W", IdentifiedIn::Temperature, "power cycles",
	 "", nullptr,
	 {}, {0.05, 1e-6, false, electronicsPowerSlot}},
	{Effect::EarthRate, "earth_rate", "vertical Earth rate at the device latitude", "latitude_deg", "deg", nullptr, "",
	 IdentifiedIn::NotIdentified, "", "", nullptr,
	 {}, {}},
}};
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
	return effect.coefficient && index == 0 ? &(device.errors.*effect.coefficient) : nullptr;
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
