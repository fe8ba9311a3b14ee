/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/FogDevice.h>
#include <mrpt_fog/common/NumberFormat.h>

#include <mrpt/containers/yaml.h>

#include <cmath>
#include <fstream>
#include <set>
#include <stdexcept>

#include "YamlFields.h"

namespace mrpt_fog::sim
{
using namespace detail;

namespace
{
struct NumField
{
	const char* key;
	double* value;
};

std::vector<NumField> thermalFields(CoilThermalParams& t)
{
	return {{"mean_diameter_m", &t.mean_diameter_m},
			{"radial_thickness_m", &t.radial_thickness_m},
			{"axial_height_m", &t.axial_height_m},
			{"volumetric_heat_capacity_J_m3K", &t.volumetric_heat_capacity_J_m3K},
			{"radial_conductivity_W_mK", &t.radial_conductivity_W_mK},
			{"tangential_conductivity_W_mK", &t.tangential_conductivity_W_mK},
			{"hub_capacity_J_K", &t.hub_capacity_J_K},
			{"hub_to_inner_W_K", &t.hub_to_inner_W_K},
			{"housing_capacity_J_K", &t.housing_capacity_J_K},
			{"housing_to_air_W_K", &t.housing_to_air_W_K},
			{"outer_to_housing_W_K", &t.outer_to_housing_W_K},
			{"faces_to_housing_W_K", &t.faces_to_housing_W_K},
			{"mount_capacity_J_K", &t.mount_capacity_J_K},
			{"mount_to_air_W_K", &t.mount_to_air_W_K},
			{"mount_to_housing_W_K", &t.mount_to_housing_W_K},
			{"mount_to_hub_W_K", &t.mount_to_hub_W_K},
			{"mount_to_coil_W_K", &t.mount_to_coil_W_K},
			{"electronics_capacity_J_K", &t.electronics_capacity_J_K},
			{"electronics_to_housing_W_K", &t.electronics_to_housing_W_K},
			{"electronics_to_coil_W_K", &t.electronics_to_coil_W_K},
			{"electronics_power_W", &t.electronics_power_W}};
}

std::vector<NumField> coilFields(WindingParams& w)
{
	return {{"fiber_length_m", &w.fiber_length_m},	 {"mean_diameter_m", &w.mean_diameter_m},
			{"midpoint_offset_m", &w.midpoint_offset_m}, {"refractive_index", &w.refractive_index},
			{"dn_dT_per_K", &w.dn_dT_per_K},			 {"expansion_per_K", &w.expansion_per_K}};
}

/** The scalar `errors:` fields: the constant bias, then each effect's coefficient and shape
 * fields in the registry's order (temp_poly_dph, a list, is read on its own). */
std::vector<NumField> errorFields(ErrorCoefficients& e)
{
	static const std::string kSection = "errors.";
	std::vector<NumField> f{{"constant_bias_dph", &e.constant_bias_dph}};
	for (const auto& d : effectDescriptors())
	{
		if (double* c = coefficientIn(d, e))
		{
			if (std::string(d.coefficient_key).rfind(kSection, 0) != 0)
				throw std::logic_error(std::string("effect ") + d.id + ": coefficient key is not an errors: field");
			f.push_back({d.coefficient_key + kSection.size(), c});
		}
		for (const auto& shape : d.shape_fields)
			if (shape.key) f.push_back({shape.key, &(e.*shape.member)});
	}
	return f;
}

std::vector<NumField> noiseFields(GyroNoiseParams& n)
{
	return {{"arw_deg_rt_h", &n.arw_deg_rt_h},
			{"bias_instability_dph", &n.bias_instability_dph},
			{"bias_corr_time_s", &n.bias_corr_time_s},
			{"rrw_deg_h_rt_h", &n.rrw_deg_h_rt_h},
			{"angle_quantum_arcsec", &n.angle_quantum_arcsec}};
}

std::vector<NumField> turnOnFields(TurnOnParams& t)
{
	return {{"bias_repeatability_dph", &t.bias_repeatability_dph},
			{"sf_repeatability_ppm", &t.sf_repeatability_ppm},
			{"aging_dph_per_year", &t.aging_dph_per_year},
			{"age_days", &t.age_days}};
}

std::set<std::string> keysOf(const std::vector<NumField>& f, std::set<std::string> extra = {})
{
	for (const auto& x : f) extra.insert(x.key);
	return extra;
}

void readFields(const mrpt::containers::yaml& node, const std::vector<NumField>& fields, const std::string& where)
{
	for (const auto& f : fields) *f.value = readNumber(node, f.key, where, *f.value);
}

int readInt(const mrpt::containers::yaml& node, const std::string& key, const std::string& where, int fallback)
{
	const double v = readNumber(node, key, where, fallback);
	if (v != std::floor(v) || std::abs(v) > 1e6) fieldError(where + "." + key, "expected an integer");
	return static_cast<int>(v);
}
}  // namespace

FogDevice FogDevice::defaultDevice()
{
	FogDevice d;
	// Length asymmetry of the quadrupole halves (1.5 m of 1500 m, a loosely trimmed coil): with
	// errors.radial_gradient_dph_per_C, one of the two knobs FITTED to the seed's figures by
	// scripts/fit_seed_knobs.py (docs/reference/simulator.md, "default device"); weakly determined (0.5-2.5 m fit
	// about as well).
	d.winding.midpoint_offset_m = 1.5;
	// The seed's four thermistors: inner/outer pairs at 0 and 180 deg (seed Fig. 1).
	// Offsets: fixed values of the ~0.1 C size PHYSICS.md gives (estimate).
	d.thermistors = {{{"Ti1", CoilSide::Inner, 0.0}, 5.0, 0.05},
					 {{"To1", CoilSide::Outer, 0.0}, 5.0, -0.08},
					 {{"Ti2", CoilSide::Inner, 180.0}, 5.0, 0.03},
					 {{"To2", CoilSide::Outer, 180.0}, 5.0, -0.04}};
	return d;
}

FogDevice FogDevice::fromYaml(const mrpt::containers::yaml& doc, const std::string& source)
{
	FogDevice d = defaultDevice();
	if (doc.isNullNode()) return d;
	const std::string top = source + ":";
	checkKeys(doc,
			  {"name", "latitude_deg", "coil", "thermal", "errors", "noise", "turn_on", "thermistors", "thermistor_noise_C",
			   "thermistor_quantum_C"},
			  top);
	d.name = readString(doc, "name", top, "custom");
	d.latitude_deg = readNumber(doc, "latitude_deg", top, d.latitude_deg);
	if (std::abs(d.latitude_deg) > 90) fieldError(top + " latitude_deg", "must be within [-90, 90]");
	d.thermistor_noise_C = readNonNegative(doc, "thermistor_noise_C", top, d.thermistor_noise_C);
	d.thermistor_quantum_C = readNonNegative(doc, "thermistor_quantum_C", top, d.thermistor_quantum_C);
	if (doc.has("coil"))
	{
		const auto node = doc["coil"];
		const std::string w = source + ": coil";
		checkKeys(node, keysOf(coilFields(d.winding), {"pattern", "fiber_layers", "layer_length_mismatch"}), w);
		readFields(node, coilFields(d.winding), w);
		// not in coilFields: describe() lists it only when set, so that the metadata (and the
		// bundled datasets' bytes) of devices without it do not change
		d.winding.layer_length_mismatch = readNumber(node, "layer_length_mismatch", w, d.winding.layer_length_mismatch);
		d.winding.fiber_layers = readInt(node, "fiber_layers", w, d.winding.fiber_layers);
		if (node.has("pattern"))
		{
			try
			{
				d.winding.pattern = windingPatternFromString(readString(node, "pattern", w, ""));
			}
			catch (const std::invalid_argument& e)
			{
				fieldError(w + ".pattern", e.what());
			}
		}
	}
	if (doc.has("thermal"))
	{
		const auto node = doc["thermal"];
		const std::string w = source + ": thermal";
		checkKeys(node, keysOf(thermalFields(d.thermal), {"layers", "sectors"}), w);
		readFields(node, thermalFields(d.thermal), w);
		d.thermal.layers = readInt(node, "layers", w, d.thermal.layers);
		d.thermal.sectors = readInt(node, "sectors", w, d.thermal.sectors);
	}
	if (doc.has("errors"))
	{
		const auto node = doc["errors"];
		const std::string w = source + ": errors";
		checkKeys(node, keysOf(errorFields(d.errors), {"temp_poly_dph"}), w);
		readFields(node, errorFields(d.errors), w);
		if (node.has("temp_poly_dph"))
		{
			if (!node["temp_poly_dph"].isSequence()) fieldError(w + ".temp_poly_dph", "expected a list [c1, c2, ...]");
			d.errors.temp_poly_dph.clear();
			const auto& seq = node["temp_poly_dph"].asSequence();
			for (std::size_t i = 0; i < seq.size(); i++)
			{
				double v = 0;
				try
				{
					v = mrpt::containers::yaml(seq[i]).as<double>();
				}
				catch (const std::exception&)
				{
					fieldError(w + ".temp_poly_dph[" + std::to_string(i) + "]", "expected a number");
				}
				d.errors.temp_poly_dph.push_back(v);
			}
		}
	}
	if (doc.has("noise"))
	{
		const auto node = doc["noise"];
		const std::string w = source + ": noise";
		checkKeys(node, keysOf(noiseFields(d.noise)), w);
		readFields(node, noiseFields(d.noise), w);
	}
	if (doc.has("turn_on"))
	{
		const auto node = doc["turn_on"];
		const std::string w = source + ": turn_on";
		checkKeys(node, keysOf(turnOnFields(d.turn_on)), w);
		readFields(node, turnOnFields(d.turn_on), w);
	}
	if (doc.has("thermistors"))
	{
		if (!doc["thermistors"].isSequence()) fieldError(source + ": thermistors", "expected a list");
		d.thermistors.clear();
		const auto& seq = doc["thermistors"].asSequence();
		for (std::size_t i = 0; i < seq.size(); i++)
		{
			const mrpt::containers::yaml node(seq[i]);
			const std::string w = source + ": thermistors[" + std::to_string(i) + "]";
			checkKeys(node, {"name", "side", "angle_deg", "tau_s", "offset_C"}, w);
			ThermistorSpec t;
			t.info.name = readString(node, "name", w, "");
			if (!isValidThermistorName(t.info.name)) fieldError(w + ".name", "missing or not [A-Za-z0-9_]+");
			try
			{
				t.info.side = coilSideFromString(readString(node, "side", w, "inner"));
			}
			catch (const std::invalid_argument& e)
			{
				fieldError(w + ".side", e.what());
			}
			if (t.info.side == CoilSide::Other) fieldError(w + ".side", "the simulator places thermistors inner or outer");
			t.info.angle_deg = readNumber(node, "angle_deg", w, 0.0);
			t.tau_s = readNonNegative(node, "tau_s", w, 5.0);
			t.offset_C = readNumber(node, "offset_C", w, 0.0);
			d.thermistors.push_back(t);
		}
	}
	try
	{
		d.validate();
	}
	catch (const std::invalid_argument& e)
	{
		throw std::invalid_argument(source + ": " + e.what());
	}
	return d;
}

FogDevice FogDevice::fromFile(const std::string& path)
{
	return fromYaml(parseYamlFile(path), path);
}

double FogDevice::epoch_s() const
{
	constexpr double kSecondsPerDay = 86400.0;
	return kSimEpoch_s + turn_on.age_days * kSecondsPerDay;
}

FogDevice FogDevice::withoutNoise() const
{
	FogDevice dev = *this;
	dev.noise.arw_deg_rt_h = 0;
	dev.noise.bias_instability_dph = 0;
	dev.noise.rrw_deg_h_rt_h = 0;
	dev.noise.angle_quantum_arcsec = 0;
	dev.thermistor_noise_C = 0;
	dev.thermistor_quantum_C = 0;
	return dev;
}

void FogDevice::validate() const
{
	thermal.validate();
	winding.validate();
	const std::pair<const char*, double> nonneg[] = {
		{"noise.arw_deg_rt_h", noise.arw_deg_rt_h},
		{"noise.bias_instability_dph", noise.bias_instability_dph},
		{"noise.rrw_deg_h_rt_h", noise.rrw_deg_h_rt_h},
		{"noise.angle_quantum_arcsec", noise.angle_quantum_arcsec},
		{"errors.hysteresis_dph", errors.hysteresis_dph()},
		{"turn_on.bias_repeatability_dph", turn_on.bias_repeatability_dph},
		{"turn_on.sf_repeatability_ppm", turn_on.sf_repeatability_ppm},
		{"turn_on.age_days", turn_on.age_days},
	};
	for (const auto& [name, v] : nonneg)
		if (!(v >= 0)) throw std::invalid_argument(std::string(name) + ": must be >= 0");
	if (!std::isfinite(turn_on.aging_dph_per_year)) throw std::invalid_argument("turn_on.aging_dph_per_year: must be finite");
	if (!(noise.bias_corr_time_s > 0)) throw std::invalid_argument("noise.bias_corr_time_s: must be > 0");
	if (!(errors.hysteresis_span_C > 0)) throw std::invalid_argument("errors.hysteresis_span_C: must be > 0");
	if (!(errors.warmup_tau_s > 0)) throw std::invalid_argument("errors.warmup_tau_s: must be > 0");
	std::set<std::string> names;
	for (const auto& t : thermistors)
		if (!names.insert(t.info.name).second)
			throw std::invalid_argument("thermistors: duplicate name '" + t.info.name + "'");
}

std::vector<std::pair<std::string, std::string>> FogDevice::describe() const
{
	FogDevice c = *this;  // the field tables take non-const pointers
	std::vector<std::pair<std::string, std::string>> out;
	out.emplace_back("device.name", name);
	out.emplace_back("device.latitude_deg", formatValue("%.10g", latitude_deg));
	out.emplace_back("device.coil.pattern", toString(winding.pattern));
	out.emplace_back("device.coil.fiber_layers", std::to_string(winding.fiber_layers));
	for (const auto& f : coilFields(c.winding)) out.emplace_back(std::string("device.coil.") + f.key, formatValue("%.10g", *f.value));
	if (winding.layer_length_mismatch != 0.0)
		out.emplace_back("device.coil.layer_length_mismatch", formatValue("%.10g", winding.layer_length_mismatch));
	out.emplace_back("device.thermal.layers", std::to_string(thermal.layers));
	out.emplace_back("device.thermal.sectors", std::to_string(thermal.sectors));
	for (const auto& f : thermalFields(c.thermal))
		out.emplace_back(std::string("device.thermal.") + f.key, formatValue("%.10g", *f.value));
	for (const auto& f : errorFields(c.errors)) out.emplace_back(std::string("device.errors.") + f.key, formatValue("%.10g", *f.value));
	std::string poly;
	for (double v : errors.temp_poly_dph) poly += (poly.empty() ? "" : ",") + formatValue("%.10g", v);
	out.emplace_back("device.errors.temp_poly_dph", "[" + poly + "]");
	for (const auto& f : noiseFields(c.noise)) out.emplace_back(std::string("device.noise.") + f.key, formatValue("%.10g", *f.value));
	// listed only when set, so that the metadata (and the bundled datasets' bytes) of devices
	// without them do not change
	if (turn_on.any())
		for (const auto& f : turnOnFields(c.turn_on))
			out.emplace_back(std::string("device.turn_on.") + f.key, formatValue("%.10g", *f.value));
	for (const auto& t : thermistors)
		out.emplace_back("device.thermistor." + t.info.name, std::string("side=") + toString(t.info.side) +
																  " angle_deg=" + formatValue("%.10g", t.info.angle_deg) +
																  " tau_s=" + formatValue("%.10g", t.tau_s) + " offset_C=" + formatValue("%.10g", t.offset_C));
	out.emplace_back("device.thermistor_noise_C", formatValue("%.10g", thermistor_noise_C));
	out.emplace_back("device.thermistor_quantum_C", formatValue("%.10g", thermistor_quantum_C));
	return out;
}

}  // namespace mrpt_fog::sim
