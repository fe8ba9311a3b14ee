/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file YamlFields.h (private to the sim room)
 * Small checked readers over mrpt::containers::yaml that turn every problem into a
 * std::invalid_argument naming "<source>: <path>: <reason>". */

#include <mrpt/containers/yaml.h>

#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace mrpt_fog::sim::detail
{
[[noreturn]] inline void fieldError(const std::string& where, const std::string& why)
{
	throw std::invalid_argument(where + ": " + why);
}

/** Throws if the map has a key outside `allowed` (catches typos). */
inline void checkKeys(const mrpt::containers::yaml& node, const std::set<std::string>& allowed, const std::string& where)
{
	if (!node.isMap()) fieldError(where, "expected a map of key: value");
	for (const auto& kv : node.asMap())
	{
		const std::string key = kv.first.as<std::string>();
		if (!allowed.count(key))
		{
			std::string list;
			for (const auto& a : allowed) list += (list.empty() ? "" : ", ") + a;
			fieldError(where + "." + key, "unknown key (allowed: " + list + ")");
		}
	}
}

inline double readNumber(const mrpt::containers::yaml& node, const std::string& key, const std::string& where)
{
	if (!node.has(key)) fieldError(where + "." + key, "missing");
	double v = 0;
	try
	{
		v = node[key].as<double>();
	}
	catch (const std::exception&)
	{
		fieldError(where + "." + key, "expected a number");
	}
	if (!std::isfinite(v)) fieldError(where + "." + key, "must be finite");
	return v;
}

inline double readNumber(const mrpt::containers::yaml& node, const std::string& key, const std::string& where, double fallback)
{
	if (!node.has(key)) return fallback;
	return readNumber(node, key, where);
}

inline double readPositive(const mrpt::containers::yaml& node, const std::string& key, const std::string& where)
{
	const double v = readNumber(node, key, where);
	if (!(v > 0)) fieldError(where + "." + key, "must be > 0");
	return v;
}

inline double readNonNegative(const mrpt::containers::yaml& node, const std::string& key, const std::string& where, double fallback)
{
	const double v = readNumber(node, key, where, fallback);
	if (v < 0) fieldError(where + "." + key, "must be >= 0");
	return v;
}

inline std::string readString(const mrpt::containers::yaml& node, const std::string& key, const std::string& where, const std::string& fallback)
{
	if (!node.has(key)) return fallback;
	try
	{
		return node[key].as<std::string>();
	}
	catch (const std::exception&)
	{
		fieldError(where + "." + key, "expected a string");
	}
}

inline bool readBool(const mrpt::containers::yaml& node, const std::string& key, const std::string& where, bool fallback)
{
	if (!node.has(key)) return fallback;
	std::string s;
	try
	{
		s = node[key].as<std::string>();
	}
	catch (const std::exception&)
	{
		fieldError(where + "." + key, "expected true/false");
	}
	if (s == "true" || s == "on" || s == "yes" || s == "1" || s == "True") return true;
	if (s == "false" || s == "off" || s == "no" || s == "0" || s == "False") return false;
	fieldError(where + "." + key, "expected true/false, got '" + s + "'");
}

}  // namespace mrpt_fog::sim::detail
