/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt_fog_heading/DriveLog.h>

#include "LatitudeMetadata.h"

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

namespace mrpt_fog::heading
{
std::vector<double> absoluteTimes(const FogSeries& s)
{
	std::vector<double> t(s.size());
	for (std::size_t k = 0; k < s.size(); ++k) t[k] = s.epoch_s + s.time_s[k];
	return t;
}

std::optional<double> driveLatitude(const FogSeries& s)
{
	for (const char* key : heading_detail::kLatitudeKeys)
	{
		const std::string v = s.metadataValue(key);
		if (v.empty()) continue;
		if (const auto lat = heading_detail::latitudeFromText(v)) return lat;
		throw std::runtime_error(std::string("metadata ") + key + ": '" + v + "' is not a latitude in [-90, 90] deg");
	}
	return std::nullopt;
}

namespace
{
void shrinkToFit(FogSeries& s)
{
	s.time_s.shrink_to_fit();
	for (auto& r : s.rate_dph) r.shrink_to_fit();
	for (auto& t : s.temp_C) t.shrink_to_fit();
	for (auto* v : {&s.table_rate_dph, &s.field_uT, &s.power}) v->shrink_to_fit();
}
}  // namespace

DriveData readDrive(const std::string& path, const DriveLabels& labels,
					const std::function<void(std::uint64_t, std::uint64_t, std::uint64_t)>& progress,
					const LogReadOptions& options)
{
	const FogLogReader* reading = nullptr;  // for the progress line
	// Read as readFogRawlog() reads, but the other observations are taken in as they come: the
	// odometry and the truth as poses, the ideal FOG as a series.
	DriveData d;
	FogSeriesBuilder ideal(0, false);  // the ideal FOG: its rates alone are used
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
		FogLogReader reader(path, labels.fog, ReadLimits{}, take, options);
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
	d.latitude_deg = driveLatitude(d.fog);
	if (!ideal.empty()) d.fog_ideal = ideal.take();
	// Growth by doubling leaves up to half of each vector unused: give it back.
	shrinkToFit(d.fog);
	if (d.fog_ideal) shrinkToFit(*d.fog_ideal);
	for (auto* v : {&d.odometry.t_s, &d.odometry.x_m, &d.odometry.y_m, &d.odometry.phi_rad}) v->shrink_to_fit();
	d.truth.shrink_to_fit();
	if (d.truth.size() < 2)
		throw NoTruthError(path + ": fewer than 2 CObservationRobotPose with label '" + labels.truth + "'");
	if (d.odometry.t_s.size() < 2)
		throw std::runtime_error(path + ": fewer than 2 CObservationOdometry with label '" + labels.odometry + "'");
	return d;
}

}  // namespace mrpt_fog::heading
