/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "DriveData.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog_nav/Rotation.h>

#include <algorithm>
#include <stdexcept>

namespace mrpt_fog::drift
{
std::vector<double> absoluteTimes(const FogSeries& s)
{
	std::vector<double> t(s.size());
	for (std::size_t k = 0; k < s.size(); ++k) t[k] = s.epoch_s + s.time_s[k];
	return t;
}

namespace
{
std::optional<double> latitudeFrom(const FogSeries& s)
{
	for (const char* key : {"latitude_deg", "device.latitude_deg"})
	{
		const std::string v = s.metadataValue(key);
		if (v.empty()) continue;
		try
		{
			std::size_t pos = 0;
			const double lat = std::stod(v, &pos);
			if (pos == v.size() && std::abs(lat) <= 90) return lat;
		}
		catch (const std::exception&)
		{
		}
		throw std::runtime_error(std::string("metadata ") + key + ": '" + v + "' is not a latitude in [-90, 90] deg");
	}
	return std::nullopt;
}

void shrinkToFit(FogSeries& s)
{
	s.time_s.shrink_to_fit();
	for (auto& r : s.rate_dph) r.shrink_to_fit();
	for (auto& t : s.temp_C) t.shrink_to_fit();
	for (auto* v : {&s.table_rate_dph, &s.field_uT, &s.power}) v->shrink_to_fit();
}

/** seriesFromObservations() one observation at a time (the same series and layout error), so
 * that a drive's observations need not be kept as MRPT objects (~2 KB each, issue 14). */
class SeriesBuilder
{
   public:
	/** keep_temperatures false: the series has no thermistors (the ideal FOG: its rates alone
	 * are used; the layout is still checked against the first observation's). */
	explicit SeriesBuilder(bool keep_temperatures) : keep_temps_(keep_temperatures) {}
	void add(const CObservationFOG& o)
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
	bool empty() const { return n_ == 0; }
	FogSeries take() { return std::move(s_); }

   private:
	bool keep_temps_ = true;
	std::vector<ThermistorInfo> first_thermistors_;
	FogSeries s_;
	std::size_t n_ = 0;
	bool table_ = false, field_ = false, power_ = false;
};
}  // namespace

DriveData readDrive(const std::string& path, const DriveLabels& labels,
					const std::function<void(std::uint64_t, std::uint64_t, std::uint64_t)>& progress)
{
	const FogLogReader* reading = nullptr;  // for the progress line
	// Read as readFogRawlog() reads, but the other observations are taken in as they come: the
	// odometry and the truth as poses, the ideal FOG as a series.
	DriveData d;
	SeriesBuilder ideal(false);
	const auto take = [&](const mrpt::obs::CObservation::Ptr& o) {
		if (progress && reading) progress(reading->samplesRead(), reading->fileBytesRead(), reading->fileBytes());
		if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o); f && o->sensorLabel == labels.fog_ideal)
			ideal.add(*f);
		else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o);
				 odo && o->sensorLabel == labels.odometry)
		{
			const double t = mrpt::Clock::toDouble(o->timestamp);
			if (!d.odometry.t_s.empty() && !(t > d.odometry.t_s.back()))
				return;  // a repeated timestamp carries no motion; an earlier one is skipped
			d.odometry.t_s.push_back(t);
			d.odometry.x_m.push_back(odo->odometry.x());
			d.odometry.y_m.push_back(odo->odometry.y());
			d.odometry.phi_rad.push_back(odo->odometry.phi());
		}
		else if (auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o);
				 gt && o->sensorLabel == labels.truth)
		{
			nav::TrajectoryPoint p;
			p.t_s = mrpt::Clock::toDouble(o->timestamp);
			if (!d.truth.empty() && !(p.t_s > d.truth.back().t_s)) return;
			const mrpt::poses::CPose3D& m = gt->pose.mean;
			p.x_m = m.x();
			p.y_m = m.y();
			p.z_m = m.z();
			p.yaw_rad = m.yaw();
			p.q_nb = nav::quatFromYawPitchRoll(m.yaw(), m.pitch(), m.roll());
			d.truth.push_back(p);
		}
	};
	{
		FogLogReader reader(path, labels.fog, ReadLimits{}, take);
		reading = &reader;
		d.fog = readAllSamples(reader);
	}
	try
	{
		d.fog.validate();
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": sensor '" + d.fog.sensor_label + "': " + e.what());
	}
	if (d.fog.size() < 2) throw std::runtime_error(path + ": FOG '" + labels.fog + "' has fewer than 2 samples");
	d.latitude_deg = latitudeFrom(d.fog);
	if (!ideal.empty()) d.fog_ideal = ideal.take();
	// Growth by doubling leaves up to half of each vector unused: give it back (issue 14).
	shrinkToFit(d.fog);
	if (d.fog_ideal) shrinkToFit(*d.fog_ideal);
	for (auto* v : {&d.odometry.t_s, &d.odometry.x_m, &d.odometry.y_m, &d.odometry.phi_rad}) v->shrink_to_fit();
	d.truth.shrink_to_fit();
	if (d.odometry.t_s.size() < 2)
		throw std::runtime_error(path + ": fewer than 2 CObservationOdometry with label '" + labels.odometry + "'");
	if (d.truth.size() < 2)
		throw std::runtime_error(path + ": fewer than 2 CObservationRobotPose with label '" + labels.truth + "'");
	return d;
}

}  // namespace mrpt_fog::drift
