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
	std::string w = fieldWarning(cal, c, log_has_field);
	if (!w.empty()) w = w.substr(11, w.size() - 12);  // without "  warning: " and the newline
	j["warning"] = w;
	return j;
}
}  // namespace mrpt_fog::app
