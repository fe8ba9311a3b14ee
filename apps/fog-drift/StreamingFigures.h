/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#pragma once

/** \file StreamingFigures.h
 * The drift figures of fog-drift's streaming evaluation (StreamingDrive.h), summed as the
 * samples come: nav::segmentDrive() on a stream of truth poses (StreamSegmenter), and
 * computeDriftReport's summary with computeHeadingFigures per gyro variant (FigureAccumulator).
 * Same arithmetic and summation order as the nav functions on whole series. */

#include <mrpt_fog_nav/DriftReport.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/HeadingFigures.h>

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog::drift
{
namespace streaming_detail
{
using mrpt_fog::units::kNaN;
constexpr double kRadToDeg = 180.0 / M_PI;  // as nav/HeadingFigures.cpp
}  // namespace streaming_detail

/** A turn with the unwrapped truth yaw [deg] at its ends. */
struct TurnSpan
{
	double t0_s = 0, t1_s = 0, yaw0_deg = 0, yaw1_deg = 0;
};

/** nav::segmentDrive() over a stream of truth poses, with the truth yaw at the turns' ends
 * (computeHeadingFigures' heading change of each turn: the ends are truth samples). */
class StreamSegmenter
{
   public:
	explicit StreamSegmenter(const nav::HeadingFigureOptions& o) : o_(o), h_(0.5 * o.smooth_s) {}

	void add(double t, double yaw_rad)
	{
		if (n_ == 0) front_yaw_rad_ = yaw_rad;
		else acc_ += std::remainder(yaw_rad - prev_yaw_rad_, 2 * M_PI);
		prev_yaw_rad_ = yaw_rad;
		const double y = (front_yaw_rad_ + acc_) * streaming_detail::kRadToDeg;
		if (n_ == 0) t_front_ = t, y_front_ = y;
		n_++;
		win_.push_back({t, y});
		// the smoothed rate of every point whose window (t + h) is now passed
		while (next_ < base_ + win_.size() && win_.back().first > at(next_).first + h_) rateOf(next_++, false);
	}

	/** The segments (empty below 3 poses) and the turns' end yaws. */
	void finish(nav::DriveSegments& seg, std::vector<TurnSpan>& turns)
	{
		if (n_ > 0)
		{
			while (next_ < base_ + win_.size()) rateOf(next_++, true);
			closeRun();
			for (auto& p : pending_) p.t1_s = win_.back().first, p.yaw1_deg = win_.back().second;
			for (auto& p : pending_) turns_.push_back(p);
			pending_.clear();
		}
		seg = {};
		turns.clear();
		if (n_ < 3) return;
		seg.straights = straights_;
		for (const auto& tr : turns_)  // merge turns that now overlap (segmentDrive)
		{
			if (!turns.empty() && tr.t0_s <= turns.back().t1_s)
			{
				if (tr.t1_s > turns.back().t1_s) turns.back().t1_s = tr.t1_s, turns.back().yaw1_deg = tr.yaw1_deg;
			}
			else
				turns.push_back(tr);
		}
		for (const auto& tr : turns) seg.turns.push_back({tr.t0_s, tr.t1_s});
	}

   private:
	const std::pair<double, double>& at(std::size_t i) const { return win_[i - base_]; }

	/** HeadingFigures.cpp's interpAt on the window (x inside the window's reach). */
	double interp(double x, bool done) const
	{
		if (x <= t_front_) return y_front_;
		if (done && x >= win_.back().first) return win_.back().second;
		const auto it = std::upper_bound(win_.begin(), win_.end(), x,
										 [](double v, const std::pair<double, double>& p) { return v < p.first; });
		const auto& b = *it;
		const auto& a = *(it - 1);
		const double f = (x - a.first) / (b.first - a.first);
		return a.second + f * (b.second - a.second);
	}

	void rateOf(std::size_t i, bool done)
	{
		const auto [t, y] = at(i);
		const double a = std::max(t_front_, t - h_), b = done ? std::min(win_.back().first, t + h_) : t + h_;
		const double rate = b > a ? (interp(b, done) - interp(a, done)) / (b - a) : 0.0;
		classify(t, y, rate);
		// drop what no later window reaches (the last point <= the next a stays). next_ is already
		// the next point to be rated (add() post-increments), so its window's start is at(next_) - h.
		if (!done)
			while (win_.size() > 2 && next_ < base_ + win_.size() && win_[1].first <= at(next_).first - h_)
			{
				win_.pop_front();
				base_++;
			}
	}

	void classify(double t, double y, double rate)
	{
		const double r = std::abs(rate);
		const bool turn = r > o_.turn_rate_dps, straight = r < o_.straight_rate_dps;
		if (!in_run_ || turn != run_turn_ || straight != run_straight_)
		{
			closeRun();
			in_run_ = true;
			run_turn_ = turn, run_straight_ = straight;
			run_t0_ = t;
			// a turn starts at the last quiet instant before it (else at the first pose)
			run_ext_t0_ = have_quiet_ ? quiet_t_ : t_front_;
			run_ext_y0_ = have_quiet_ ? quiet_y_ : y_front_;
		}
		run_t1_ = t;
		if (!(r >= o_.straight_rate_dps))  // quiet: ends the turns waiting for their end
		{
			for (auto& p : pending_) p.t1_s = t, p.yaw1_deg = y;
			for (auto& p : pending_) turns_.push_back(p);
			pending_.clear();
			have_quiet_ = true, quiet_t_ = t, quiet_y_ = y;
		}
	}

	void closeRun()
	{
		if (!in_run_) return;
		if (run_turn_ && run_t1_ > run_t0_)
			pending_.push_back({run_ext_t0_, streaming_detail::kNaN, run_ext_y0_, streaming_detail::kNaN});
		else if (run_straight_ && run_t1_ - run_t0_ - 2 * o_.margin_s >= o_.min_straight_s)
			straights_.push_back({run_t0_ + o_.margin_s, run_t1_ - o_.margin_s});
		in_run_ = false;
	}

	nav::HeadingFigureOptions o_;
	double h_;
	std::size_t n_ = 0, base_ = 0, next_ = 0;
	double front_yaw_rad_ = 0, prev_yaw_rad_ = 0, acc_ = 0, t_front_ = 0, y_front_ = 0;
	std::deque<std::pair<double, double>> win_;  //!< (t, unwrapped yaw [deg]) still needed
	bool in_run_ = false, run_turn_ = false, run_straight_ = false;
	double run_t0_ = 0, run_t1_ = 0, run_ext_t0_ = 0, run_ext_y0_ = 0;
	bool have_quiet_ = false;
	double quiet_t_ = 0, quiet_y_ = 0;
	std::vector<TurnSpan> pending_, turns_;
	std::vector<nav::DriveSegments::Span> straights_;
};

/** computeDriftReport's summary and computeHeadingFigures of one variant, summed over its
 * heading / position errors at the truth times as they come (same order, same arithmetic). */
class FigureAccumulator
{
   public:
	FigureAccumulator(const nav::DriveSegments& seg, const std::vector<TurnSpan>& turns) : seg_(seg), turns_(turns)
	{
		for (const auto& tr : turns) queries_.push_back(tr.t0_s), queries_.push_back(tr.t1_s);
		at_query_.assign(queries_.size(), streaming_detail::kNaN);
	}

	void add(double t, double e_deg, double pos_m)
	{
		// computeDriftReport
		s_.heading_error_max_deg = std::max(s_.heading_error_max_deg, std::abs(e_deg));
		s_.position_error_max_m = std::max(s_.position_error_max_m, pos_m);
		last_e_ = e_deg, last_pos_ = pos_m;
		// computeHeadingFigures: RMS and max
		ss_ += e_deg * e_deg;
		f_.heading_error_max_deg = std::max(f_.heading_error_max_deg, std::abs(e_deg));
		// the straight it is in (straights are disjoint and in time order)
		while (straight_ < seg_.straights.size() && t > seg_.straights[straight_].t1_s) closeStraight();
		if (straight_ < seg_.straights.size() && t >= seg_.straights[straight_].t0_s) in_straight_.push_back({t, e_deg});
		// the error at the turns' ends (interpAt: the first sample after x and the one before)
		while (q_ < queries_.size() && queries_[q_] < t)
		{
			const double x = queries_[q_];
			at_query_[q_++] = n_ == 0 ? e_deg : prev_e_ + ((x - prev_t_) / (t - prev_t_)) * (e_deg - prev_e_);
		}
		if (n_ == 0) first_t_ = t;
		prev_t_ = t, prev_e_ = e_deg;
		n_++;
	}

	std::size_t size() const { return n_; }

	void finish(const std::string& name, double distance_m, nav::DriftSeries& s, nav::HeadingFigures& f)
	{
		if (n_ == 0)
			throw std::invalid_argument("computeDriftReport: variant '" + name + "' does not overlap the truth in time");
		s_.name = name;
		s_.heading_error_final_signed_deg = last_e_;
		s_.heading_error_final_deg = std::abs(last_e_);
		s_.position_error_final_m = last_pos_;
		if (distance_m > 0)
		{
			s_.position_error_final_pct = 100.0 * s_.position_error_final_m / distance_m;
			s_.position_error_max_pct = 100.0 * s_.position_error_max_m / distance_m;
		}
		s = std::move(s_);
		if (n_ < 2) throw std::invalid_argument("computeHeadingFigures: need >= 2 error samples with times");
		while (straight_ < seg_.straights.size()) closeStraight();
		while (q_ < queries_.size()) at_query_[q_++] = prev_e_;  // x >= the last time
		f_.heading_error_rms_deg = std::sqrt(ss_ / static_cast<double>(n_));
		f_.heading_error_final_deg = std::abs(prev_e_);
		const double drift_dps = sxx_ > 0 ? sxy_ / sxx_ : streaming_detail::kNaN;
		f_.heading_drift_between_turns_dph = drift_dps * 3600.0;
		double sab = 0, saa = 0;
		for (std::size_t i = 0; i < turns_.size(); i++)
		{
			const TurnSpan& tr = turns_[i];
			if (tr.t0_s < first_t_ || tr.t1_s > prev_t_) continue;
			const double dpsi = tr.yaw1_deg - tr.yaw0_deg;
			double de = at_query_[2 * i + 1] - at_query_[2 * i];
			if (std::isfinite(drift_dps)) de -= drift_dps * (tr.t1_s - tr.t0_s);
			sab += de * dpsi;
			saa += dpsi * dpsi;
			f_.turns++;
			f_.turned_deg += std::abs(dpsi);
		}
		f_.turn_scale_factor_ppm = saa > 0 ? 1e6 * sab / saa : streaming_detail::kNaN;
		f = f_;
	}

   private:
	void closeStraight()
	{
		const auto& s = seg_.straights[straight_++];
		double st = 0, se = 0;
		for (const auto& [t, e] : in_straight_) st += t, se += e;
		const std::size_t m = in_straight_.size();
		if (m >= 3)
		{
			const double tm = st / static_cast<double>(m), em = se / static_cast<double>(m);
			for (const auto& [t, e] : in_straight_)
			{
				sxy_ += (t - tm) * (e - em);
				sxx_ += (t - tm) * (t - tm);
			}
			f_.straights++;
			f_.straight_time_s += s.t1_s - s.t0_s;
		}
		in_straight_.clear();
	}

	const nav::DriveSegments& seg_;
	const std::vector<TurnSpan>& turns_;
	nav::DriftSeries s_;
	nav::HeadingFigures f_;
	double last_e_ = 0, last_pos_ = 0, ss_ = 0, sxy_ = 0, sxx_ = 0;
	std::size_t n_ = 0, straight_ = 0, q_ = 0;
	double first_t_ = 0, prev_t_ = 0, prev_e_ = 0;
	std::vector<std::pair<double, double>> in_straight_;  //!< (t, error) of the current straight
	std::vector<double> queries_, at_query_;
};


}  // namespace mrpt_fog::drift
