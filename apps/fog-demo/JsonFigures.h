/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file JsonFigures.h
 * Reads figures back from the programs' --json outputs (JSON is YAML, so MRPT's YAML parser
 * reads it). A missing key or a JSON null (a figure that could not be computed) gives NaN. */

#include <mrpt/containers/yaml.h>

#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog::demo
{
class JsonFigures
{
   public:
	/** Loads a JSON file; throws std::runtime_error naming the file when it cannot be parsed. */
	explicit JsonFigures(const std::string& path);
	/** Number at a dotted path ("raw.stability_dph"); NaN when absent or null. */
	double number(const std::string& dotted_path) const;
	bool has(const std::string& dotted_path) const;
	/** Number at a path of keys that may themselves hold dots (fog-drift's over_drives keys,
	 * e.g. {"over_drives", "ratio.heading_rms_compensated_over_raw", "median"}); NaN when absent. */
	double numberAt(const std::vector<std::string>& keys) const;
	/** Text at a dotted path; empty when absent, null or not a scalar. */
	std::string text(const std::string& dotted_path) const;

   private:
	std::optional<mrpt::containers::yaml> find(const std::string& dotted_path) const;
	mrpt::containers::yaml doc_;
};
}  // namespace mrpt_fog::demo
