/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/SimulatorConfig.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <algorithm>
#include <filesystem>
#include <stdexcept>

// The sim room's checked YAML readers (header-only, used read-only here).
#include "../sim/YamlFields.h"

namespace mrpt_fog::discrepancy
{
namespace
{
using mrpt::containers::yaml;

std::vector<std::string> readIdList(const yaml& doc, const std::string& key, const std::string& where)
{
	std::vector<std::string> out;
	const auto& node = doc[key];
	if (!node.isSequence()) throw std::invalid_argument(where + " " + key + ": expected a list [id, ...]");
	const auto& seq = node.asSequence();
	for (std::size_t i = 0; i < seq.size(); ++i)
	{
		try
		{
			out.push_back(yaml(seq[i]).as<std::string>());
		}
		catch (const std::exception&)
		{
			throw std::invalid_argument(where + " " + key + "[" + std::to_string(i) + "]: expected an id");
		}
	}
	return out;
}
}  // namespace

const std::vector<std::string>& freeParameterIds()
{
	// the constant bias, each effect's calibration parameter (registry order), the thermal
	// network's time scale, the thermistor offsets and the scale factor's reference temperature
	static const std::vector<std::string> ids = [] {
		std::vector<std::string> v{"constant_bias_dph"};
		for (const auto& d : sim::effectDescriptors())
			if (*d.calibration_parameter) v.push_back(d.calibration_parameter);
		v.push_back("thermal_time_scale");
		v.push_back("thermistor_offsets_C");
		v.push_back("sf_ref_C");
		return v;
	}();
	return ids;
}

std::string coefficientParameterOf(const std::string& effect_id)
{
	for (const auto& d : sim::effectDescriptors())
		if (effect_id == d.id) return d.calibration_parameter;
	return "";
}

std::vector<std::string> defaultFreeParameters(const sim::EffectSet& effects)
{
	std::vector<std::string> out{"constant_bias_dph"};
	for (const auto& id : sim::allEffectIds())
		if (effects.count(id))
			if (auto p = coefficientParameterOf(id); !p.empty()) out.push_back(p);
	out.push_back("thermal_time_scale");
	out.push_back("thermistor_offsets_C");
	return out;
}

SimulatorConfig simulatorConfigFromYaml(const yaml& doc, const std::string& source, const std::string& base_dir)
{
	using namespace sim::detail;
	SimulatorConfig cfg;
	cfg.source = source;
	const std::string top = source + ":";
	if (doc.isNullNode())
		throw std::invalid_argument(source +
									": empty: a simulator configuration needs at least the device, e.g. `device_file: gyro.yaml` "
									"or `device: {}` for fog-sim's default gyro (keys: device, device_file, effects, free, "
									"profile; docs/guide/model-gap-simulator.md)");
	if (!doc.isMap())
		throw std::invalid_argument(source + ": expected a map of key: value (keys: device, device_file, effects, free, profile)");
	checkKeys(doc, {"device", "device_file", "effects", "free", "profile"}, top);
	if (doc.has("device") && doc.has("device_file"))
		throw std::invalid_argument(source + ": device, device_file: give one of them, not both");
	if (doc.has("device")) cfg.device = sim::FogDevice::fromYaml(doc["device"], source + ": device");
	if (doc.has("device_file"))
	{
		std::filesystem::path p(readString(doc, "device_file", top, ""));
		if (p.is_relative()) p = std::filesystem::path(base_dir) / p;
		cfg.device = sim::FogDevice::fromFile(p.string());
	}
	if (doc.has("effects"))
	{
		try
		{
			cfg.effects = sim::effectsFromSelection(readIdList(doc, "effects", top));
		}
		catch (const std::invalid_argument& e)
		{
			throw std::invalid_argument(std::string(source) + ": effects: " + e.what());
		}
	}
	if (doc.has("free"))
	{
		cfg.free_is_default = false;
		const auto& known = freeParameterIds();
		for (const auto& id : readIdList(doc, "free", top))
		{
			if (std::find(known.begin(), known.end(), id) == known.end())
			{
				std::string list;
				for (const auto& k : known) list += (list.empty() ? "" : ", ") + k;
				throw std::invalid_argument(source + ": free: unknown parameter '" + id + "' (known: " + list + ")");
			}
			if (std::find(cfg.free.begin(), cfg.free.end(), id) == cfg.free.end()) cfg.free.push_back(id);
		}
	}
	else
		cfg.free = defaultFreeParameters(cfg.effects);
	cfg.profile = readString(doc, "profile", top, "");
	return cfg;
}

SimulatorConfig readSimulatorConfig(const std::string& path)
{
	const auto doc = sim::detail::parseYamlFile(path);
	const auto dir = std::filesystem::path(path).parent_path();
	return simulatorConfigFromYaml(doc, path, dir.empty() ? "." : dir.string());
}

}  // namespace mrpt_fog::discrepancy
