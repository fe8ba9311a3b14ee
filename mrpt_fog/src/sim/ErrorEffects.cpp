/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/ErrorEffects.h>

#include <algorithm>
#include <stdexcept>

namespace mrpt_fog::sim
{
const std::vector<std::string>& allEffectIds()
{
	static const std::vector<std::string> ids = []
	{
		std::vector<std::string> v;
		for (const auto& d : effectDescriptors()) v.push_back(d.id);
		return v;
	}();
	return ids;
}

EffectSet defaultEffects()
{
	const auto& ids = allEffectIds();
	return EffectSet(ids.begin(), ids.end());
}

void checkEffectId(const std::string& id) { effectFromId(id); }

EffectSet effectsFromSelection(const std::vector<std::string>& selection)
{
	EffectSet set = defaultEffects();
	bool explicit_started = false;
	for (const auto& item : selection)
	{
		if (item == "all")
		{
			set = defaultEffects();
			explicit_started = true;
		}
		else if (item == "none")
		{
			set.clear();
			explicit_started = true;
		}
		else if (!item.empty() && (item[0] == '-' || item[0] == '+'))
		{
			const std::string id = item.substr(1);
			checkEffectId(id);
			if (item[0] == '-')
				set.erase(id);
			else
				set.insert(id);
		}
		else
		{
			checkEffectId(item);
			if (!explicit_started)
			{
				set.clear();
				explicit_started = true;
			}
			set.insert(item);
		}
	}
	return set;
}

std::string effectsToString(const EffectSet& effects)
{
	std::string s;
	for (const auto& id : allEffectIds())
		if (effects.count(id)) s += (s.empty() ? "" : ",") + id;
	return s.empty() ? "none" : s;
}

}  // namespace mrpt_fog::sim
