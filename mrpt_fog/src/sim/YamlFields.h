/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file YamlFields.h (private to the sim room)
 * Small checked readers over mrpt::containers::yaml that turn every problem into a
 * std::invalid_argument naming "<source>: <path>: <reason>". */

#include <mrpt/containers/yaml.h>
#include <mrpt_fog/common/Utf8.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <stdexcept>
#include <string>

namespace mrpt_fog::sim::detail
{
/** "<where>.<key>", or "<file>: <key>" when where is a file name ending in ':'. */
inline std::string sub(const std::string& where, const std::string& key)
{
	return (!where.empty() && where.back() == ':') ? where + " " + key : where + "." + key;
}

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
			fieldError(sub(where, key), "unknown key (allowed: " + list + ")");
		}
	}
}

inline double readNumber(const mrpt::containers::yaml& node, const std::string& key, const std::string& where)
{
	if (!node.has(key)) fieldError(sub(where, key), "missing");
	double v = 0;
	try
	{
		v = node[key].as<double>();
	}
	catch (const std::exception&)
	{
		fieldError(sub(where, key), "expected a number");
	}
	if (!std::isfinite(v)) fieldError(sub(where, key), "must be finite");
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
	if (!(v > 0)) fieldError(sub(where, key), "must be > 0");
	return v;
}

inline double readNonNegative(const mrpt::containers::yaml& node, const std::string& key, const std::string& where, double fallback)
{
	const double v = readNumber(node, key, where, fallback);
	if (v < 0) fieldError(sub(where, key), "must be >= 0");
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
		fieldError(sub(where, key), "expected a string");
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
		fieldError(sub(where, key), "expected true/false");
	}
	if (s == "true" || s == "on" || s == "yes" || s == "1" || s == "True") return true;
	if (s == "false" || s == "off" || s == "no" || s == "0" || s == "False") return false;
	fieldError(sub(where, key), "expected true/false, got '" + s + "'");
}

}  // namespace mrpt_fog::sim::detail

#include <mrpt_fog/common/YamlGuard.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <iostream>

namespace mrpt_fog::sim::detail
{
/** Parses a YAML file. MRPT's parser reports syntax errors on stderr and may return a partial
 * document instead of throwing: its stderr is captured during the parse and any message turns
 * into std::invalid_argument "<path>: not valid YAML: <first line>". */
inline mrpt::containers::yaml parseYamlFile(const std::string& path)
{
	// Size, nesting depth, aliases and UTF-8 checked before MRPT's parser sees the text.
	std::stringstream f(readYamlTextLimited(path));
	// An empty (or all-blank) file is an empty document: the caller says what it needed. (MRPT's
	// parser throws a bare std::length_error on an empty stream.)
	if (f.str().find_first_not_of(" \t\r\n") == std::string::npos) return mrpt::containers::yaml();
	std::fflush(stderr);
	std::cerr.flush();
	std::FILE* capture = std::tmpfile();
	const int saved = capture ? dup(STDERR_FILENO) : -1;
	if (saved >= 0) dup2(fileno(capture), STDERR_FILENO);
	mrpt::containers::yaml doc;
	std::string error;
	try
	{
		doc = mrpt::containers::yaml::FromStream(f);
	}
	catch (const std::exception& e)
	{
		error = e.what();
	}
	std::fflush(stderr);
	std::cerr.flush();
	if (saved >= 0)
	{
		dup2(saved, STDERR_FILENO);
		close(saved);
	}
	std::string captured;
	if (capture)
	{
		std::rewind(capture);
		char buf[512];
		while (std::fgets(buf, sizeof buf, capture)) captured += buf;
		std::fclose(capture);
	}
	if (error.empty()) error = captured;
	if (!error.empty())
	{
		// Keep the first line with text that is not MRPT's exception banner; drop the parser's
		// buffer address prefix.
		std::string line;
		for (std::size_t a = 0; a < error.size();)
		{
			const std::size_t b = std::min(error.find('\n', a), error.size());
			line = error.substr(a, b - a);
			if (line.find_first_not_of(" \t\r") != std::string::npos && line.rfind("====", 0) != 0) break;
			line.clear();
			a = b + 1;
		}
		const auto pos = line.find(">:");
		if (pos != std::string::npos) line = "line " + line.substr(pos + 2);
		throw std::invalid_argument(path + ": not valid YAML: " + line);
	}
	return doc;
}
}  // namespace mrpt_fog::sim::detail
