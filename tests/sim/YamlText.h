/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/** Test helpers: parse a YAML text with T::fromYaml(doc, source), or get the message it throws. */
#include <mrpt/containers/yaml.h>

#include <sstream>
#include <stdexcept>
#include <string>

namespace fogtest
{
template <class T>
T fromYamlText(const std::string& text, const std::string& source)
{
	std::istringstream ss(text);
	return T::fromYaml(mrpt::containers::yaml::FromStream(ss), source);
}

/** The std::invalid_argument message of fromYamlText, "" when it parses. */
template <class T>
std::string fromYamlTextError(const std::string& text, const std::string& source)
{
	try
	{
		fromYamlText<T>(text, source);
	}
	catch (const std::invalid_argument& e)
	{
		return e.what();
	}
	return "";
}
}  // namespace fogtest
