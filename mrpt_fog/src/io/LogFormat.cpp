/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/containers/yaml.h>
#include <mrpt_fog/common/ErrorText.h>
#include <mrpt_fog/common/YamlGuard.h>
#include <mrpt_fog/io/LogFormat.h>
#include <mrpt_fog/io/NumberText.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
constexpr double kPi = 3.14159265358979323846;
}

std::string toString(TimeUnit u)
{
	switch (u)
	{
		case TimeUnit::s: return "s";
		case TimeUnit::ms: return "ms";
		case TimeUnit::us: return "us";
		case TimeUnit::ns: return "ns";
	}
	return "?";
}
std::string toString(RateUnit u)
{
	switch (u)
	{
		case RateUnit::deg_per_h: return "deg/h";
		case RateUnit::deg_per_s: return "deg/s";
		case RateUnit::rad_per_s: return "rad/s";
		case RateUnit::mdeg_per_s: return "mdeg/s";
	}
	return "?";
}
std::string toString(TemperatureUnit u) { return u == TemperatureUnit::C ? "C" : "K"; }

TimeUnit timeUnitFromString(const std::string& t)
{
	for (auto u : {TimeUnit::s, TimeUnit::ms, TimeUnit::us, TimeUnit::ns})
		if (t == toString(u)) return u;
	throw std::invalid_argument("unknown time unit '" + t + "' (expected s, ms, us or ns)");
}
RateUnit rateUnitFromString(const std::string& t)
{
	for (auto u : {RateUnit::deg_per_h, RateUnit::deg_per_s, RateUnit::rad_per_s, RateUnit::mdeg_per_s})
		if (t == toString(u)) return u;
	throw std::invalid_argument("unknown rate unit '" + t + "' (expected deg/h, deg/s, rad/s or mdeg/s)");
}
TemperatureUnit temperatureUnitFromString(const std::string& t)
{
	if (t == "C") return TemperatureUnit::C;
	if (t == "K") return TemperatureUnit::K;
	throw std::invalid_argument("unknown temperature unit '" + t + "' (expected C or K)");
}

double secondsPer(TimeUnit u)
{
	switch (u)
	{
		case TimeUnit::s: return 1;
		case TimeUnit::ms: return 1e-3;
		case TimeUnit::us: return 1e-6;
		case TimeUnit::ns: return 1e-9;
	}
	return 1;
}
double degPerHourPer(RateUnit u)
{
	switch (u)
	{
		case RateUnit::deg_per_h: return 1;
		case RateUnit::deg_per_s: return 3600;
		case RateUnit::rad_per_s: return 3600 * 180 / kPi;
		case RateUnit::mdeg_per_s: return 3.6;
	}
	return 1;
}

std::vector<const FormatColumn*> LogFormat::columns() const
{
	std::vector<const FormatColumn*> out{&time};
	for (const auto& r : rates)
		if (r) out.push_back(&*r);
	for (const auto& t : thermistors) out.push_back(&t);
	if (table_rate) out.push_back(&*table_rate);
	if (field) out.push_back(&*field);
	if (power) out.push_back(&*power);
	return out;
}

namespace
{
using mrpt::containers::yaml;

/** Checked reading of the format file's nodes; every error names the source and the key. */
struct FormatReader
{
	std::string source;

	[[noreturn]] void fail(const std::string& key, const std::string& why) const
	{
		throw std::invalid_argument(source + ": " + key + ": " + why);
	}
	void keys(const yaml& n, const std::string& key, const std::set<std::string>& allowed) const
	{
		if (!n.isMap()) fail(key, "expected a map such as {column: \"...\", unit: ...}");
		for (const auto& kv : n.asMap())
		{
			const std::string k = kv.first.as<std::string>();
			if (!allowed.count(k))
			{
				std::string list;
				for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
				fail(key.empty() ? k : key + "." + k, "unknown key (allowed: " + list + ")");
			}
		}
	}
	std::string scalar(const yaml& n, const std::string& key) const
	{
		if (n.isNullNode()) return {};
		if (!n.isScalar()) fail(key, "expected a single value");
		try
		{
			return n.as<std::string>();
		}
		catch (const std::exception&)
		{
			fail(key, "expected a single value");
		}
	}
	std::string text(const yaml& n, const std::string& name, const std::string& key) const
	{
		if (!n.has(name)) fail(key + "." + name, "missing");
		const std::string v = scalar(n[name], key + "." + name);
		if (v.empty()) fail(key + "." + name, "empty");
		return v;
	}
	double number(const yaml& n, const std::string& name, const std::string& key) const
	{
		const std::string t = text(n, name, key);
		const auto v = io::parseNumber(t);
		if (!v || !std::isfinite(*v)) fail(key + "." + name, "'" + t + "' is not a finite number");
		return *v;
	}
	template <class Unit, class FromString>
	Unit unit(const yaml& n, const std::string& key, FromString fromString) const
	{
		const std::string t = text(n, "unit", key);
		try
		{
			return fromString(t);
		}
		catch (const std::invalid_argument& e)
		{
			fail(key + ".unit", e.what());
		}
	}
	FormatColumn column(const yaml& n, const std::string& key) const
	{
		FormatColumn c;
		c.key = key;
		c.column = text(n, "column", key);
		return c;
	}
	RateColumn rate(const yaml& n, const std::string& key) const
	{
		keys(n, key, {"column", "unit"});
		RateColumn r;
		static_cast<FormatColumn&>(r) = column(n, key);
		r.unit = unit<RateUnit>(n, key, rateUnitFromString);
		return r;
	}
};

}  // namespace

LogFormat parseLogFormat(const std::string& text, const std::string& source)
{
	FormatReader rd{source};
	requireSafeYamlText(text, source);
	yaml root;
	try
	{
		root = yaml::FromText(text);
	}
	catch (const std::exception& e)
	{
		throw std::invalid_argument(source + ": not valid YAML: " + oneLineErrorMessage(e.what()));
	}
	if (!root.isMap()) throw std::invalid_argument(source + ": expected a YAML map (keys time, rates, thermistors, ...)");
	rd.keys(root, "",
			{"delimiter", "skip_lines", "time", "rates", "thermistors", "table_rate", "field", "power", "metadata"});
	LogFormat f;
	f.source = source;
	if (root.has("delimiter"))
	{
		const std::string d = rd.scalar(root["delimiter"], "delimiter");
		if (d == "\t" || d == "tab" || d == "\\t") f.delimiter = '\t';
		else if (d.size() == 1 && d != "\"" && d != "\n" && d != "\r") f.delimiter = d[0];
		else rd.fail("delimiter", "expected one character such as \",\", \";\" or \"tab\", got '" + d + "'");
	}
	if (root.has("skip_lines"))
	{
		const double v = rd.number(root, "skip_lines", "");
		if (v < 0 || v > 1e6 || v != std::floor(v)) rd.fail("skip_lines", "expected a whole number of lines in [0, 1000000]");
		f.skip_lines = static_cast<std::size_t>(v);
	}
	if (!root.has("time")) rd.fail("time", "missing (e.g. time: {column: \"Time [ms]\", unit: ms})");
	{
		const yaml t = root["time"];
		rd.keys(t, "time", {"column", "unit"});
		f.time = rd.column(t, "time");
		f.time_unit = rd.unit<TimeUnit>(t, "time", timeUnitFromString);
	}
	if (!root.has("rates")) rd.fail("rates", "missing (e.g. rates: {z: {column: \"Gyro Z [deg/s]\", unit: deg/s}})");
	{
		const yaml r = root["rates"];
		rd.keys(r, "rates", {"x", "y", "z"});
		for (int a = 0; a < 3; a++)
		{
			const std::string axis(1, static_cast<char>('x' + a));
			if (r.has(axis)) f.rates[a] = rd.rate(r[axis], "rates." + axis);
		}
		if (!f.rates[0] && !f.rates[1] && !f.rates[2]) rd.fail("rates", "no axis mapped (expected x, y and/or z)");
	}
	if (root.has("thermistors") && !root["thermistors"].isNullNode())
	{
		const yaml th = root["thermistors"];
		if (!th.isMap()) rd.fail("thermistors", "expected a map of your thermistor names to {column, unit, side, angle_deg}");
		for (const auto& kv : th.asMap())
		{
			const std::string name = kv.first.as<std::string>();
			const std::string key = "thermistors." + name;
			if (!isValidThermistorName(name)) rd.fail(key, "'" + name + "' is not a valid thermistor name (letters, digits and '_' only)");
			const yaml n(kv.second);
			rd.keys(n, key, {"column", "unit", "side", "angle_deg"});
			ThermistorColumn t;
			static_cast<FormatColumn&>(t) = rd.column(n, key);
			t.name = name;
			t.unit = rd.unit<TemperatureUnit>(n, key, temperatureUnitFromString);
			if (n.has("side"))
			{
				t.side = rd.text(n, "side", key);
				try
				{
					coilSideFromString(t.side);
				}
				catch (const std::exception&)
				{
					rd.fail(key + ".side", "'" + t.side + "' is not inner, outer or other");
				}
			}
			if (n.has("angle_deg")) t.angle_deg = rd.number(n, "angle_deg", key);
			f.thermistors.push_back(t);
		}
		std::sort(f.thermistors.begin(), f.thermistors.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
	}
	if (root.has("table_rate")) f.table_rate = rd.rate(root["table_rate"], "table_rate");
	if (root.has("field"))
	{
		const yaml n = root["field"];
		rd.keys(n, "field", {"column", "unit"});
		f.field = rd.column(n, "field");
		const std::string u = rd.text(n, "unit", "field");
		if (u != "uT") rd.fail("field.unit", "unknown field unit '" + u + "' (expected uT)");
	}
	if (root.has("power"))
	{
		const yaml n = root["power"];
		rd.keys(n, "power", {"column"});
		f.power = rd.column(n, "power");
	}
	if (root.has("metadata") && !root["metadata"].isNullNode())
	{
		const yaml m = root["metadata"];
		if (!m.isMap()) rd.fail("metadata", "expected a map of key: value");
		for (const auto& kv : m.asMap())
		{
			const std::string key = kv.first.as<std::string>();
			const std::string value = rd.scalar(yaml(kv.second), "metadata." + key);
			if (key.empty() || key.find_first_of("\n\r:#") != std::string::npos || value.find_first_of("\n\r") != std::string::npos)
				rd.fail("metadata." + key, "keys and values must be one line (no ':' or '#' in a key)");
			if (key == "sensor" && value.empty()) rd.fail("metadata.sensor", "empty sensor label");
			if (key == "epoch_s" || key == "latitude_deg")
			{
				const auto v = io::parseNumber(value);
				if (!v || !std::isfinite(*v)) rd.fail("metadata." + key, "'" + value + "' is not a finite number");
				if (key == "latitude_deg" && std::abs(*v) > 90) rd.fail("metadata." + key, "not a latitude in [-90, 90] deg");
			}
			f.metadata.emplace_back(key, value);
		}
	}
	// One column, one meaning.
	std::map<std::string, std::string> owner;
	for (const FormatColumn* c : f.columns())
	{
		auto [it, fresh] = owner.emplace(c->column, c->key);
		if (!fresh) rd.fail(c->key + ".column", "column '" + c->column + "' is already mapped by " + it->second);
	}
	return f;
}

LogFormat readLogFormat(const std::string& path) { return parseLogFormat(readYamlTextLimited(path), path); }

}  // namespace mrpt_fog
