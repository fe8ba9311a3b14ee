/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "JsonFigures.h"

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

namespace mrpt_fog::demo
{
JsonFigures::JsonFigures(const std::string& path)
{
	try
	{
		doc_ = mrpt::containers::yaml::FromFile(path);
	}
	catch (const std::exception& e)
	{
		throw std::runtime_error("cannot read figures from '" + path + "': " + std::string(e.what()).substr(0, 200));
	}
}

namespace
{
std::optional<mrpt::containers::yaml> descend(const mrpt::containers::yaml& node, const std::vector<std::string>& keys,
											  std::size_t i)
{
	if (i == keys.size()) return node;
	if (!node.isMap() || !node.has(keys[i])) return std::nullopt;
	return descend(node[keys[i].c_str()], keys, i + 1);
}
}  // namespace

std::optional<mrpt::containers::yaml> JsonFigures::find(const std::string& dotted_path) const
{
	std::vector<std::string> keys;
	std::stringstream ss(dotted_path);
	std::string key;
	while (std::getline(ss, key, '.')) keys.push_back(key);
	return descend(doc_, keys, 0);
}

bool JsonFigures::has(const std::string& dotted_path) const
{
	const auto n = find(dotted_path);
	return n && !n->isNullNode();
}

double JsonFigures::numberAt(const std::vector<std::string>& keys) const
{
	const auto n = descend(doc_, keys, 0);
	if (!n || n->isNullNode()) return std::numeric_limits<double>::quiet_NaN();
	try
	{
		return n->as<double>();
	}
	catch (const std::exception&)
	{
		return std::numeric_limits<double>::quiet_NaN();
	}
}

double JsonFigures::number(const std::string& dotted_path) const
{
	const auto n = find(dotted_path);
	if (!n || n->isNullNode()) return std::numeric_limits<double>::quiet_NaN();
	try
	{
		return n->as<double>();
	}
	catch (const std::exception&)
	{
		return std::numeric_limits<double>::quiet_NaN();
	}
}

std::string JsonFigures::text(const std::string& dotted_path) const
{
	const auto n = find(dotted_path);
	if (!n || n->isNullNode() || !n->isScalar()) return {};
	try
	{
		return n->as<std::string>();
	}
	catch (const std::exception&)
	{
		return {};
	}
}
}  // namespace mrpt_fog::demo
