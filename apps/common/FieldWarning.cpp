/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "FieldWarning.h"

#include <cstdio>

namespace mrpt_fog::app
{
std::string fieldWarning(const Calibration& cal, const CompensationCounters& c, bool log_has_field)
{
	if (!cal.magnetic || c.field_unknown_samples == 0) return {};
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
	return b;
}

JsonValue fieldJson(const Calibration& cal, const CompensationCounters& c, bool log_has_field)
{
	if (!cal.magnetic) return JsonValue();
	JsonValue j = JsonValue::object();
	j["dph_per_uT"] = cal.magnetic->dph_per_uT;
	j["field_column"] = log_has_field;
	j["field_unknown_samples"] = static_cast<unsigned long>(c.field_unknown_samples);
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
