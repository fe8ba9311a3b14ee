/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/model/ModelPreset.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
std::vector<std::string> split(const std::string& s, char sep)
{
	std::vector<std::string> out;
	std::string cur;
	std::istringstream in(s);
	while (std::getline(in, cur, sep)) out.push_back(cur);
	return out;
}

std::string layoutNames(const std::vector<ThermistorInfo>& layout)
{
	std::string s;
	for (const auto& t : layout) s += (s.empty() ? "" : ", ") + t.name;
	return s.empty() ? "(none)" : s;
}

int parseInt(const std::string& s, const std::string& what, const std::string& text)
{
	if (s.empty() || s.find_first_not_of("0123456789") != std::string::npos)
		throw std::invalid_argument("model preset '" + text + "': " + what + " must be a whole number, got '" + s + "'");
	return std::stoi(s);
}
}  // namespace

std::vector<ThermalTerm> multipointTerms(const std::vector<std::string>& names, int temp_order, int rate_order)
{
	std::vector<ThermalTerm> terms;
	for (const auto& n : names)
	{
		for (int k = 1; k <= temp_order; k++) terms.push_back(ThermalTerm::of(SignalKind::Temp, n, "", k));
		for (int k = 1; k <= rate_order; k++) terms.push_back(ThermalTerm::of(SignalKind::Rate, n, "", k));
	}
	return terms;
}

namespace
{
constexpr EnumName<PresetKind> kPresetKinds[] = {
	{PresetKind::Multipoint, "multipoint"}, {PresetKind::M1, "M1"},		  {PresetKind::M2, "M2"},
	{PresetKind::M3, "M3"},					{PresetKind::M4, "M4"},		  {PresetKind::Points, "points"},
	{PresetKind::Terms, "terms"}};
}  // namespace

const char* toString(PresetKind kind) { return nameIn(kPresetKinds, kind, "?"); }

ModelPreset parseModelPreset(const std::string& text, const std::vector<ThermistorInfo>& layout)
{
	ModelPreset p;
	p.text = text;
	const auto fail = [&](const std::string& why) { throw std::invalid_argument("model preset '" + text + "': " + why); };
	if (text.empty()) fail("empty (use multipoint, M1..M4, points:K or terms:...)");
	std::string body = text;
	bool rate_given = false;
	if (text.rfind("terms:", 0) == 0)
	{
		p.kind = PresetKind::Terms;
		for (const auto& name : split(text.substr(6), ';'))
			if (!name.empty()) p.explicit_terms.push_back(ThermalTerm::parse(name));
		if (p.explicit_terms.empty()) fail("no terms listed");
		ThermalFeatureSet fs(p.explicit_terms);
		for (const auto& n : fs.thermistors())
		{
			bool found = false;
			for (const auto& t : layout) found |= t.name == n;
			if (!found) fail("unknown thermistor '" + n + "' (the data has: " + layoutNames(layout) + ")");
		}
		p.thermistors = fs.thermistors();
		return p;
	}
	const auto at = body.find('@');
	if (at != std::string::npos)
	{
		const auto orders = split(body.substr(at + 1), '/');
		if (orders.empty() || orders.size() > 2 || body.back() == '/')
			fail("orders must be written @T/R (e.g. @5/3) or @T (temperature order only)");
		p.temp_order = parseInt(orders[0], "temperature order", text);
		rate_given = orders.size() == 2;
		if (rate_given) p.rate_order = parseInt(orders[1], "rate order", text);
		if (p.temp_order < 1 || p.temp_order > 5) fail("temperature order must be 1..5");
		if (p.rate_order < 0 || p.rate_order > 3) fail("rate order must be 0..3");
		body = body.substr(0, at);
	}
	const auto colon = body.find(':');
	const std::string kind_text = body.substr(0, colon);
	std::vector<std::string> args;
	if (colon != std::string::npos)
	{
		args = split(body.substr(colon + 1), ',');
		if (args.empty()) fail("nothing after ':'");
	}
	if (layout.empty()) fail("the data has no thermistors");
	const auto kind = valueIn(kPresetKinds, kind_text);
	if (!kind || *kind == PresetKind::Terms)  // terms come as "terms:A;B" (above)
		fail("unknown preset '" + kind_text + "' (use multipoint, M1..M4, points:K or terms:...)");
	p.kind = *kind;
	const auto check = [&](const std::string& n) -> const ThermistorInfo& {
		for (const auto& t : layout)
			if (t.name == n) return t;
		fail("unknown thermistor '" + n + "' (the data has: " + layoutNames(layout) + ")");
		return layout.front();
	};
	const auto firstInner = [&]() {
		for (const auto& t : layout)
			if (t.side == CoilSide::Inner) return t.name;
		return layout.front().name;
	};
	const auto outerNearest = [&](const ThermistorInfo& in) {
		const ThermistorInfo* best = nullptr;
		for (const auto& t : layout)
			if (t.side == CoilSide::Outer &&
				(!best || std::abs(t.angle_deg - in.angle_deg) < std::abs(best->angle_deg - in.angle_deg)))
				best = &t;
		if (!best) fail("no outer thermistor in the data for the inner/outer pair; name it as :IN,OUT");
		return best->name;
	};
	if (p.kind == PresetKind::Multipoint)
	{
		if (args.empty())
			for (const auto& t : layout) p.thermistors.push_back(t.name);
		for (const auto& a : args) p.thermistors.push_back(check(a).name);
	}
	else if (p.kind == PresetKind::M1 || p.kind == PresetKind::M2)
	{
		if (p.kind == PresetKind::M1 && rate_given && p.rate_order != 0)
			fail("M1 is poly(T) only and has no rate terms: write M1@T (e.g. M1@3), or use M2 for rates");
		if (args.size() > 1) fail(kind_text + " takes one thermistor (" + kind_text + ":NAME)");
		p.thermistors.push_back(args.empty() ? firstInner() : check(args[0]).name);
	}
	else if (p.kind == PresetKind::M3 || p.kind == PresetKind::M4)
	{
		if (args.size() == 1 || args.size() > 2) fail(kind_text + " takes an inner/outer pair (" + kind_text + ":IN,OUT)");
		if (args.empty())
		{
			const auto& in = check(firstInner());
			p.thermistors = {in.name, outerNearest(in)};
		}
		else
			p.thermistors = {check(args[0]).name, check(args[1]).name};
		if (p.thermistors[0] == p.thermistors[1]) fail("the pair must be two different thermistors");
	}
	else  // PresetKind::Points
	{
		if (args.size() != 1) fail("write points:K with K the number of thermistors to use");
		p.points_k = parseInt(args[0], "K", text);
		if (p.points_k < 1 || p.points_k > static_cast<int>(layout.size()))
			fail("K must be 1.." + std::to_string(layout.size()) + " (thermistors in the data)");
		for (const auto& t : layout) p.thermistors.push_back(t.name);
	}
	for (std::size_t i = 0; i < p.thermistors.size(); i++)
		for (std::size_t j = 0; j < i; j++)
			if (p.thermistors[i] == p.thermistors[j]) fail("thermistor '" + p.thermistors[i] + "' listed twice");
	return p;
}

ThermalFeatureSet presetFeatures(const ModelPreset& p)
{
	if (p.kind == PresetKind::Terms) return ThermalFeatureSet(p.explicit_terms);
	if (p.kind == PresetKind::Multipoint || p.kind == PresetKind::Points) return ThermalFeatureSet(multipointTerms(p.thermistors, p.temp_order, p.rate_order));
	const std::string& a = p.thermistors.at(0);
	std::vector<ThermalTerm> terms;
	if (p.kind == PresetKind::M1) terms = multipointTerms({a}, p.temp_order, 0);
	else if (p.kind == PresetKind::M2) terms = multipointTerms({a}, p.temp_order, p.rate_order);
	else if (p.kind == PresetKind::M3)
	{
		terms = multipointTerms({a}, p.temp_order, p.rate_order);
		for (int k = 1; k <= std::max(1, p.rate_order); k++)
			terms.push_back(ThermalTerm::of(SignalKind::Diff, a, p.thermistors.at(1), k));
	}
	else if (p.kind == PresetKind::M4)
	{
		for (int k = 1; k <= std::max(1, p.rate_order); k++)
			terms.push_back(ThermalTerm::of(SignalKind::Diff, a, p.thermistors.at(1), k));
		for (int k = 1; k <= p.rate_order; k++)
			terms.push_back(ThermalTerm::of(SignalKind::DiffRate, a, p.thermistors.at(1), k));
	}
	return ThermalFeatureSet(terms);
}

}  // namespace mrpt_fog
