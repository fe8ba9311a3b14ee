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
	FogSeriesBuilder b(obs.size());
	for (const auto& o : obs) b.add(*o);
	return b.take();
}

void FogSeriesBuilder::add(const CObservationFOG& o)
{
	if (n_ == 0)
	{
		s_.sensor_label = o.sensorLabel;
		first_thermistors_ = o.thermistors;
		if (keep_temps_) s_.thermistors = o.thermistors;
		s_.has_axis = o.hasAxis;
		s_.epoch_s = std::floor(mrpt::Clock::toDouble(o.timestamp));
		s_.temp_C.assign(s_.thermistors.size(), {});
		table_ = o.hasTableRate;
		field_ = o.hasField;
		power_ = o.hasPower;
		s_.time_s.reserve(expected_);
		for (int a = 0; a < 3; a++)
			if (s_.has_axis[a]) s_.rate_dph[a].reserve(expected_);
		for (auto& c : s_.temp_C) c.reserve(expected_);
	}
	else if (o.thermistors != first_thermistors_ || o.hasAxis != s_.has_axis || o.hasTableRate != table_ ||
			 o.hasField != field_ || o.hasPower != power_)
		throw std::invalid_argument("FOG observation " + std::to_string(n_) + " (sensor '" + o.sensorLabel +
									"') has a different layout than the first one");
	s_.time_s.push_back(mrpt::Clock::toDouble(o.timestamp) - s_.epoch_s);
	for (int a = 0; a < 3; a++)
		if (s_.has_axis[a]) s_.rate_dph[a].push_back(o.rate_dph[a]);
	for (std::size_t i = 0; i < s_.thermistors.size(); i++) s_.temp_C[i].push_back(o.temperature_C(i));
	if (table_) s_.table_rate_dph.push_back(o.tableRate_dph);
	if (field_) s_.field_uT.push_back(o.field_uT);
	if (power_) s_.power.push_back(o.powerOn ? 1.0 : 0.0);
	n_++;
}

}  // namespace mrpt_fog
