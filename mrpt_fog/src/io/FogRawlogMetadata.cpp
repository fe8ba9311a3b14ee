/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/io/NumberText.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::io
{
namespace
{
const char* const kMagic = "# mrpt_fog metadata v1";

std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r");
	if (b == std::string::npos) return {};
	return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}
}  // namespace

void requireOneLineMetadata(const FogSeries& s)
{
	auto oneLine = [](const std::string& t) { return t.find_first_of("\r\n") == std::string::npos; };
	if (s.sensor_label.empty() || !oneLine(s.sensor_label))
		throw std::invalid_argument("sensor label '" + s.sensor_label + "' is empty or has a line break");
	for (const auto& [k, v] : s.metadata)
		if (!oneLine(k) || !oneLine(v) || k.find(':') != std::string::npos)
			throw std::invalid_argument("metadata key '" + k + "' has a line break or ':', or its value a line break");
}

std::string formatFogRawlogMetadata(const FogSeries& s)
{
	std::string out = std::string(kMagic) + "\n";
	out += "# sensor: " + s.sensor_label + "\n";
	out += "# epoch_s: " + formatNumber(s.epoch_s) + "\n";
	for (const auto& [k, v] : s.metadata)
	{
		if (k == "sensor" || k == "epoch_s") continue;
		out += k.empty() ? "# " + v + "\n" : "# " + k + ": " + v + "\n";
	}
	return out;
}

std::optional<FogRawlogMetadata> parseFogRawlogMetadata(const std::string& text)
{
	std::istringstream in(text);
	std::string line;
	if (!std::getline(in, line) || trim(line) != kMagic) return std::nullopt;
	FogRawlogMetadata m;
	bool has_sensor = false, has_epoch = false;
	while (std::getline(in, line))
	{
		line = trim(line);
		if (line.empty()) continue;
		if (line[0] != '#') return std::nullopt;
		const std::string body = trim(line.substr(1));
		const auto colon = body.find(':');
		if (colon == std::string::npos)
		{
			m.metadata.emplace_back("", body);
			continue;
		}
		const std::string key = trim(body.substr(0, colon)), value = trim(body.substr(colon + 1));
		if (key == "sensor")
		{
			m.sensor_label = value;
			has_sensor = true;
		}
		else if (key == "epoch_s")
		{
			const auto v = parseNumber(value);
			if (!v || !std::isfinite(*v)) return std::nullopt;
			m.epoch_s = *v;
			has_epoch = true;
		}
		else
			m.metadata.emplace_back(key, value);
	}
	if (!has_sensor || !has_epoch) return std::nullopt;
	return m;
}

}  // namespace mrpt_fog::io
