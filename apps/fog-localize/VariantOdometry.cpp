/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "VariantOdometry.h"

#include "PipelineRate.h"

#include <mrpt_fog_nav/DeadReckoning.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::localize
{
namespace
{
struct Window
{
	double t0_s, t1_s;  //!< absolute [s]
	nav::AttitudeTrack track;
};
}  // namespace

std::vector<nav::Trajectory> deadReckonPoweredSpans(heading::HeadingPipeline& pipe, const FogSeries& fog,
													const heading::PowerSpanBuilder& power,
													const heading::DriveData& drive, const std::string& cal_path,
													const std::string& drive_path)
{
	const std::vector<double> t = heading::absoluteTimes(fog);
	const heading::OdometryPoses& odo = drive.odometry;
	if (t.size() < 2) throw std::runtime_error(drive_path + ": " + fog.sensor_label + ": fewer than 2 gyro samples");
	const double lo = std::max({t.front(), odo.t_s.front(), drive.truth.front().t_s});
	const double hi = std::min({t.back(), odo.t_s.back(), drive.truth.back().t_s});
	const bool per_span = !power.stretches().empty();
	std::vector<Window> windows;
	if (!per_span)  // powered throughout: the drive as one
		windows.push_back({lo, hi, {}});
	else
		for (const heading::PoweredSpan& span : power.powered())
			if (const auto w = heading::navigationWindow(span, t.front(), t.back(), odo.t_s.front(), odo.t_s.back(),
														 drive.truth.front().t_s, drive.truth.back().t_s))
				windows.push_back({std::max(w->first, lo), std::min(w->second, hi), {}});
	for (const Window& w : windows)
		if (!(w.t1_s > w.t0_s)) throw std::runtime_error("the gyro, the odometry and the truth do not overlap in time");

	constexpr double nan = std::numeric_limits<double>::quiet_NaN();
	FogSample x;
	x.temp_C.resize(fog.thermistors.size());
	std::size_t aligned = 0;  // windows aligned so far
	for (std::size_t k = 0; k < fog.size(); k++)
	{
		for (; aligned < windows.size() && t[k] >= windows[aligned].t0_s; aligned++)
		{
			Window& w = windows[aligned];
			pipe.realign(w.t0_s, nav::interpolate(drive.truth, w.t0_s).yaw_rad, 0.0, 0.0);  // position: below
			w.track.push_back(w.t0_s, pipe.attitude());
		}
		x.time_s = fog.time_s[k];
		for (std::size_t a = 0; a < 3; a++) x.rate_dph[a] = fog.has_axis[a] ? fog.rate_dph[a][k] : nan;
		for (std::size_t i = 0; i < x.temp_C.size(); i++) x.temp_C[i] = fog.temp_C[i][k];
		x.field_uT = fog.field_uT.empty() ? nan : fog.field_uT[k];
		x.power = fog.power.empty() ? nan : fog.power[k];
		const heading::RateStep& s = app::addFogSample(pipe, x, cal_path);
		if (aligned == 0) continue;
		Window& w = windows[aligned - 1];
		if (s.integrated && s.t_s <= w.t1_s && s.t_s > w.track.backTime()) w.track.push_back(s.t_s, pipe.attitude());
	}

	// Per window: the odometry inside its attitudes, dead-reckoned from the truth's position.
	std::vector<nav::Trajectory> out;
	for (const Window& w : windows)
	{
		if (w.track.times().empty()) continue;
		const auto first = static_cast<std::size_t>(std::lower_bound(odo.t_s.begin(), odo.t_s.end(), w.t0_s) - odo.t_s.begin());
		const auto last =
			static_cast<std::size_t>(std::upper_bound(odo.t_s.begin(), odo.t_s.end(), w.track.backTime()) - odo.t_s.begin());
		if (last < first + 2)
		{
			if (per_span) continue;  // a powered span too short to navigate
			throw std::runtime_error("fewer than 2 odometry samples inside the gyro's time span");
		}
		const nav::TrajectoryPoint p0 = nav::interpolate(drive.truth, odo.t_s[first]);
		nav::Trajectory part = nav::deadReckon2D(odo.t_s[first], p0.x_m, p0.y_m,
												 nav::odometryFromPoses2D(odo.t_s, odo.x_m, odo.y_m, odo.phi_rad, first, last),
												 w.track);
		if (!per_span || part.size() >= 2) out.push_back(std::move(part));
	}
	if (out.empty())
		throw std::runtime_error(drive_path + ": no powered span of the gyro overlaps the odometry and the truth long "
											  "enough to navigate");
	return out;
}

}  // namespace mrpt_fog::localize
