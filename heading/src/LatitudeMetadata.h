/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file LatitudeMetadata.h
 * Where a FOG log's metadata holds its latitude, and how that text reads (private to the heading
 * library: latitudeOf skips a value that is not a latitude, driveLatitude refuses it). */

#include <cmath>
#include <exception>
#include <optional>
#include <string>

namespace mrpt_fog::heading_detail
{
/** Metadata keys that hold the latitude [deg], in the order they are looked up. */
constexpr const char* kLatitudeKeys[] = {"latitude_deg", "device.latitude_deg"};

/** The latitude [deg] a metadata value states: a number in [-90, 90] with no trailing text, else nothing. */
inline std::optional<double> latitudeFromText(const std::string& v)
{
	try
	{
		std::size_t pos = 0;
		const double lat = std::stod(v, &pos);
		if (pos == v.size() && std::abs(lat) <= 90) return lat;
	}
	catch (const std::exception&)
	{
	}
	return std::nullopt;
}
}  // namespace mrpt_fog::heading_detail
