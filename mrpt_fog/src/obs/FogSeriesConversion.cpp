/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/system/datetime.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog
{
CObservationFOG::Ptr observationFromSeries(const FogSeries& s, std::size_t k)
{
	auto o = CObservationFOG::Create();
	o->sensorLabel = s.sensor_label;
	o->timestamp = mrpt::Clock::fromDouble(s.epoch_s + s.time_s.at(k));
	for (int a = 0; a < 3; a++)
		if (s.has_axis[a]) o->setRate_dph(static_cast<GyroAxis>(a), s.rate_dph[a].at(k));
		else o->hasAxis[a] = false;
	for (std::size_t i = 0; i < s.thermistors.size(); i++) o->addThermistor(s.thermistors[i], s.temp_C[i].at(k));
	if (!s.table_rate_dph.empty())
	{
		o->hasTableRate = true;
		o->tableRate_dph = s.table_rate_dph[k];
	}
	if (!s.field_uT.empty())
	{
		o->hasField = true;
		o->field_uT = s.field_uT[k];
	}
	if (!s.power.empty())
	{
		o->hasPower = true;
		o->powerOn = s.power[k] != 0.0;
	}
	return o;
}

std::vector<CObservationFOG::Ptr> observationsFromSeries(const FogSeries& s)
{
	s.validate();
	std::vector<CObservationFOG::Ptr> out;
	out.reserve(s.size());
	for (std::size_t k = 0; k < s.size(); k++) out.push_back(observationFromSeries(s, k));
	return out;
}

FogSeries seriesFromObservations(const std::vector<CObservationFOG::Ptr>& obs)
{
	FogSeries s;
	if (obs.empty()) return s;
	const auto& first = *obs.front();
	s.sensor_label = first.sensorLabel;
	s.thermistors = first.thermistors;
	s.has_axis = first.hasAxis;
	s.epoch_s = std::floor(mrpt::Clock::toDouble(first.timestamp));
	const std::size_t n = obs.size();
	s.time_s.reserve(n);
	for (int a = 0; a < 3; a++)
		if (s.has_axis[a]) s.rate_dph[a].reserve(n);
	s.temp_C.assign(s.thermistors.size(), {});
	for (auto& c : s.temp_C) c.reserve(n);
	for (std::size_t k = 0; k < n; k++)
	{
		const auto& o = *obs[k];
		if (o.thermistors != s.thermistors || o.hasAxis != s.has_axis || o.hasTableRate != first.hasTableRate ||
			o.hasField != first.hasField || o.hasPower != first.hasPower)
			throw std::invalid_argument("FOG observation " + std::to_string(k) + " (sensor '" + o.sensorLabel +
										"') has a different layout than the first one");
		s.time_s.push_back(mrpt::Clock::toDouble(o.timestamp) - s.epoch_s);
		for (int a = 0; a < 3; a++)
			if (s.has_axis[a]) s.rate_dph[a].push_back(o.rate_dph[a]);
		for (std::size_t i = 0; i < s.thermistors.size(); i++) s.temp_C[i].push_back(o.temperature_C(i));
		if (first.hasTableRate) s.table_rate_dph.push_back(o.tableRate_dph);
		if (first.hasField) s.field_uT.push_back(o.field_uT);
		if (first.hasPower) s.power.push_back(o.powerOn ? 1.0 : 0.0);
	}
	return s;
}

}  // namespace mrpt_fog
