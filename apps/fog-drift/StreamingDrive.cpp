/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "StreamingDrive.h"

#include "GyroOff.h"
#include "StreamingFigures.h"

#include "PowerCycles.h"
#include "Progress.h"
#include "FieldWarning.h"
#include "RangeWarning.h"
#include "ThermistorScreeningReport.h"

#include <mrpt/core/Clock.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/ThermistorHealth.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/EarthModel.h>
#include <mrpt_fog_nav/Rotation.h>
#include <mrpt_fog_nav/StrapdownAttitude.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <deque>
#include <limits>
#include <memory>
#include <stdexcept>
#include <tuple>

namespace mrpt_fog::drift
{
namespace
{
using mrpt_fog::units::kNaN;

/** First and last value of a stream and its length. */
struct Ends
{
	double first = kNaN, last = kNaN;
	std::size_t n = 0;
	void add(double t)
	{
		if (n == 0) first = t;
		last = t;
		n++;
	}
};

/** A truth pose as readDrive() stores it. */
nav::TrajectoryPoint truthPoint(const mrpt::obs::CObservationRobotPose& gt)
{
	nav::TrajectoryPoint p;
	p.t_s = mrpt::Clock::toDouble(gt.timestamp);
	const mrpt::poses::CPose3D& m = gt.pose.mean;
	p.x_m = m.x();
	p.y_m = m.y();
	p.z_m = m.z();
	p.yaw_rad = m.yaw();
	p.q_nb = nav::quatFromYawPitchRoll(m.yaw(), m.pitch(), m.roll());
	return p;
}

/** What pass 1 found. */
struct DriveScan
{
	FogSeries header;  //!< label, epoch, axes, metadata, thermistors; no samples
	Ends fog, ideal, odometry, truth;
	bool ideal_has_z = true;
	std::string ideal_label;
	double distance_m = 0;
	nav::DriveSegments segments;
	std::vector<TurnSpan> turns;
	std::vector<PoweredSpan> powered;  //!< the FOG's powered spans
	std::vector<GyroOffStretch> gyro_off;  //!< and its gyro-off stretches (GyroOff.h)
};

/** A queue with global indices: the samples not yet needed by no one. */
template <class T>
struct IndexedQueue
{
	std::deque<T> q;
	std::size_t base = 0;  //!< global index of q.front()
	bool done = false;  //!< the stream has ended
	std::size_t end() const { return base + q.size(); }
	const T& at(std::size_t i) const { return q[i - base]; }
	void dropBefore(std::size_t i)
	{
		while (base < i && !q.empty()) q.pop_front(), base++;
	}
};

struct OdoPose
{
	double t_s, x_m, y_m, phi_rad;
};

/** One gyro variant: attitude -> dead reckoning -> errors at the truth times -> figures. */
class VariantStream
{
   public:
	/** windows: the time spans navigated, each aligned from the truth at its start (one
	 * without gyro-off stretches; GyroOff.h); skip_short: a window with fewer than 2 odometry
	 * samples is skipped (else an error). */
	VariantStream(std::string name, std::vector<std::pair<double, double>> windows, bool skip_short,
				  const HeadingOptions& hopt, const DriveScan& scan)
		: name_(std::move(name)), windows_(std::move(windows)), skip_short_(skip_short), hopt_(hopt),
		  acc_(scan.segments, scan.turns)
	{
		nav::StrapdownOptions so;
		so.latitude_rad = hopt.latitude_deg * units::kDegToRad;
		so.use_transport_rate = false;
		so.sampling = hopt.sampling;
		att_ = std::make_unique<nav::StrapdownAttitude>(so, nav::StrapdownAttitude::Mode::VerticalOnly);
		t0_ = windows_.front().first, t_end_ = windows_.front().second;
	}

	/** Sample k of the variant's gyro: absolute time [s], vertical rate [deg/h]. */
	void addGyro(double t, double rate_dph, std::size_t k)
	{
		// a sample before the window being navigated (or, once it has stopped, before the next one) is
		// never integrated: not held (a long gyro-off stretch does not fill the queue)
		if (t < t0_) return;
		if (gyro_stopped_ && (window_ + 1 >= windows_.size() || t < windows_[window_ + 1].first)) return;
		gyro_.push_back({t, rate_dph, k});
	}
	void gyroDone() { gyro_done_ = true; }

	/** Advances as far as the data allow. */
	void pump(const IndexedQueue<nav::TrajectoryPoint>& truth, const IndexedQueue<OdoPose>& odo)
	{
		for (;;)
		{
			if (!initialised_)
			{
				if (!truthReady(truth, t0_)) return;
				const nav::TrajectoryPoint start = interpolateTruth(truth, t0_);
				att_->initialize(t0_, nav::quatFromYawPitchRoll(start.yaw_rad, 0, 0));
				track_.push_back({t0_, att_->attitude()});
				initialised_ = true;
			}
			integrate();
			deadReckon(truth, odo);
			compare(truth);
			if (!compared_all_ || window_ + 1 >= windows_.size()) return;
			nextWindow();
		}
	}

	bool done() const { return compared_all_ && window_ + 1 >= windows_.size(); }
	/** Windows navigated (at least 2 odometry samples). */
	std::size_t windowsNavigated() const { return navigated_; }
	/** Truth and odometry indices this variant still needs (its lower bounds). Before the
	 * dead reckoning of a later window starts: the last truth pose at or before its start. */
	std::size_t truthNeeded(const IndexedQueue<nav::TrajectoryPoint>& truth) const
	{
		if (initialised_ && dr_started_) return next_truth_;
		if (window_ == 0) return 0;
		std::size_t i = truth.base;
		while (i + 1 < truth.end() && truth.at(i + 1).t_s <= t0_) i++;
		return i;
	}
	std::size_t odoNeeded(const IndexedQueue<OdoPose>& odo) const
	{
		if (window_ > 0 && !dr_started_)  // a later window starts at the first odometry at or after its start
		{
			std::size_t i = std::max(next_odo_, odo.base);
			while (i < odo.end() && odo.at(i).t_s < t0_) i++;
			return i;
		}
		return next_odo_ > 0 ? next_odo_ - 1 : 0;
	}

	void finish(double distance_m, nav::DriftSeries& s, nav::HeadingFigures& f)
	{
		if (navigated_ == 0)
			throw std::runtime_error("no powered span of the gyro overlaps the odometry and the truth long enough to "
									 "navigate");
		flushWindow();
		acc_.finish(name_, distance_m, s, f);
	}

	/** --odometry-out: this variant's poses and integrated rates into `poses` (t, x, y, yaw) and
	 * `rates` (t, rate [rad/s]), window by window as the in-memory path keeps them: a window
	 * that was navigated and (with gyro-off stretches) compared at a truth pose. */
	void keepTrajectoryIn(RowSpill* poses, RowSpill* rates, double earth_up_rad_s)
	{
		poses_ = poses, rates_ = rates, earth_up_ = earth_up_rad_s;
		win_poses_ = std::make_unique<RowSpill>(4);
		win_rates_ = std::make_unique<RowSpill>(2);
	}

   private:
	struct Att
	{
		double t;
		Eigen::Quaterniond q;
	};

	static bool truthReady(const IndexedQueue<nav::TrajectoryPoint>& truth, double t)
	{
		return truth.done || (!truth.q.empty() && truth.q.back().t_s > t);
	}

	/** nav::interpolate(truth, t) on the truth still held (the same bracket). */
	nav::TrajectoryPoint interpolateTruth(const IndexedQueue<nav::TrajectoryPoint>& truth, double t)
	{
		return interpolateIn(truth.q, t);
	}

	/** nav::interpolate on the two points the whole trajectory would bracket t with. */
	template <class Q>
	nav::TrajectoryPoint interpolateIn(const Q& q, double t)
	{
		if (q.empty()) throw std::out_of_range("interpolate(trajectory): empty");
		auto it = std::upper_bound(q.begin(), q.end(), t, [](double v, const nav::TrajectoryPoint& p) { return v < p.t_s; });
		if (q.size() == 1) pair_.assign(1, q.front());
		else
		{
			if (it == q.end()) --it;
			if (it == q.begin()) throw std::out_of_range("interpolate(trajectory): time before the poses held");
			pair_.assign(it - 1, it + 1);
		}
		return nav::interpolate(pair_, t);
	}

	void integrate()
	{
		while (!gyro_.empty())
		{
			const auto [t, rate, k] = gyro_.front();
			gyro_.pop_front();
			if (t < t0_ || (t == t0_ && hopt_.sampling == nav::RateSampling::IntervalAverage)) continue;
			if (t > t_end_)
			{
				gyro_stopped_ = true;
				if (window_ + 1 < windows_.size()) gyro_.push_front({t, rate, k});  // a later window's
				else gyro_.clear();
				break;
			}
			if (!std::isfinite(rate))
				throw std::runtime_error("gyro rate is not finite at sample " + std::to_string(k) + " (t = " +
										 std::to_string(t) +
										 " s; a heading cannot be integrated while the gyro is off)");
			const double w = rate * units::kDegPerHourToRadPerSec;
			att_->updateRateZ(t, w, Eigen::Vector3d::Zero());
			if (t > track_.back().t) track_.push_back({t, att_->attitude()});
			if (win_rates_)
			{
				const double row[2] = {t, w - earth_up_};
				win_rates_->push(row);
			}
		}
	}

	bool trackFinal() const { return gyro_stopped_ || gyro_done_; }

	/** AttitudeTrack::yawAt(t) on the attitudes still held (the same bracket); drops the
	 * attitudes before it. */
	double yawAt(double t)
	{
		std::size_t i1;
		if (track_.size() == 1) return nav::yawOf(track_.front().q);
		auto it = std::upper_bound(track_.begin(), track_.end(), t, [](double v, const Att& a) { return v < a.t; });
		i1 = it == track_.end() ? track_.size() - 1 : static_cast<std::size_t>(it - track_.begin());
		if (i1 == 0) throw std::out_of_range("AttitudeTrack::at: time before the attitudes held");
		const std::size_t i0 = i1 - 1;
		const double f = (t - track_[i0].t) / (track_[i1].t - track_[i0].t);
		const double yaw = nav::yawOf(track_[i0].q.slerp(f, track_[i1].q));
		for (std::size_t k = 0; k < i0; k++) track_.pop_front();
		return yaw;
	}

	/** Whether the attitude at t is final (a later attitude exists, or there will be none). */
	bool attitudeReady(double t) const { return track_.back().t > t || trackFinal(); }

	void deadReckon(const IndexedQueue<nav::TrajectoryPoint>& truth, const IndexedQueue<OdoPose>& odo)
	{
		while (!dr_done_)
		{
			if (next_odo_ < odo.base) next_odo_ = odo.base;  // (never: the queue keeps what is needed)
			if (next_odo_ >= odo.end())
			{
				if (odo.done) finishDeadReckoning();
				return;
			}
			const OdoPose& o = odo.at(next_odo_);
			if (!dr_started_)
			{
				if (o.t_s < t0_)  // lower_bound(t0)
				{
					next_odo_++;
					continue;
				}
				if (!truthReady(truth, o.t_s) || !attitudeReady(o.t_s)) return;
				if (!(o.t_s <= track_.back().t))  // not inside the attitude track
				{
					finishDeadReckoning();
					return;
				}
				const nav::TrajectoryPoint p0 = interpolateTruth(truth, o.t_s);
				last_ = nav::TrajectoryPoint{};
				last_.t_s = o.t_s;
				last_.x_m = p0.x_m;
				last_.y_m = p0.y_m;
				first_pending_ = true;
				dr_started_ = true;
				dr_points_ = 1;
				next_truth_ = truth.base;
				prev_odo_ = o;
				next_odo_++;
				continue;
			}
			if (!attitudeReady(o.t_s)) return;
			if (!(o.t_s <= track_.back().t))
			{
				finishDeadReckoning();
				return;
			}
			const nav::OdometryIncrement inc =
				nav::odometryIncrement2D(o.t_s, prev_odo_.x_m, prev_odo_.y_m, prev_odo_.phi_rad, o.x_m, o.y_m, o.phi_rad);
			if (first_pending_)  // DeadReckoning2D::add's first step: the start's heading
			{
				if (!std::isfinite(inc.t_s) || !std::isfinite(inc.distance_m) || !(inc.t_s > last_.t_s))
					(void)nav::deadReckonStep2D(last_, inc, 0.0);  // throws its message
				last_.yaw_rad = yawAt(last_.t_s);
				last_.q_nb = nav::quatFromYawPitchRoll(last_.yaw_rad, 0, 0);
				traj_.push_back(last_);
				keepPose(last_);
				traj_front_t_ = last_.t_s;
				first_pending_ = false;
			}
			last_ = nav::deadReckonStep2D(last_, inc, yawAt(inc.t_s));
			traj_.push_back(last_);
			keepPose(last_);
			dr_points_++;
			prev_odo_ = o;
			next_odo_++;
		}
	}

	void finishDeadReckoning()
	{
		if (dr_done_) return;
		if (dr_points_ < 2)
		{
			if (!skip_short_) throw std::runtime_error("fewer than 2 odometry samples inside the gyro's time span");
			dr_done_ = compared_all_ = true;  // too short to navigate: nothing compared
			return;
		}
		navigated_++;
		dr_done_ = true;
	}

	/** The next window: navigated afresh from the truth at its start (GyroOff.h). */
	void nextWindow()
	{
		flushWindow();
		window_++;
		t0_ = windows_[window_].first, t_end_ = windows_[window_].second;
		initialised_ = gyro_stopped_ = false;
		dr_started_ = dr_done_ = first_pending_ = compared_all_ = false;
		dr_points_ = 0;
		track_.clear();
		traj_.clear();
	}

	/** computeDriftReport: each truth pose inside the trajectory's span, the trajectory
	 * interpolated there. */
	void compare(const IndexedQueue<nav::TrajectoryPoint>& truth)
	{
		if (!dr_started_ || compared_all_ || traj_.empty()) return;
		while (next_truth_ < truth.end())
		{
			const nav::TrajectoryPoint& gt = truth.at(next_truth_);
			if (gt.t_s < traj_front_t_)
			{
				next_truth_++;
				continue;
			}
			if (!(traj_.back().t_s > gt.t_s))
			{
				if (!dr_done_) return;
				if (gt.t_s > traj_.back().t_s)
				{
					compared_all_ = true;  // the later poses are outside the span too
					return;
				}
			}
			const nav::TrajectoryPoint p = interpolateIn(traj_, gt.t_s);
			// drop the trajectory before the bracket
			while (traj_.size() > 2 && traj_[1].t_s <= gt.t_s) traj_.pop_front();
			const double dpsi_deg = mrpt::RAD2DEG(nav::wrapToPi(p.yaw_rad - gt.yaw_rad));
			const double dpos =
				std::sqrt(std::pow(p.x_m - gt.x_m, 2) + std::pow(p.y_m - gt.y_m, 2) + std::pow(p.z_m - gt.z_m, 2));
			acc_.add(gt.t_s, dpsi_deg, dpos);
			compared_in_window_++;
			if (series_)
			{
				const double row[3] = {gt.t_s, dpsi_deg, dpos};
				series_->push(row);
			}
			next_truth_++;
		}
		if (truth.done && dr_done_) compared_all_ = true;
	}

   public:
	/** Every error as it is compared (t, heading [deg], position [m]) also into `spill` (--csv). */
	void spillSeriesTo(RowSpill* spill) { series_ = spill; }

   private:
	void keepPose(const nav::TrajectoryPoint& p)
	{
		if (!win_poses_) return;
		const double row[4] = {p.t_s, p.x_m, p.y_m, p.yaw_rad};
		win_poses_->push(row);
	}
	/** The window's poses and rates into the kept ones (see keepTrajectoryIn), then afresh. */
	void flushWindow()
	{
		if (!win_poses_) return;
		const bool keep = dr_points_ >= 2 && (!skip_short_ || compared_in_window_ > 0);
		if (keep)
			for (auto [from, to] : {std::pair{win_poses_.get(), poses_}, {win_rates_.get(), rates_}})
			{
				RowSpill::Reader r(*from);
				while (const double* row = r.next()) to->push(row);
			}
		win_poses_ = std::make_unique<RowSpill>(4);
		win_rates_ = std::make_unique<RowSpill>(2);
		compared_in_window_ = 0;
	}

	RowSpill* series_ = nullptr;
	RowSpill *poses_ = nullptr, *rates_ = nullptr;
	std::unique_ptr<RowSpill> win_poses_, win_rates_;
	double earth_up_ = 0;
	std::size_t compared_in_window_ = 0;
	std::string name_;
	std::vector<std::pair<double, double>> windows_;
	bool skip_short_ = false;
	std::size_t window_ = 0, navigated_ = 0;
	double t0_ = 0, t_end_ = 0;
	HeadingOptions hopt_;
	FigureAccumulator acc_;
	std::unique_ptr<nav::StrapdownAttitude> att_;
	std::deque<std::tuple<double, double, std::size_t>> gyro_;
	std::deque<Att> track_;
	std::deque<nav::TrajectoryPoint> traj_;
	nav::Trajectory pair_;
	nav::TrajectoryPoint last_;
	OdoPose prev_odo_{};
	bool initialised_ = false, gyro_stopped_ = false, gyro_done_ = false;
	bool dr_started_ = false, dr_done_ = false, first_pending_ = false, compared_all_ = false;
	std::size_t next_odo_ = 0, next_truth_ = 0, dr_points_ = 0;
	double traj_front_t_ = 0;  //!< the trajectory's first time (traj_ keeps its tail)
};

/** readDrive()'s handling of the other observations (odometry and truth: a repeated or earlier
 * time skipped), for both passes. */
struct OtherObservations
{
	const DriveLabels& labels;
	std::function<void(const CObservationFOG&)> on_ideal;
	std::function<void(const OdoPose&)> on_odometry;
	std::function<void(const nav::TrajectoryPoint&)> on_truth;
	double last_odo_t = kNaN, last_truth_t = kNaN;
	bool any_odo = false, any_truth = false;

	void operator()(const mrpt::obs::CObservation::Ptr& o)
	{
		if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o); f && o->sensorLabel == labels.fog_ideal)
			on_ideal(*f);
		else if (auto odo = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(o);
				 odo && o->sensorLabel == labels.odometry)
		{
			const double t = mrpt::Clock::toDouble(o->timestamp);
			if (any_odo && !(t > last_odo_t)) return;
			any_odo = true, last_odo_t = t;
			on_odometry({t, odo->odometry.x(), odo->odometry.y(), odo->odometry.phi()});
		}
		else if (auto gt = std::dynamic_pointer_cast<mrpt::obs::CObservationRobotPose>(o); gt && o->sensorLabel == labels.truth)
		{
			const double t = mrpt::Clock::toDouble(o->timestamp);
			if (any_truth && !(t > last_truth_t)) return;
			any_truth = true, last_truth_t = t;
			on_truth(truthPoint(*gt));
		}
	}
};

/** FogSeries::validate()'s per-sample checks on one FOG sample. */
void checkFogSample(const FogSeries& h, const FogSample& x, std::size_t k, bool has_power)
{
	for (int a = 0; a < 3; a++)
	{
		if (!h.has_axis[a]) continue;
		const double r = x.rate_dph[a];
		if (!std::isfinite(r) && !(std::isnan(r) && has_power && x.power == 0.0))
			throw std::invalid_argument(std::string("FOG series: non-finite rate_") + "xyz"[a] + "_dph at sample " +
										std::to_string(k) +
										(std::isnan(r) ? " (a missing rate is allowed only where power is 0)" : ""));
	}
	for (std::size_t i = 0; i < x.temp_C.size(); i++)
		if (std::isinf(x.temp_C[i]))
			throw std::invalid_argument("FOG series: infinite temp_" + h.thermistors[i].name + "_C at sample " +
										std::to_string(k));
}

/** The ideal FOG's layout check (FogSeriesBuilder's) and its absolute times. */
struct IdealTimes
{
	std::string label;
	double epoch_s = 0;
	std::size_t n = 0;
	std::vector<ThermistorInfo> th;
	std::array<bool, 3> axes{};
	bool table = false, field = false, power = false;
	/** Absolute time of the observation as absoluteTimes(readDrive(...).fog_ideal) gives it. */
	double add(const CObservationFOG& o)
	{
		if (n == 0)
		{
			label = o.sensorLabel;
			th = o.thermistors;
			axes = o.hasAxis;
			table = o.hasTableRate, field = o.hasField, power = o.hasPower;
			epoch_s = std::floor(mrpt::Clock::toDouble(o.timestamp));
		}
		else if (o.thermistors != th || o.hasAxis != axes || o.hasTableRate != table || o.hasField != field ||
				 o.hasPower != power)
			throw std::invalid_argument("FOG observation " + std::to_string(n) + " (sensor '" + o.sensorLabel +
										"') has a different layout than the first one");
		n++;
		return epoch_s + (mrpt::Clock::toDouble(o.timestamp) - epoch_s);
	}
};

}  // namespace

bool canStream(const DriveSettings& st)
{
	return st.keep_trajectories != KeptTrajectories::All && !st.heading.transport_rate && !st.in_memory;
}

std::optional<DriveEvaluation> evaluateDriveStreaming(const std::string& path, const DriveSettings& st)
{
	const DriveLabels labels = st.labels;
	DriveScan scan;
	// ---- pass 1: ends, path length, segments
	{
		StreamSegmenter seg(st.figures);
		PowerSpanBuilder power;
		IdealTimes ideal;
		nav::TrajectoryPoint prev_truth;
		OtherObservations others{labels, {}, {}, {}};
		others.on_ideal = [&](const CObservationFOG& o) {
			scan.ideal.add(ideal.add(o));
			scan.ideal_has_z = ideal.axes[2];
			scan.ideal_label = ideal.label;
		};
		others.on_odometry = [&](const OdoPose& p) {
			if (!std::isfinite(p.t_s))
				throw std::invalid_argument("odometryFromPoses2D: time not increasing at sample " +
											std::to_string(scan.odometry.n));
			scan.odometry.add(p.t_s);
		};
		others.on_truth = [&](const nav::TrajectoryPoint& p) {
			if (scan.truth.n > 0)
				scan.distance_m += std::sqrt(std::pow(p.x_m - prev_truth.x_m, 2) + std::pow(p.y_m - prev_truth.y_m, 2) +
											 std::pow(p.z_m - prev_truth.z_m, 2));
			prev_truth = p;
			scan.truth.add(p.t_s);
			seg.add(p.t_s, p.yaw_rad);
		};
		app::Progress progress("fog-drift: reading " + path + " (1/2)", st.quiet);
		const FogLogReader* reading = nullptr;
		FogLogReader reader(
			path, labels.fog, ReadLimits{},
			[&](const mrpt::obs::CObservation::Ptr& o) {
				if (reading) progress.update(reading->samplesRead(), reading->fileBytesRead(), reading->fileBytes());
				others(o);
			},
			st.read_options);
		reading = &reader;
		const FogSeries& h = reader.header();
		if (h.has_axis[0] && h.has_axis[1] && h.has_axis[2]) return std::nullopt;  // a triad: evaluateDrive()
		FogSample x;
		try
		{
			if (!h.has_axis[0] && !h.has_axis[1] && !h.has_axis[2])
				throw std::invalid_argument("FOG series: no sensitive axis present");
			const bool has_power = reader.hasPower();
			while (reader.next(x))
			{
				checkFogSample(h, x, scan.fog.n, has_power);
				scan.fog.add(h.epoch_s + x.time_s);
				power.add(h.epoch_s + x.time_s, has_power ? x.power : NAN);
			}
		}
		catch (const FogIoError&)
		{
			throw;
		}
		catch (const std::invalid_argument& e)
		{
			throw FogIoError(path + ": sensor '" + h.sensor_label + "': " + e.what());
		}
		scan.header = h;
		seg.finish(scan.segments, scan.turns);
		power.finish();
		scan.powered = power.powered();
		scan.gyro_off = power.stretches();
		// what a gyro-off stretch touches is not judged (as evaluateDrive: GyroOff.h)
		cutSegmentsAtGyroOff(scan.segments, &scan.turns, scan.gyro_off, st.figures);
	}
	if (scan.fog.n < 2) throw std::runtime_error(path + ": FOG '" + labels.fog + "' has fewer than 2 samples");
	if (scan.powered.empty())
		throw std::runtime_error(path + ": FOG '" + scan.header.sensor_label + "': the gyro is off throughout");

	DriveEvaluation e;
	e.input = path;
	e.drive.latitude_deg = driveLatitude(scan.header);
	if (scan.truth.n < 2)
		throw NoTruthError(path + ": fewer than 2 CObservationRobotPose with label '" + labels.truth + "'");
	if (scan.odometry.n < 2)
		throw std::runtime_error(path + ": fewer than 2 CObservationOdometry with label '" + labels.odometry + "'");
	const HeadingOptions hopt = headingOptionsFor(e, path, st);
	const FogSeries& h = scan.header;

	std::optional<CalibrationSet> cals;
	const Calibration* zcal = nullptr;
	if (!st.cal_path.empty())
	{
		cals = loadCalibrationSet(st.cal_path);
		zcal = cals->forAxis(GyroAxis::Z);
		if (!zcal) throw std::runtime_error(st.cal_path + ": axes: no calibration for axis z (the heading gyro)");
		noteCalibrationEarthRate(e, st, *zcal);
	}
	if (!h.has_axis[2])
		throw std::runtime_error(path + ": FOG '" + h.sensor_label +
								 "' has no z (vertical) axis; fog-drift integrates the vertical gyro");
	if (scan.ideal.n > 0 && !scan.ideal_has_z)
		throw std::runtime_error(path + ": FOG '" + scan.ideal_label +
								 "' has no z (vertical) axis; fog-drift integrates the vertical gyro");

	// ---- pass 2: every variant at once
	const auto overlap = [&](const Ends& g) {
		if (g.n < 2) throw std::runtime_error("gyro series: sizes differ or fewer than 2 samples");
		const double t0 = std::max({g.first, scan.odometry.first, scan.truth.first});
		const double t_end = std::min({g.last, scan.odometry.last, scan.truth.last});
		if (!(t_end > t0)) throw std::runtime_error("the gyro, the odometry and the truth do not overlap in time");
		return std::pair<double, double>(t0, t_end);
	};
	std::vector<std::unique_ptr<VariantStream>> vars;
	std::vector<std::string> names;
	const bool gyro_off = !scan.gyro_off.empty();
	const auto addVariant = [&](const std::string& name, const Ends& g) {
		std::vector<std::pair<double, double>> windows;
		if (!gyro_off) windows.push_back(overlap(g));
		else
		{
			for (const PoweredSpan& span : scan.powered)
				if (const auto w = navigationWindow(span, g.first, g.last, scan.odometry.first, scan.odometry.last,
													scan.truth.first, scan.truth.last))
					windows.push_back(*w);
			if (windows.empty())
				throw std::runtime_error("no powered span of the gyro overlaps the odometry and the truth long enough "
										 "to navigate");
		}
		vars.push_back(std::make_unique<VariantStream>(name, std::move(windows), gyro_off, hopt, scan));
		names.push_back(name);
	};
	addVariant("raw", scan.fog);
	VariantStream* raw = vars.back().get();
	VariantStream* comp_var = nullptr;
	if (zcal)
	{
		addVariant("compensated", scan.fog);
		comp_var = vars.back().get();
	}
	VariantStream* ideal_var = nullptr;
	if (scan.ideal.n > 0)
	{
		addVariant("ideal", scan.ideal);
		ideal_var = vars.back().get();
	}

	// --csv: the per-sample series into temporary files (the report's vectors stay empty)
	if (st.keep_series || st.keep_trajectories == KeptTrajectories::ForOdometry) e.spilled = std::make_shared<SpilledSeries>();
	if (st.keep_series)
		for (auto& v : vars)
		{
			e.spilled->variants.push_back(std::make_unique<RowSpill>(3));
			v->spillSeriesTo(e.spilled->variants.back().get());
		}
	// --odometry-out: the compensated variant's trajectory and rates (raw without a calibration)
	if (st.keep_trajectories == KeptTrajectories::ForOdometry)
	{
		VariantStream* v = comp_var ? comp_var : raw;
		e.spilled->odometry_variant = comp_var ? "compensated" : "raw";
		v->keepTrajectoryIn(&e.spilled->odometry_poses, &e.spilled->odometry_rates,
							nav::earthRateEnu(hopt.latitude_deg * units::kDegToRad).z());
	}
	IndexedQueue<nav::TrajectoryPoint> truth;
	IndexedQueue<OdoPose> odo;
	IdealTimes ideal_times;
	// the compensator, as compensateRun() drives it (screening first: screenedForCompensation)
	std::unique_ptr<Compensator> compensator;
	std::unique_ptr<ThermistorHealth> health;
	const bool screen = st.screen_thermistors;
	double prev_power = 1.0;
	std::vector<double> temps;
	if (zcal)
	{
		try
		{
			compensator = std::make_unique<Compensator>(*zcal, h.thermistors);
			if (zcal->warmup) compensator->notePowerOnFromMetadata(h);
		}
		catch (const std::exception& ex)
		{
			throw std::runtime_error(st.cal_path + ": cannot compensate the drive's FOG: " + ex.what());
		}
		if (screen) health = std::make_unique<ThermistorHealth>(h.thermistors.size());
	}
	// the in-field refinement of the compensated rate (as evaluateDrive: refineInMemory); its
	// output waits for the odometry that covers each sample
	std::unique_ptr<nav::FieldBiasRefiner> refiner;
	struct PendingComp
	{
		std::size_t k;
		double rate_dph;
		bool on;
	};
	std::deque<PendingComp> comp_pending;
	bool prev_on = true;
	if (zcal)
	{
		e.refinement.calibration_offset = loadFieldOffset(st.cal_path);
		if (e.refinement.calibration_offset)
			e.refinement.calibration_offset_at_drive_dph = e.refinement.calibration_offset->offsetAt_dph(scan.fog.first);
	}
	const FieldOffset* field_offset = e.refinement.calibration_offset ? &*e.refinement.calibration_offset : nullptr;
	if (zcal && st.refinement.enabled)
		refiner = std::make_unique<nav::FieldBiasRefiner>(
			refinementOptionsFor(st.refinement, *zcal, e.latitude_deg, scan.fog.first, e.refinement), scan.fog.first);
	const auto drainRefiner = [&] {
		nav::RefinedRate x;
		while (refiner->next(x))
		{
			if (comp_pending.empty()) throw std::logic_error("field refinement: output out of step");
			const PendingComp p = comp_pending.front();
			comp_pending.pop_front();
			comp_var->addGyro(x.t_s, p.on ? x.rate_dph : p.rate_dph, p.k);
		}
	};
	const auto pumpAll = [&] {
		for (auto& v : vars) v->pump(truth, odo);
		std::size_t tn = truth.end(), on = odo.end();
		for (const auto& v : vars)
		{
			tn = std::min(tn, v->truthNeeded(truth));
			on = std::min(on, v->odoNeeded(odo));
		}
		truth.dropBefore(tn);
		odo.dropBefore(on);
	};
	OtherObservations others{labels, {}, {}, {}};
	others.on_ideal = [&](const CObservationFOG& o) {
		const double t = ideal_times.add(o);
		if (ideal_var) ideal_var->addGyro(t, o.rate_dph[2], ideal_times.n - 1);
	};
	others.on_odometry = [&](const OdoPose& p) {
		odo.q.push_back(p);
		if (refiner)
		{
			refiner->addOdometry(p.t_s, p.x_m, p.y_m, p.phi_rad);
			drainRefiner();
		}
	};
	TruthYawAt off_yaw(stretchQueryTimes(scan.gyro_off));
	others.on_truth = [&](const nav::TrajectoryPoint& p) {
		off_yaw.add(p.t_s, p.yaw_rad);
		if (e.spilled)
		{
			const double row[2] = {p.t_s, p.yaw_rad};
			e.spilled->truth.push(row);
		}
		truth.q.push_back(p);
	};
	{
		app::Progress progress("fog-drift: dead reckoning " + path + " (2/2)", st.quiet);
		const FogLogReader* reading = nullptr;
		std::size_t since_pump = 0;
		FogLogReader reader(
			path, labels.fog, ReadLimits{},
			[&](const mrpt::obs::CObservation::Ptr& o) {
				if (reading) progress.update(reading->samplesRead(), reading->fileBytesRead(), reading->fileBytes());
				others(o);
				if (++since_pump >= 64) pumpAll(), since_pump = 0;
			},
			st.read_options);
		reading = &reader;
		const bool has_power = reader.hasPower();
		FogSample x;
		for (std::size_t k = 0; reader.next(x); k++)
		{
			const double t = h.epoch_s + x.time_s;
			raw->addGyro(t, x.rate_dph[2], k);
			if (comp_var)
			{
				temps = x.temp_C;
				if (health) health->step(x.time_s, temps.data());
				const double power = has_power ? x.power : NAN;
				if (zcal->warmup && app::isTurnOn(prev_power, power)) compensator->notePowerOn(x.time_s);
				prev_power = power;
				if (compensator->readsField()) compensator->noteField(x.field_uT);  // NaN when the log has none
				double r;
				try
				{
					r = compensator->step(x.time_s, x.rate_dph[2], temps.data()).compensated_dph;
				}
				catch (const std::exception& ex)
				{
					throw std::runtime_error(st.cal_path + ": cannot compensate the drive's FOG: " + ex.what());
				}
				// the calibration's field offset at this date (as evaluateDrive)
				const double v = field_offset ? r + e.calibration_earth_rate_dph - field_offset->offsetAt_dph(t)
											  : r + e.calibration_earth_rate_dph;
				if (refiner)
				{
					const bool on = !has_power || x.power != 0.0;
					comp_pending.push_back({k, v, on});
					refiner->addRate(t, on ? v : NAN, k > 0 && on && !prev_on);
					prev_on = on;
					drainRefiner();
				}
				else
					comp_var->addGyro(t, v, k);
			}
			if (++since_pump >= 64) pumpAll(), since_pump = 0;
		}
		if (refiner)
		{
			refiner->finish();
			drainRefiner();
			if (!comp_pending.empty()) throw std::runtime_error(path + ": field refinement: FOG samples lost (times not increasing)");
			noteRefinement(*refiner, e.refinement);
		}
		truth.done = odo.done = true;
		for (auto& v : vars) v->gyroDone();
		pumpAll();
	}
	if (comp_var)
	{
		ThermistorScreening screening;
		if (health)
			for (std::size_t i = 0; i < h.thermistors.size(); i++)
			{
				screening.names.push_back(h.thermistors[i].name);
				const ThermistorHealthCounters c = health->counters(i);
				screening.counters.push_back(c);
				screening.rejected_readings += c.out_of_range + c.spike + c.stuck;
			}
		if (!screen || screening.rejected_readings) std::fputs(app::screeningText(screening, screen).c_str(), stdout);
		const CompensationCounters& c = compensator->counters();
		if (c.fallback_samples || c.no_model_samples || c.clamped_samples)
			std::printf("  compensation: %zu samples, %zu on a fallback model, %zu without model, %zu clamped to the "
						"calibrated range\n",
						c.samples, c.fallback_samples, c.no_model_samples, c.clamped_samples);
		std::fputs(app::outOfRangeWarning(c, zcal->extrapolation).c_str(), stdout);
		e.magnetic_term = zcal->magnetic.has_value();
		e.field_warning = app::fieldWarning(*zcal, c, !h.field_uT.empty());
		std::fputs(e.field_warning.c_str(), stderr);
	}

	off_yaw.finish();
	setTruthHeadingChanges(scan.gyro_off, off_yaw);
	e.gyro_off = scan.gyro_off;
	e.powered_spans = scan.powered.size();
	e.powered_spans_navigated = raw->windowsNavigated();
	e.report.distance_m = scan.distance_m;
	e.report.duration_s = scan.truth.last - scan.truth.first;
	e.segments = scan.segments;
	for (std::size_t i = 0; i < vars.size(); i++)
	{
		nav::DriftSeries s;
		nav::HeadingFigures f;
		vars[i]->finish(scan.distance_m, s, f);
		e.report.variants.push_back(std::move(s));
		e.figures[names[i]] = f;
		e.variants.emplace_back(names[i], nav::Trajectory{});
		e.results.emplace_back();
	}
	e.drive.fog.sensor_label = h.sensor_label;
	e.drive.fog.epoch_s = h.epoch_s;
	e.drive.fog.has_axis = h.has_axis;
	e.drive.fog.metadata = h.metadata;
	return e;
}

}  // namespace mrpt_fog::drift
