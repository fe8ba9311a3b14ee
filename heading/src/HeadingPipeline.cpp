/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#include <mrpt/core/Clock.h>
#include <mrpt_fog/obs/GyroPower.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/HeadingPipeline.h>

#include "LatitudeMetadata.h"
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/EarthModel.h>
#include <mrpt_fog_nav/Rotation.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mrpt_fog::heading
{
namespace
{
std::string timeText(double t_s)
{
	char b[64];
	std::snprintf(b, sizeof b, "%.6f", t_s);
	return b;
}

nav::StrapdownOptions strapdownOptions(const PipelineOptions& o)
{
	if (!(std::abs(o.latitude_deg) <= 90))
		throw std::invalid_argument("heading pipeline: the drive's latitude " + std::to_string(o.latitude_deg) +
									" deg is not within [-90, 90] (give it: the Earth rate depends on it)");
	if (!(o.max_odometry_lag_s > 0))
		throw std::invalid_argument("heading pipeline: max_odometry_lag_s must be > 0");
	nav::StrapdownOptions so;
	so.latitude_rad = o.latitude_deg * units::kDegToRad;
	so.use_transport_rate = false;
	so.sampling = o.sampling;
	return so;
}
}  // namespace

std::optional<double> latitudeOf(const FogSeries& s)
{
	for (const char* key : heading_detail::kLatitudeKeys)
	{
		const std::string v = s.metadataValue(key);
		if (v.empty()) continue;
		if (const auto lat = heading_detail::latitudeFromText(v)) return lat;
	}
	return std::nullopt;
}

FogSeries HeadingPipeline::headerOf(const CObservationFOG& o)
{
	FogSeries h;
	h.sensor_label = o.sensorLabel;
	h.epoch_s = std::floor(mrpt::Clock::toDouble(o.timestamp));
	h.has_axis = o.hasAxis;
	h.thermistors = o.thermistors;
	if (o.hasTableRate) h.table_rate_dph.assign(1, NAN);
	if (o.hasField) h.field_uT.assign(1, NAN);
	if (o.hasPower) h.power.assign(1, NAN);
	return h;
}

HeadingPipeline::HeadingPipeline(const FogSeries& header, const PipelineOptions& options, const Calibration* cal)
	: header_(emptySeriesLike(header)), options_(options),
	  att_(strapdownOptions(options), nav::StrapdownAttitude::Mode::VerticalOnly)
{
	header_.epoch_s = header.epoch_s;
	header_.metadata = header.metadata;
	if (!header_.has_axis[2])
		throw std::invalid_argument("FOG '" + header_.sensor_label +
									"' has no z (vertical) axis; the heading pipeline integrates the vertical gyro");
	drive_earth_dph_ = verticalEarthRate_dph(options.latitude_deg);
	if (cal)
	{
		if (cal->axis != GyroAxis::Z) throw std::invalid_argument("heading pipeline: the calibration is not for the z axis");
		cal_ = *cal;
		earth_ = calibrationEarthRate(*cal_, options.latitude_deg, options.earth);
		compensator_ = std::make_unique<Compensator>(*cal_, header_.thermistors);
		if (cal_->warmup) compensator_->notePowerOnFromMetadata(header);
		if (options.screen_thermistors) health_ = std::make_unique<ThermistorHealth>(header_.thermistors.size());
		thermal_sigma_dph_ = thermalModelSigma_dph(*cal_);
		if (options.field_refinement) correction_ = std::make_shared<StandstillCorrection>(options.field);
	}
	temps_.resize(header_.thermistors.size());
}

HeadingPipeline::~HeadingPipeline() = default;

const CompensationCounters* HeadingPipeline::compensationCounters() const
{
	return compensator_ ? &compensator_->counters() : nullptr;
}

std::vector<ThermistorHealthCounters> HeadingPipeline::screeningCounters() const
{
	std::vector<ThermistorHealthCounters> c;
	if (health_)
		for (std::size_t i = 0; i < health_->thermistorCount(); i++) c.push_back(health_->counters(i));
	return c;
}

double HeadingPipeline::heading_rad() const { return aligned_ ? att_.yaw() : std::numeric_limits<double>::quiet_NaN(); }

const RateStep& HeadingPipeline::addFog(const FogSample& x)
{
	return step(header_.epoch_s + x.time_s, x.time_s, x.rate_dph[2], x.temp_C.data(), x.temp_C.size(), x.field_uT,
				x.power);
}

const RateStep& HeadingPipeline::addFog(const CObservationFOG& o)
{
	if (o.thermistors != header_.thermistors || o.hasAxis != header_.has_axis)
		throw std::runtime_error("FOG observation of sensor '" + o.sensorLabel + "' at t = " +
								 timeText(mrpt::Clock::toDouble(o.timestamp)) +
								 " s has another layout (thermistors or axes) than the pipeline's");
	const double t = mrpt::Clock::toDouble(o.timestamp);
	for (std::size_t i = 0; i < temps_.size(); i++) temps_[i] = o.temperature_C(i);
	const double power = o.hasPower ? (o.powerOn ? 1.0 : 0.0) : NAN;
	const double rate = o.hasPower && !o.powerOn ? NAN : o.rate_dph[2];
	return step(t, t - header_.epoch_s, rate, temps_.data(), temps_.size(), o.hasField ? o.field_uT : NAN, power);
}

const RateStep& HeadingPipeline::addFog(const mrpt::obs::CObservationIMU& imu, const mrpt::obs::CObservationRawDAQ* daq)
{
	const double t = mrpt::Clock::toDouble(imu.timestamp);
	std::vector<double> temps(header_.thermistors.size(), NAN);
	if (daq)
		for (std::size_t i = 0; i < temps.size() && i < daq->AIN_double.size(); i++) temps[i] = daq->AIN_double[i];
	const bool has_rate = imu.has(mrpt::obs::IMU_WZ);
	const double rate = has_rate ? imu.get(mrpt::obs::IMU_WZ) * units::kRadPerSecToDegPerHour : NAN;
	// the stock form leaves the rate absent while the gyro is off
	return step(t, t - header_.epoch_s, rate, temps.data(), temps.size(), NAN, has_rate ? NAN : 0.0);
}

const RateStep& HeadingPipeline::step(double t, double time_s, double raw, const double* temp_C, std::size_t n_temp,
									  double field_uT, double power)
{
	if (finished_) throw std::runtime_error("heading pipeline: a FOG sample after finish()");
	if (any_fog_ && !(t > last_fog_t_))
		throw std::runtime_error("FOG sample at t = " + timeText(t) + " s: " +
								 (t == last_fog_t_ ? "duplicates the previous sample's time" : "goes backwards") +
								 "; times must be strictly increasing");
	if (n_temp != header_.thermistors.size())
		throw std::runtime_error("FOG sample at t = " + timeText(t) + " s has " + std::to_string(n_temp) +
								 " temperatures, the header " + std::to_string(header_.thermistors.size()));
	const bool off = isGyroOff(power);
	const bool turn_on = isTurnOn(prev_power_, power);
	prev_power_ = power;
	if (!off && !std::isfinite(raw))
		throw std::runtime_error("FOG sample at t = " + timeText(t) +
								 " s: the rate is not finite while the gyro is on (a missing rate is allowed only "
								 "where power is 0)");
	any_fog_ = true;
	last_fog_t_ = t;
	counters_.fog_samples++;
	RateStep s;
	s.t_s = t;
	s.raw_dph = off ? NAN : raw;
	s.gyro_on = !off;
	s.turn_on = turn_on;
	s.compensated_dph = raw;
	if (compensator_)
	{
		std::copy(temp_C, temp_C + n_temp, temps_.begin());
		if (health_) health_->step(time_s, temps_.data());
		if (cal_->warmup && turn_on) compensator_->notePowerOn(time_s);
		if (compensator_->readsField()) compensator_->noteField(field_uT);
		const Compensator::Output out = compensator_->step(time_s, raw, temps_.data());
		s.compensated_dph = out.compensated_dph;
		s.compensation_flags = out.flags;
		const FieldOffset* fo = options_.field_offset ? &*options_.field_offset : nullptr;
		if (fo) s.compensated_dph -= fo->offsetAt_dph(t);
		// the prior's uncertainty: the thermal model's, and the field offset's at the drive's start
		if (counters_.fog_samples == 1) sigma_dph_ = fo ? std::hypot(thermal_sigma_dph_, fo->sigmaAt_dph(t)) : thermal_sigma_dph_;
	}
	s.corrected_dph = s.compensated_dph;
	if (correction_)
	{
		RateCorrectionInput in;
		in.t_s = t;
		in.raw_dph = s.raw_dph;
		in.compensated_dph = s.compensated_dph;
		in.compensation_sigma_dph = sigma_dph_;
		in.still_reading_dph = drive_earth_dph_ - earth_.add_back_dph;
		in.compensation_flags = s.compensation_flags;
		in.gyro_on = s.gyro_on;
		in.turn_on = turn_on;
		in.odometry = last_odo_ ? &*last_odo_ : nullptr;
		s.corrected_dph = correction_->correct(in);
	}
	s.integrated_dph = s.corrected_dph + earth_.add_back_dph;
	const double w = s.integrated_dph * units::kDegPerHourToRadPerSec;
	s.yaw_rate_rad_s = w - drive_earth_dph_ * units::kDegPerHourToRadPerSec;
	if (off)
	{
		counters_.gyro_off_samples++;
		if (!gyro_off_)
		{
			gyro_off_ = true;
			resolve();  // the poses past the last powered sample take the wheels' heading
		}
	}
	else
	{
		if (turn_on) counters_.turn_ons++;
		if (aligned_ && gyro_off_)
		{
			// turn-on: the heading goes on from the last pose's (the wheels' through the stretch)
			const double yaw = last_pose_ ? last_pose_->heading_rad : att_.yaw();
			att_.initialize(t, nav::quatFromYawPitchRoll(yaw, 0, 0));
			track_.clear();
			track_.push_back({t, att_.attitude()});
			t0_ = t;
			restarted_ = true;
		}
		gyro_off_ = false;
		if (aligned_ && !(t < t0_ || (t == t0_ && options_.sampling == nav::RateSampling::IntervalAverage)))
		{
			if (!std::isfinite(w))
				throw std::runtime_error("FOG sample at t = " + timeText(t) +
										 " s: the corrected rate is not finite (compensation or correction)");
			att_.updateRateZ(t, w);
			if (t > track_.back().t_s) track_.push_back({t, att_.attitude()});
			s.integrated = true;
			counters_.integrated_samples++;
		}
		resolve();
	}
	s.heading_rad = heading_rad();
	step_ = s;
	return step_;
}

void HeadingPipeline::addOdometry(const mrpt::obs::CObservationOdometry& odo)
{
	addOdometry(mrpt::Clock::toDouble(odo.timestamp), odo.odometry.x(), odo.odometry.y(), odo.odometry.phi());
}

void HeadingPipeline::addOdometry(double t, double x, double y, double phi)
{
	if (!std::isfinite(t) || !std::isfinite(x) || !std::isfinite(y) || !std::isfinite(phi))
		throw std::runtime_error("odometry at t = " + timeText(t) + " s: a non-finite time or pose");
	if (last_odo_ && !(t > last_odo_->t_s))
	{
		counters_.odometry_skipped++;
		return;
	}
	WheelOdometry w;
	w.t_s = t, w.x_m = x, w.y_m = y, w.phi_rad = phi;
	if (last_odo_)
	{
		const nav::OdometryIncrement inc =
			nav::odometryIncrement2D(t, last_odo_->x_m, last_odo_->y_m, last_odo_->phi_rad, x, y, phi);
		w.distance_m = inc.distance_m;
		w.dphi_rad = nav::wrapToPi(phi - last_odo_->phi_rad);
		w.dt_s = t - last_odo_->t_s;
	}
	last_odo_ = w;
	counters_.odometry_samples++;
	if (correction_) correction_->noteOdometry(w);
	if (!aligned_ && options_.alignment == Alignment::AtFirstOdometry) align(t, phi, x, y);
	if (!aligned_ || t < t0_) return;  // before the alignment: no pose
	pending_.push_back(w);
	resolve();
}

void HeadingPipeline::realign(double t, double yaw, double x, double y)
{
	if (!aligned_) return align(t, yaw, x, y);
	if (any_fog_ && t < last_fog_t_)
		throw std::runtime_error("heading pipeline: a new alignment at t = " + timeText(t) +
								 " s, before the last FOG sample's time " + timeText(last_fog_t_));
	const bool finished = finished_;
	finished_ = true;  // the poses still waiting: final, as finish() makes them
	resolve();
	finished_ = finished;
	last_pose_.reset();
	gyro_off_ = restarted_ = false;  // this alignment replaces the turn-on rule
	aligned_ = false;
	align(t, yaw, x, y);
}

void HeadingPipeline::align(double t, double yaw, double x, double y)
{
	if (aligned_) throw std::runtime_error("heading pipeline: already aligned");
	if (!std::isfinite(t) || !std::isfinite(yaw) || !std::isfinite(x) || !std::isfinite(y))
		throw std::invalid_argument("heading pipeline: a non-finite alignment");
	att_.initialize(t, nav::quatFromYawPitchRoll(yaw, 0, 0));
	track_.clear();
	track_.push_back({t, att_.attitude()});
	t0_ = t;
	start_x_m_ = x, start_y_m_ = y, start_given_ = true;
	aligned_ = true;
}

double HeadingPipeline::yawAt(double t) const
{
	if (track_.size() == 1) return nav::yawOf(track_.front().q);
	auto it = std::upper_bound(track_.begin(), track_.end(), t, [](double v, const Att& a) { return v < a.t_s; });
	const std::size_t i1 = it == track_.end() ? track_.size() - 1 : static_cast<std::size_t>(it - track_.begin());
	const std::size_t i0 = i1 - 1;
	const double f = (t - track_[i0].t_s) / (track_[i1].t_s - track_[i0].t_s);
	return nav::yawOf(track_[i0].q.slerp(f, track_[i1].q));
}

void HeadingPipeline::emit(const WheelOdometry& w, double yaw, HeadingSource source)
{
	DeadReckonedPose p;
	p.wheel = w;
	p.source = source;
	if (!last_pose_)
	{
		p.t_s = w.t_s;
		p.x_m = start_given_ ? start_x_m_ : w.x_m;
		p.y_m = start_given_ ? start_y_m_ : w.y_m;
		p.heading_rad = nav::wrapToPi(yaw);
	}
	else
	{
		nav::TrajectoryPoint last;
		last.t_s = last_pose_->t_s;
		last.x_m = last_pose_->x_m;
		last.y_m = last_pose_->y_m;
		last.yaw_rad = last_pose_->heading_rad;
		const nav::TrajectoryPoint next = nav::deadReckonStep2D(last, {w.t_s, w.distance_m}, yaw);
		p.t_s = next.t_s;
		p.x_m = next.x_m;
		p.y_m = next.y_m;
		p.heading_rad = nav::wrapToPi(yaw);
	}
	counters_.poses++;
	if (source == HeadingSource::Wheels) counters_.wheel_poses++;
	else restarted_ = false;
	last_pose_ = p;
	ready_.push_back(p);
}

void HeadingPipeline::resolve()
{
	if (!aligned_) return;
	while (!pending_.empty())
	{
		const WheelOdometry w = pending_.front();
		const double wheel_yaw = last_pose_ ? last_pose_->heading_rad + w.dphi_rad : yawAt(t0_);
		if (w.t_s < track_.front().t_s)
		{
			if (!restarted_ && last_pose_)
				throw std::runtime_error("odometry at t = " + timeText(w.t_s) + " s arrives more than " +
										 std::to_string(options_.max_odometry_lag_s) +
										 " s after the FOG samples past its time");
			emit(w, wheel_yaw, HeadingSource::Wheels);  // inside the gyro-off stretch before a turn-on
		}
		else if (w.t_s <= track_.back().t_s && (track_.back().t_s > w.t_s || gyro_off_ || finished_))
			emit(w, yawAt(w.t_s), HeadingSource::Gyro);
		else if (gyro_off_ || finished_)
			emit(w, wheel_yaw, HeadingSource::Wheels);
		else
			break;  // the heading at its time is not known yet
		pending_.pop_front();
	}
	prune();
}

void HeadingPipeline::prune()
{
	if (track_.empty()) return;
	// keep the attitudes around the oldest time still needed: the oldest pending pose's, else the
	// last pose's (an odometry sample cannot come earlier), and never more than the lag allows
	const double need = !pending_.empty() ? pending_.front().t_s : (last_pose_ ? last_pose_->t_s : track_.back().t_s);
	const double oldest = std::max(need, track_.back().t_s - options_.max_odometry_lag_s);
	while (track_.size() > 2 && track_[1].t_s <= oldest) track_.pop_front();
}

bool HeadingPipeline::popPose(DeadReckonedPose& p)
{
	if (ready_.empty()) return false;
	p = ready_.front();
	ready_.pop_front();
	return true;
}

void HeadingPipeline::finish()
{
	finished_ = true;
	if (aligned_) resolve();
}

}  // namespace mrpt_fog::heading
