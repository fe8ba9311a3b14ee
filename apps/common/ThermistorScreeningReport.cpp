/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "ThermistorScreeningReport.h"

#include <sstream>

namespace mrpt_fog::app
{
FogSeries screenedForCompensation(const FogSeries& in, bool enabled, ThermistorScreening& screening)
{
	FogSeries out = in;
	screening = ThermistorScreening{};
	if (enabled) screening = screenThermistors(out);
	return out;
}

ThermistorScreening screenInPlace(FogSeries& series, bool enabled)
{
	if (!enabled) return {};
	return screenThermistors(series);
}

std::function<void(double, double*, std::size_t)> StreamScreening::hook()
{
	if (!enabled_) return {};
	return [this](double t, double* temp_C, std::size_t n) {
		if (!health_) health_ = std::make_unique<ThermistorHealth>(n);
		health_->step(t, temp_C);
	};
}

ThermistorScreening StreamScreening::result(const FogRun& run) const
{
	ThermistorScreening out;
	if (!enabled_) return out;
	const auto& th = run.header().thermistors;
	for (std::size_t i = 0; i < th.size(); i++)
	{
		out.names.push_back(th[i].name);
		const ThermistorHealthCounters c = health_ ? health_->counters(i) : ThermistorHealthCounters{};
		out.counters.push_back(c);
		out.rejected_readings += c.out_of_range + c.spike + c.stuck;
	}
	return out;
}

std::string screeningText(const ThermistorScreening& s, bool enabled)
{
	if (!enabled) return "  thermistor screening: off (--no-screening)\n";
	if (s.rejected_readings == 0) return "  thermistor screening: all readings accepted\n";
	std::ostringstream o;
	o << "  thermistor screening: " << s.rejected_readings
	  << " readings rejected (treated as dropouts: the fallback model covers them)\n";
	for (std::size_t i = 0; i < s.names.size(); i++)
	{
		const auto& c = s.counters[i];
		if (c.stuck + c.spike + c.out_of_range == 0) continue;
		o << "    thermistor " << s.names[i] << ": stuck " << c.stuck << " samples (" << c.stuck_events
		  << " events), spike " << c.spike << ", out of range " << c.out_of_range << "\n";
	}
	return o.str();
}

JsonValue screeningJson(const ThermistorScreening& s, bool enabled)
{
	JsonValue j = JsonValue::object();
	j["enabled"] = enabled;
	j["rejected_readings"] = static_cast<unsigned long>(s.rejected_readings);
	JsonValue& th = j["thermistors"];
	th = JsonValue::object();
	for (std::size_t i = 0; i < s.names.size(); i++)
	{
		const auto& c = s.counters[i];
		th[s.names[i]] = JsonValue::object(
			{{"stuck", static_cast<unsigned long>(c.stuck)}, {"stuck_events", static_cast<unsigned long>(c.stuck_events)},
			 {"spike", static_cast<unsigned long>(c.spike)}, {"out_of_range", static_cast<unsigned long>(c.out_of_range)},
			 {"dropout", static_cast<unsigned long>(c.dropout)},
			 {"level_changes", static_cast<unsigned long>(c.level_changes)}});
	}
	return j;
}

}  // namespace mrpt_fog::app
