/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogRawlogMetadata.h
 * A FOG series' run-level metadata (time origin epoch_s, latitude, free `key: value` notes)
 * has no place in per-sample observations. writeFogRawlog() stores it in a stock
 * mrpt::obs::CObservationComment (label "<sensor>_METADATA") heading the file, written in the
 * same `# key: value` lines as the CSV header, so that CSV -> rawlog -> CSV loses nothing:
 *
 *   # mrpt_fog metadata v1
 *   # sensor: FOG
 *   # epoch_s: 1700000000
 *   # latitude_deg: 45.5
 *
 * Any MRPT tool shows it as a plain comment. */

#include <mrpt_fog/obs/FogSeries.h>

#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog::io
{
struct FogRawlogMetadata
{
	std::string sensor_label;
	double epoch_s = 0.0;  //!< UNIX time [s] of time_s == 0
	std::vector<std::pair<std::string, std::string>> metadata;  //!< as FogSeries::metadata
};

/** Throws std::invalid_argument unless every piece of run metadata fits one `# key: value`
 * line: non-empty sensor label without line breaks, keys without ':' or line breaks, values
 * without line breaks. Both writers (CSV, rawlog) check this first. */
void requireOneLineMetadata(const FogSeries& series);

/** The comment text for a series (first line "# mrpt_fog metadata v1"). */
std::string formatFogRawlogMetadata(const FogSeries& series);

/** Parses a comment text; std::nullopt when it is not an mrpt_fog metadata block (any other
 * comment), or when its sensor/epoch lines are missing or unparsable. */
std::optional<FogRawlogMetadata> parseFogRawlogMetadata(const std::string& text);

}  // namespace mrpt_fog::io
