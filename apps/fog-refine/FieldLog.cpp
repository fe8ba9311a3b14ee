/* fog-refine: a calibration that learns its bias offset and aging from field logs. */
#include "FieldLog.h"

#include "PowerCycles.h"

#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/ThermistorHealth.h>
#include <mrpt_fog/obs/Units.h>

#include <Eigen/Dense>

#include <cmath>
#include <deque>
#include <stdexcept>

namespace mrpt_fog::refine
{
namespace
{
constexpr double kSecondsPerDay = 86400.0;

std::optional<double> metadataLatitude(const FogSeries& s)
{
	for (const char* key : {"latitude_deg", "device.latitude_deg"})
	{
		const std::string v = s.metadataValue(key);
		if (v.empty()) continue;
		std::size_t pos = 0;
		double lat = NAN;
		try
		{
			lat = std::stod(v, &pos);
		}
		catch (const std::exception&)
		{
		}
		if (pos == v.size() && std::abs(lat) <= 90) return lat;
		throw std::runtime_error(std::string("metadata ") + key + ": '" + v + "' is not a latitude in [-90, 90] deg");
	}
	return std::nullopt;
}
}  // namespace

FieldLogOffset measureFieldLog(const std::string& path, const Calibration& zcal, const std::optional<FieldOffset>& previous,
							   const FieldLogSettings& st)
{
	FieldLogOffset out;
	out.path = path;
	std::unique_ptr<nav::FieldBiasRefiner> refiner;
	std::deque<int> pending;  // one entry per gyro sample not yet returned by the refiner
	const auto drain = [&] {
		nav::RefinedRate x;
		while (refiner && refiner->next(x)) pending.pop_front();
	};
	FogLogReader reader(path, st.fog_label, ReadLimits{}, [&](const mrpt::obs::CObservation::Ptr& o) {
		auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o);
		if (!odo || o->sensorLabel != st.odometry_label || !refiner) return;
		refiner->addOdometry(mrpt::Clock::toDouble(o->timestamp), odo->odometry.x(), odo->odometry.y(), odo->odometry.phi());
		out.odometry++;
		drain();
	});
	const FogSeries& h = reader.header();
	if (!h.has_axis[2]) throw std::runtime_error(path + ": FOG '" + h.sensor_label + "' has no z (vertical) axis");
	const std::optional<double> lat = st.latitude_deg ? st.latitude_deg : metadataLatitude(h);
	if (!lat) throw std::runtime_error(path + ": no latitude_deg in the metadata (give --latitude-deg)");
	// the Earth rate the calibration's bias holds (removed by the compensator): added back
	const double cal_lat = std::isfinite(zcal.latitude_deg) ? zcal.latitude_deg : *lat;
	const double cal_earth_dph = zcal.earth_rate == EarthRateHandling::InBias
									 ? units::kEarthRate_dph * std::sin(cal_lat * units::kDegToRad)
									 : 0.0;
	Compensator comp(zcal, h.thermistors);
	if (zcal.warmup) comp.notePowerOnFromMetadata(h);
	ThermistorHealth health(h.thermistors.size());
	const bool has_power = reader.hasPower();
	FogSample x;
	std::vector<double> temps;
	double prev_power = 1.0;
	bool prev_on = true;
	nav::FieldRefinementOptions o;
	o.standstill = st.standstill;
	o.noise = st.noise;
	o.min_still_s = st.min_still_s;
	o.guard_s = st.guard_s;
	o.expected_rate_dph = units::kEarthRate_dph * std::sin(*lat * units::kDegToRad);
	const double held = zcal.held_out.stability_dph;
	const double thermal = std::isfinite(held) && held > 0 ? held : 0.0;
	for (std::size_t k = 0; reader.next(x); k++)
	{
		const double t = h.epoch_s + x.time_s;
		if (k == 0)
		{
			out.t_unix_s = t;
			out.applied_dph = previous ? previous->offsetAt_dph(t) : 0.0;
			o.prior_sigma_dph = std::hypot(thermal, st.turn_on_repeatability_dph);
			if (previous) o.prior_sigma_dph = std::hypot(o.prior_sigma_dph, previous->sigmaAt_dph(t));
			refiner = std::make_unique<nav::FieldBiasRefiner>(o, t);
		}
		temps = x.temp_C;
		health.step(x.time_s, temps.data());
		const double power = has_power ? x.power : NAN;
		if (zcal.warmup && app::isTurnOn(prev_power, power)) comp.notePowerOn(x.time_s);
		prev_power = power;
		if (comp.readsField()) comp.noteField(x.field_uT);
		const double r = comp.step(x.time_s, x.rate_dph[2], temps.data()).compensated_dph;
		const bool on = !has_power || x.power != 0.0;
		const double v = r + cal_earth_dph - (previous ? previous->offsetAt_dph(t) : 0.0);
		pending.push_back(0);
		refiner->addRate(t, on ? v : NAN, k > 0 && on && !prev_on);
		prev_on = on;
		out.samples++;
		drain();
	}
	if (!refiner) throw std::runtime_error(path + ": the FOG has no samples");
	refiner->finish();
	drain();
	if (!pending.empty()) throw std::runtime_error(path + ": FOG times not increasing");
	out.updates = refiner->updates();
	out.short_standstills = refiner->shortStandstills();
	out.measured = !out.updates.empty();
	if (refiner->restarts())
		out.note = "the gyro was powered on again within the log: only the last turn-on's standstills are used";
	if (!out.measured)
		out.note = out.odometry < 2 ? "no odometry (label '" + st.odometry_label + "'): no standstill can be told"
									: "no standstill long enough to beat the prior: nothing learned";
	out.offset_dph = out.applied_dph + refiner->filter().offset_dph();
	out.sigma_dph = refiner->filter().offset_sigma_dph();
	return out;
}

FieldOffset combineFieldLogs(const std::vector<FieldLogOffset>& logs, double repeatability_dph,
							 const std::optional<FieldOffset>& previous, double min_span_days)
{
	std::vector<const FieldLogOffset*> used;
	for (const auto& l : logs)
		if (l.measured) used.push_back(&l);
	if (used.empty()) throw std::invalid_argument("no log has a standstill update: the calibration cannot be refined");
	FieldOffset f;
	double t_ref = used.front()->t_unix_s, t_min = t_ref;
	for (const auto* l : used) t_ref = std::max(t_ref, l->t_unix_s), t_min = std::min(t_min, l->t_unix_s);
	f.reference_unix_s = t_ref;
	const bool trend = used.size() >= 2 && (t_ref - t_min) / kSecondsPerDay >= min_span_days;
	// weighted least squares of offset = a + b (t - t_ref) / day, weights 1 / (sigma^2 + rep^2)
	Eigen::MatrixXd A(used.size(), trend ? 2 : 1);
	Eigen::VectorXd y(used.size()), w(used.size());
	for (std::size_t i = 0; i < used.size(); i++)
	{
		A(i, 0) = 1.0;
		if (trend) A(i, 1) = (used[i]->t_unix_s - t_ref) / kSecondsPerDay;
		y(i) = used[i]->offset_dph;
		w(i) = 1.0 / (used[i]->sigma_dph * used[i]->sigma_dph + repeatability_dph * repeatability_dph);
	}
	const Eigen::MatrixXd N = A.transpose() * w.asDiagonal() * A;
	const Eigen::MatrixXd cov = N.inverse();
	const Eigen::VectorXd x = cov * (A.transpose() * w.asDiagonal() * y);
	f.offset_dph = x(0);
	f.sigma_dph = std::sqrt(cov(0, 0));
	if (trend)
	{
		f.aging_dph_per_day = x(1);
		f.aging_sigma_dph_per_day = std::sqrt(cov(1, 1));
	}
	else if (previous)
	{
		f.aging_dph_per_day = previous->aging_dph_per_day;
		f.aging_sigma_dph_per_day = previous->aging_sigma_dph_per_day;
	}
	f.revision = previous ? previous->revision + 1 : 1;
	for (const auto* l : used) f.logs.push_back(l->path);
	return f;
}

}  // namespace mrpt_fog::refine
