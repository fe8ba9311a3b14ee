/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "StreamingDrive.h"

#include "GyroOff.h"
#include "StreamingFigures.h"
#include "VariantPipeline.h"

#include "Progress.h"

#include <mrpt/core/Clock.h>
#include <mrpt/core/bits_math.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/DeadReckoning.h>
#include <mrpt_fog_nav/EarthModel.h>
#include <mrpt_fog_nav/Rotation.h>

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
	FogSeries ideal_header;  //!< the ideal FOG's layout (HeadingPipeline::headerOf its first observation)
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

/** One gyro variant: its heading pipeline (the library's, HeadingPipeline.h: compensation, rate
 * correction, Earth rate, strapdown) fed in time order and aligned from the truth at the start of
 * each window; its attitudes dead-reckoned with the odometry from the truth's position there and
 * compared with the truth as the samples come -> figures. */
class VariantStream
{
   public:
	/** windows: the time spans navigated, each aligned from the truth at its start (one
	 * without gyro-off stretches; GyroOff.h); skip_short: a window with fewer than 2 odometry
	 * samples is skipped (else an error). pipe: the variant's pipeline (Alignment::ByCaller);
	 * feeds_odometry: the odometry goes to it too (its rate correction reads it); fog_samples:
	 * how many FOG samples the variant's gyro has (pass 1); cal_path: its calibration file, named
	 * in a compensation error ("" without). */
	VariantStream(std::string name, std::vector<std::pair<double, double>> windows, bool skip_short,
				  const DriveScan& scan, std::unique_ptr<heading::HeadingPipeline> pipe, bool feeds_odometry,
				  std::size_t fog_samples, std::string cal_path)
		: name_(std::move(name)), skip_short_(skip_short), acc_(scan.segments, scan.turns), pipe_(std::move(pipe)),
		  feeds_odometry_(feeds_odometry), cal_path_(std::move(cal_path)), fog_total_(fog_samples),
		  odo_total_(scan.odometry.n), odo_first_s_(scan.odometry.first)
	{
		for (const auto& [t0, t1] : windows)
		{
			Window w;
			w.t0 = t0, w.t1 = t1;
			windows_.push_back(std::move(w));
		}
	}

	heading::HeadingPipeline& pipeline() { return *pipe_; }

	/** The variant's next FOG sample (time relative to the pipeline header's epoch). */
	void addFog(const FogSample& x)
	{
		fogq_.push_back(x);
		fog_pushed_++;
	}
	/** The next odometry sample (readDrive's: a repeated or earlier time already skipped). */
	void addOdometry(const OdoPose& p)
	{
		if (!feeds_odometry_) return;
		odoq_.push_back(p);
		odo_pushed_++;
		last_odo_pushed_s_ = p.t_s;
	}
	/** The end of the file: every sample is in. */
	void inputDone() { fog_total_ = fog_pushed_, odo_total_ = odo_pushed_; }

	/** Advances as far as the data allow. */
	void pump(const IndexedQueue<nav::TrajectoryPoint>& truth, const IndexedQueue<OdoPose>& odo)
	{
		feed(truth);
		for (;;)
		{
			if (!cur().aligned) return;
			deadReckon(truth, odo);
			compare(truth);
			if (!compared_all_ || window_ + 1 >= windows_.size()) return;
			nextWindow();
		}
	}

	/** Windows navigated (at least 2 odometry samples). */
	std::size_t windowsNavigated() const { return navigated_; }
	/** Truth and odometry indices this variant still needs (its lower bounds). Before the
	 * dead reckoning of a later window starts: the last truth pose at or before its start; before
	 * the pipeline is aligned for a window: the last one at or before that window's start. */
	std::size_t truthNeeded(const IndexedQueue<nav::TrajectoryPoint>& truth) const
	{
		std::size_t need;
		if (cur().aligned && dr_started_) need = next_truth_;
		else if (window_ == 0) need = 0;
		else need = lastAtOrBefore(truth, cur().t0);
		if (aligned_windows_ < windows_.size()) need = std::min(need, lastAtOrBefore(truth, windows_[aligned_windows_].t0));
		return need;
	}
	std::size_t odoNeeded(const IndexedQueue<OdoPose>& odo) const
	{
		if (window_ > 0 && !dr_started_)  // a later window starts at the first odometry at or after its start
		{
			std::size_t i = std::max(next_odo_, odo.base);
			while (i < odo.end() && odo.at(i).t_s < cur().t0) i++;
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
		for (Window& w : windows_) w.rates = std::make_unique<RowSpill>(2);
	}

	/** Every error as it is compared (t, heading [deg], position [m]) also into `spill` (--csv). */
	void spillSeriesTo(RowSpill* spill) { series_ = spill; }

   private:
	struct Att
	{
		double t;
		Eigen::Quaterniond q;
	};
	/** A window: its span, the pipeline's attitudes inside it not yet passed by the dead
	 * reckoning, and (--odometry-out) its integrated rates. */
	struct Window
	{
		double t0 = 0, t1 = 0;
		bool aligned = false;  //!< the pipeline was aligned at t0
		bool final = false;  //!< no later attitude comes (a sample after t1 was given)
		std::deque<Att> track;
		std::unique_ptr<RowSpill> rates;
	};
	Window& cur() { return windows_[window_]; }
	const Window& cur() const { return windows_[window_]; }

	/** A FOG sample's absolute time, as the pipeline computes it. */
	double fogTime(const FogSample& x) const { return pipe_->header().epoch_s + x.time_s; }

	/** How far a FOG sample may be given ahead of the last odometry read when the odometry
	 * between them has not been read yet [s] (a log interleaves them at most this far out of
	 * time order; the pipeline's own limit, PipelineOptions::max_odometry_lag_s): beyond it the
	 * odometry has a gap, and the FOG samples are not held for it (memory). */
	static constexpr double kOrderLag_s = 10.0;

	/** Gives the pipeline what can be given in time order: an odometry sample before the FOG
	 * samples at or after its time (as the in-memory path merges them), each FOG sample once
	 * the pipeline is aligned for the windows that start at or before it. */
	void feed(const IndexedQueue<nav::TrajectoryPoint>& truth)
	{
		for (;;)
		{
			bool odo_first;
			if (!fogq_.empty() && !odoq_.empty()) odo_first = odoq_.front().t_s <= fogTime(fogq_.front());
			else if (!odoq_.empty())
			{
				// no FOG sample can come before it: all are in, or it is not after one already given
				if (!(fog_pushed_ >= fog_total_ || (any_fog_fed_ && odoq_.front().t_s <= last_fog_fed_s_))) return;
				odo_first = true;
			}
			else if (!fogq_.empty())
			{
				const double t = fogTime(fogq_.front());
				if (!(!feeds_odometry_ || odo_pushed_ >= odo_total_ || (odo_pushed_ == 0 && t < odo_first_s_) ||
					  (odo_pushed_ > 0 && t > last_odo_pushed_s_ + kOrderLag_s)))
					return;
				odo_first = false;
			}
			else
				return;
			if (odo_first)
			{
				const OdoPose o = odoq_.front();
				odoq_.pop_front();
				pipe_->addOdometry(o.t_s, o.x_m, o.y_m, o.phi_rad);
				dropPoses();
				continue;
			}
			const double t = fogTime(fogq_.front());
			if (!alignFor(t, truth)) return;  // the truth at a window's start is not read yet
			const heading::RateStep& s = addFogSample(*pipe_, fogq_.front(), cal_path_);
			fogq_.pop_front();
			any_fog_fed_ = true, last_fog_fed_s_ = t;
			dropPoses();
			keep(s);
		}
	}

	/** The pipeline's own poses (dead-reckoned from its alignment) are not the figures': this
	 * class dead-reckons from the truth's position. */
	void dropPoses()
	{
		heading::DeadReckonedPose p;
		while (pipe_->popPose(p))
		{
		}
	}

	/** Aligns the pipeline for the windows that start at or before t, from the truth's heading
	 * at their start; false while that truth is not read yet. */
	bool alignFor(double t, const IndexedQueue<nav::TrajectoryPoint>& truth)
	{
		while (aligned_windows_ < windows_.size() && t >= windows_[aligned_windows_].t0)
		{
			Window& w = windows_[aligned_windows_];
			if (!truthReady(truth, w.t0)) return false;
			const double yaw = interpolateTruth(truth, w.t0).yaw_rad;
			if (aligned_windows_ > 0) windows_[aligned_windows_ - 1].final = true;
			pipe_->realign(w.t0, yaw, 0.0, 0.0);  // the position: this class's dead reckoning
			w.track.push_back({w.t0, pipe_->attitude()});
			w.aligned = true;
			aligned_windows_++;
		}
		return true;
	}

	/** The attitude after an integrated sample of the window being fed. */
	void keep(const heading::RateStep& s)
	{
		if (aligned_windows_ == 0) return;
		Window& w = windows_[aligned_windows_ - 1];
		if (w.final) return;
		if (s.t_s > w.t1)
		{
			w.final = true;
			return;
		}
		if (!s.integrated) return;
		if (s.t_s > w.track.back().t) w.track.push_back({s.t_s, pipe_->attitude()});
		if (w.rates)
		{
			const double row[2] = {s.t_s, s.integrated_dph * units::kDegPerHourToRadPerSec - earth_up_};
			w.rates->push(row);
		}
	}

	static bool truthReady(const IndexedQueue<nav::TrajectoryPoint>& truth, double t)
	{
		return truth.done || (!truth.q.empty() && truth.q.back().t_s > t);
	}

	/** The index of the last truth pose held at or before t (the first held when none). */
	static std::size_t lastAtOrBefore(const IndexedQueue<nav::TrajectoryPoint>& truth, double t)
	{
		std::size_t i = truth.base;
		while (i + 1 < truth.end() && truth.at(i + 1).t_s <= t) i++;
		return i;
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

	/** Whether the window's attitudes are all in. */
	bool trackFinal() const { return cur().final || (fog_pushed_ >= fog_total_ && fogq_.empty()); }

	/** AttitudeTrack::yawAt(t) on the attitudes still held (the same bracket); drops the
	 * attitudes before it. */
	double yawAt(double t)
	{
		std::deque<Att>& track = cur().track;
		std::size_t i1;
		if (track.size() == 1) return nav::yawOf(track.front().q);
		auto it = std::upper_bound(track.begin(), track.end(), t, [](double v, const Att& a) { return v < a.t; });
		i1 = it == track.end() ? track.size() - 1 : static_cast<std::size_t>(it - track.begin());
		if (i1 == 0) throw std::out_of_range("AttitudeTrack::at: time before the attitudes held");
		const std::size_t i0 = i1 - 1;
		const double f = (t - track[i0].t) / (track[i1].t - track[i0].t);
		const double yaw = nav::yawOf(track[i0].q.slerp(f, track[i1].q));
		for (std::size_t k = 0; k < i0; k++) track.pop_front();
		return yaw;
	}

	/** Whether the attitude at t is final (a later attitude exists, or there will be none). */
	bool attitudeReady(double t) const { return cur().track.back().t > t || trackFinal(); }

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
				if (o.t_s < cur().t0)  // lower_bound(t0)
				{
					next_odo_++;
					continue;
				}
				if (!truthReady(truth, o.t_s) || !attitudeReady(o.t_s)) return;
				if (!(o.t_s <= cur().track.back().t))  // not inside the attitude track
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
			if (!(o.t_s <= cur().track.back().t))
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
		cur().track.clear();
		window_++;
		dr_started_ = dr_done_ = first_pending_ = compared_all_ = false;
		dr_points_ = 0;
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
			for (auto [from, to] : {std::pair{win_poses_.get(), poses_}, {cur().rates.get(), rates_}})
			{
				RowSpill::Reader r(*from);
				while (const double* row = r.next()) to->push(row);
			}
		win_poses_ = std::make_unique<RowSpill>(4);
		cur().rates.reset();
		compared_in_window_ = 0;
	}


	RowSpill* series_ = nullptr;
	RowSpill *poses_ = nullptr, *rates_ = nullptr;
	std::unique_ptr<RowSpill> win_poses_;
	double earth_up_ = 0;
	std::size_t compared_in_window_ = 0;
	std::string name_;
	bool skip_short_ = false;
	std::size_t window_ = 0, navigated_ = 0;
	FigureAccumulator acc_;
	std::unique_ptr<heading::HeadingPipeline> pipe_;
	bool feeds_odometry_ = false;
	std::string cal_path_;
	std::vector<Window> windows_;
	std::size_t aligned_windows_ = 0;  //!< windows the pipeline was aligned for
	std::deque<FogSample> fogq_;  //!< FOG samples read, not yet given to the pipeline
	std::deque<OdoPose> odoq_;  //!< odometry read, not yet given to the pipeline
	std::size_t fog_total_, fog_pushed_ = 0, odo_total_, odo_pushed_ = 0;
	double odo_first_s_, last_odo_pushed_s_ = 0, last_fog_fed_s_ = 0;
	bool any_fog_fed_ = false;
	nav::Trajectory pair_;
	nav::TrajectoryPoint last_;
	OdoPose prev_odo_{};
	bool dr_started_ = false, dr_done_ = false, first_pending_ = false, compared_all_ = false;
	std::size_t next_odo_ = 0, next_truth_ = 0, dr_points_ = 0;
	double traj_front_t_ = 0;  //!< the trajectory's first time (traj_ keeps its tail)
	std::deque<nav::TrajectoryPoint> traj_;
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
			if (scan.ideal.n == 0) scan.ideal_header = heading::HeadingPipeline::headerOf(o);
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

	// ---- pass 2: every variant at once, each on its heading pipeline (VariantPipeline.h)
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
	const auto windowsOf = [&](const Ends& g) {
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
		return windows;
	};
	const auto addVariant = [&](const std::string& name, const Ends& g, std::unique_ptr<heading::HeadingPipeline> pipe,
								bool feeds_odometry, std::string cal_path) {
		vars.push_back(std::make_unique<VariantStream>(name, windowsOf(g), gyro_off, scan, std::move(pipe), feeds_odometry,
													   g.n, std::move(cal_path)));
		names.push_back(name);
	};
	addVariant("raw", scan.fog, std::make_unique<heading::HeadingPipeline>(h, pipelineOptionsFor(hopt)), false, "");
	VariantStream* raw = vars.back().get();
	VariantStream* comp_var = nullptr;
	if (zcal)
	{
		// the odometry goes to its pipeline too when the standstill updates read it
		auto pipe = compensatedPipeline(h, *zcal, st, hopt, scan.fog.first, st.refinement.enabled, e);
		const bool reads_odometry = pipe->rateCorrection() != nullptr;
		addVariant("compensated", scan.fog, std::move(pipe), reads_odometry, st.cal_path);
		comp_var = vars.back().get();
	}
	VariantStream* ideal_var = nullptr;
	if (scan.ideal.n > 0)
	{
		addVariant("ideal", scan.ideal,
				   std::make_unique<heading::HeadingPipeline>(scan.ideal_header, pipelineOptionsFor(hopt)), false, "");
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
		(void)ideal_times.add(o);  // its layout checked
		if (ideal_var) ideal_var->addFog(fogSampleOf(o, scan.ideal_header.epoch_s));
	};
	others.on_odometry = [&](const OdoPose& p) {
		odo.q.push_back(p);
		for (auto& v : vars) v->addOdometry(p);
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
		FogSample x;
		while (reader.next(x))
		{
			raw->addFog(x);
			if (comp_var) comp_var->addFog(x);
			if (++since_pump >= 64) pumpAll(), since_pump = 0;
		}
		truth.done = odo.done = true;
		for (auto& v : vars) v->inputDone();
		pumpAll();
	}
	if (comp_var) reportCompensation(comp_var->pipeline(), *zcal, !h.field_uT.empty(), st, e);

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
