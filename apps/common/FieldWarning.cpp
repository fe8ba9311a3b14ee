/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "FieldWarning.h"

#include <cmath>
#include <cstdio>

namespace mrpt_fog::app
{
namespace
{
/** The out-of-range line, worded as the temperature's (RangeWarning.h), or "". */
std::string fieldOutsideWarning(const Calibration& cal, const CompensationCounters& c)
{
	if (!cal.magnetic || c.field_outside_samples == 0) return {};
	char b[400];
	std::snprintf(b, sizeof b,
				  "  warning: axis %c: %.1f %% of samples (%zu) have an applied field (field_uT) outside the "
				  "calibrated range [%.4g, %.4g] uT, up to %.4g uT beyond it (magnetic term extrapolated: up to "
				  "%.3g deg/h beyond the calibrated contribution)\n",
				  axisLetter(cal.axis),
				  c.samples ? 100.0 * static_cast<double>(c.field_outside_samples) / static_cast<double>(c.samples) : 0.0,
				  c.field_outside_samples, cal.magnetic->field_min_uT, cal.magnetic->field_max_uT,
				  c.max_field_excursion_uT, std::abs(cal.magnetic->dph_per_uT) * c.max_field_excursion_uT);
	return b;
}
}  // namespace

std::string fieldWarning(const Calibration& cal, const CompensationCounters& c, bool log_has_field)
{
	const std::string outside = fieldOutsideWarning(cal, c);
	if (!cal.magnetic || c.field_unknown_samples == 0) return outside;
	char b[320];
	if (!log_has_field)
		std::snprintf(b, sizeof b,
					  "  warning: axis %c: the calibration has a magnetic term (%.3g deg/h per uT) but the log has no "
					  "field column: %zu samples compensated without it\n",
					  axisLetter(cal.axis), cal.magnetic->dph_per_uT, c.field_unknown_samples);
	else
		std::snprintf(b, sizeof b,
					  "  warning: axis %c: applied field unknown (empty cells) on %zu samples: compensated without the "
					  "magnetic term there\n",
					  axisLetter(cal.axis), c.field_unknown_samples);
	return b + outside;
}

JsonValue fieldJson(const Calibration& cal, const CompensationCounters& c, bool log_has_field)
{
	if (!cal.magnetic) return JsonValue();
	JsonValue j = JsonValue::object();
	j["dph_per_uT"] = cal.magnetic->dph_per_uT;
	j["field_column"] = log_has_field;
	j["field_unknown_samples"] = static_cast<unsigned long>(c.field_unknown_samples);
	j["field_range_uT"] = JsonValue::array({cal.magnetic->field_min_uT, cal.magnetic->field_max_uT});
	j["field_outside_samples"] = static_cast<unsigned long>(c.field_outside_samples);
	j["field_max_beyond_uT"] = c.max_field_excursion_uT;
	j["warning"] = fieldWarningMessage(fieldWarning(cal, c, log_has_field));
	return j;
}

std::string fieldWarningMessage(const std::string& lines)
{
	const std::string prefix = "  warning: ";
	std::string out;
	for (std::size_t b = 0; b < lines.size();)
	{
		std::size_t e = lines.find('\n', b);
		if (e == std::string::npos) e = lines.size();
		std::string line = lines.substr(b, e - b);
		if (line.rfind(prefix, 0) == 0) line = line.substr(prefix.size());
		if (!line.empty()) out += (out.empty() ? "" : "; ") + line;
		b = e + 1;
	}
	return out;
}
}  // namespace mrpt_fog::app
