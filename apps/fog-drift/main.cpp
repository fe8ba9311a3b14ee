/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a vehicle drive.
 *
 *   fog-drift -i DRIVE.rawlog --cal CAL.yaml [--json F] [--plots DIR] [--odometry-out F.rawlog]
 *
 * Reads the drive (FOG "FOG" with thermal error, "FOG_IDEAL" without, wheel odometry
 * "ODOMETRY", truth "GROUND_TRUTH"), compensates "FOG" with the calibration, integrates the
 * heading of each gyro (Earth rate at the drive's latitude removed) with the odometry, and
 * compares the three dead-reckoned trajectories with the truth. */
#include "AppMain.h"
#include "CommandLine.h"
#include "Compensation.h"
#include "DriftOutputs.h"
#include "DriveData.h"
#include "HeadingDeadReckoning.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/DriftReport.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>

using namespace mrpt_fog;

namespace
{
/** Linear interpolation of (t, y) at the times tq (clamped at the ends). */
std::vector<double> interpAt(const std::vector<double>& t, const std::vector<double>& y, const nav::Trajectory& tq)
{
	std::vector<double> out;
	out.reserve(tq.size());
	for (const auto& p : tq)
	{
		auto it = std::lower_bound(t.begin(), t.end(), p.t_s);
		if (it == t.begin()) out.push_back(y.front());
		else if (it == t.end()) out.push_back(y.back());
		else
		{
			const std::size_t i = static_cast<std::size_t>(it - t.begin());
			const double f = (p.t_s - t[i - 1]) / (t[i] - t[i - 1]);
			out.push_back(y[i - 1] + f * (y[i] - y[i - 1]));
		}
	}
	return out;
}
}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-drift", [&] {
		TCLAP::CmdLine cmd("fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive", ' ',
						   "0.1");
		TCLAP::ValueArg<std::string> in("i", "input", "drive rawlog (FOG, FOG_IDEAL, ODOMETRY, GROUND_TRUTH)", true, "",
										"DRIVE.rawlog", cmd);
		TCLAP::ValueArg<std::string> cal("", "cal", "calibration YAML for the FOG (fog-calibrate); without it the "
														"compensated variant is left out",
										 false, "", "CAL.yaml", cmd);
		TCLAP::ValueArg<std::string> json("", "json", "write the drift figures as JSON", false, "", "F.json", cmd);
		TCLAP::ValueArg<std::string> plots("", "plots", "write trajectories.png and heading_error.png here", false, "",
										   "DIR", cmd);
		TCLAP::ValueArg<std::string> odo_out("", "odometry-out",
											 "write the compensated (else raw) dead-reckoned trajectory as a rawlog of "
											 "CObservationOdometry + CObservationIMU for pf-localization",
											 false, "", "F.rawlog", cmd);
		TCLAP::ValueArg<double> lat("", "latitude-deg", "latitude [deg] (default: from the drive's metadata)", false,
									NAN, "DEG", cmd);
		TCLAP::ValueArg<double> cal_lat("", "cal-latitude-deg",
										"latitude [deg] of the calibration runs (default: the drive's): a static "
										"calibration's bias absorbs the vertical Earth rate there, which the "
										"compensator then removes; fog-drift adds it back before its own "
										"Earth-rate removal so that it is not removed twice",
										false, NAN, "DEG", cmd);
		TCLAP::SwitchArg cal_no_earth("", "cal-no-earth-rate",
									  "the calibration runs' table rate already included the Earth rate (their bias "
									  "does not contain it)",
									  cmd);
		TCLAP::SwitchArg transport("", "transport-rate",
								   "also remove the vertical transport rate (for real drives over the curved Earth; "
								   "the simulator's drive is flat-Earth)",
								   cmd);
		TCLAP::ValueArg<std::string> sampling("", "rate-sampling",
											  "gyro samples are the mean rate over the preceding interval ('average', digital FOGs and fog-sim) or 'instantaneous' (trapezoid rule) "
											  "preceding interval",
											  false, "average", "KIND", cmd);
		TCLAP::SwitchArg no_screen("", "no-screening",
								   "do not screen the FOG's thermistor readings (stuck / spike / out of range -> "
								   "dropout, fallback model) before compensating",
								   cmd);
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-drift")) return *rc;

		drift::HeadingOptions hopt;
		if (sampling.getValue() == "instantaneous") hopt.sampling = nav::RateSampling::Instantaneous;
		else if (sampling.getValue() == "average") hopt.sampling = nav::RateSampling::IntervalAverage;
		else throw std::runtime_error("--rate-sampling: '" + sampling.getValue() + "' is not instantaneous|average");
		hopt.transport_rate = transport.getValue();

		requireSafeOutputs({{"-i", in.getValue()}, {"--cal", cal.getValue()}},
						   {{"--json", json.getValue()}, {"--odometry-out", odo_out.getValue()}});
		const drift::DriveData drive = drift::readDrive(in.getValue());
		if (std::isfinite(lat.getValue())) hopt.latitude_deg = lat.getValue();
		else if (drive.latitude_deg) hopt.latitude_deg = *drive.latitude_deg;
		else
			throw std::runtime_error(in.getValue() + ": no latitude_deg in the metadata; give --latitude-deg");
		if (!(std::abs(hopt.latitude_deg) <= 90)) throw std::runtime_error("--latitude-deg: must be within [-90, 90]");

		std::vector<nav::NamedTrajectory> variants;
		std::vector<drift::VariantResult> results;
		auto run = [&](const std::string& name, const std::vector<double>& t, const std::vector<double>& rate) {
			results.push_back(drift::deadReckonVariant(t, rate, drive, hopt));
			variants.emplace_back(name, results.back().trajectory);
		};
		// The heading gyro is the vertical (z) axis; x/y axes of a triad are not used (planar drive).
		auto verticalRate = [&](const FogSeries& s) -> const std::vector<double>& {
			if (!s.has_axis[2])
				throw std::runtime_error(in.getValue() + ": FOG '" + s.sensor_label +
										 "' has no z (vertical) axis; fog-drift integrates the vertical gyro");
			return s.rate_dph[2];
		};
		const std::vector<double> t_fog = drift::absoluteTimes(drive.fog);
		run("raw", t_fog, verticalRate(drive.fog));
		double cal_earth_dph = 0.0;  // vertical Earth rate inside the calibration's bias
		if (!cal.getValue().empty())
		{
			const double cal_lat_deg = std::isfinite(cal_lat.getValue()) ? cal_lat.getValue() : hopt.latitude_deg;
			if (!(std::abs(cal_lat_deg) <= 90)) throw std::runtime_error("--cal-latitude-deg: must be within [-90, 90]");
			if (!cal_no_earth.getValue()) cal_earth_dph = units::kEarthRate_dph * std::sin(cal_lat_deg * units::kDegToRad);
			std::vector<double> comp = drift::compensatedRate_dph(drive.fog, cal.getValue(), !no_screen.getValue());
			for (double& r : comp) r += cal_earth_dph;
			run("compensated", t_fog, comp);
		}
		if (drive.fog_ideal) run("ideal", drift::absoluteTimes(*drive.fog_ideal), verticalRate(*drive.fog_ideal));

		const nav::DriftReport rep = nav::computeDriftReport(drive.truth, variants);

		std::printf("fog-drift: %s: %.0f s, %.1f m driven, latitude %.4f deg (Earth rate %.4f deg/h removed)\n",
					in.getValue().c_str(), rep.duration_s, rep.distance_m, hopt.latitude_deg,
					units::kEarthRate_dph * std::sin(hopt.latitude_deg * units::kDegToRad));
		std::printf("  %-12s %18s %16s %18s %14s\n", "gyro", "heading final [deg]", "heading max [deg]",
					"position final [m]", "[% distance]");
		for (const auto& v : rep.variants)
			std::printf("  %-12s %18.4f %16.4f %18.2f %14.3f\n", v.name.c_str(), v.heading_error_final_deg,
						v.heading_error_max_deg, v.position_error_final_m, v.position_error_final_pct);

		if (!json.getValue().empty())
		{
			drift::DriftContext ctx;
			ctx.input = in.getValue();
			ctx.calibration = cal.getValue();
			ctx.latitude_deg = hopt.latitude_deg;
			ctx.earth_rate_removed_dph = units::kEarthRate_dph * std::sin(hopt.latitude_deg * units::kDegToRad);
			ctx.transport_rate = hopt.transport_rate;
			ctx.rate_sampling = sampling.getValue();
			ctx.calibration_earth_rate_dph = cal_earth_dph;
			drift::writeDriftJson(json.getValue(), rep, ctx);
		}
		if (!plots.getValue().empty()) drift::writeDriftPlots(plots.getValue(), drive.truth, variants, rep);
		if (!odo_out.getValue().empty())
		{
			const std::size_t i = cal.getValue().empty() ? 0 : 1;  // compensated when available
			const auto& r = results[i];
			drift::writeOdometryRawlog(odo_out.getValue(), r.trajectory, interpAt(r.t_s, r.yaw_rate_rad_s, r.trajectory));
			const auto& p0 = r.trajectory.front();
			std::printf("  odometry rawlog (%s): %s; pf-localization: initial_odo_x=%.6f initial_odo_y=%.6f "
						"initial_odo_phi=%.9f\n",
						variants[i].first.c_str(), odo_out.getValue().c_str(), p0.x_m, p0.y_m, p0.yaw_rad);
		}
		return 0;
	});
}
