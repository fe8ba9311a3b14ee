/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "DriftOutputs.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/metrics/PlotCanvas.h>
#include <mrpt_fog_nav/OdometryRawlog.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::drift
{
void writeDriftJson(const std::string& path, const nav::DriftReport& report, const DriftContext& ctx)
{
	JsonValue j = JsonValue::object();
	const char* names[] = {"raw", "compensated", "ideal"};
	auto table = [&](const char* key, double nav::DriftSeries::*field) {
		JsonValue& t = j[key];
		t = JsonValue::object();
		for (const char* n : names)
		{
			bool found = false;
			for (const auto& v : report.variants)
				if (v.name == n)
				{
					t[n] = v.*field;
					found = true;
				}
			if (!found) t[n] = JsonValue();  // null: variant not available
		}
	};
	table("heading_error_final_deg", &nav::DriftSeries::heading_error_final_deg);
	table("heading_error_max_deg", &nav::DriftSeries::heading_error_max_deg);
	table("heading_error_final_signed_deg", &nav::DriftSeries::heading_error_final_signed_deg);
	table("position_error_final_m", &nav::DriftSeries::position_error_final_m);
	table("position_error_max_m", &nav::DriftSeries::position_error_max_m);
	table("position_error_final_pct", &nav::DriftSeries::position_error_final_pct);
	j["distance_m"] = report.distance_m;
	j["duration_s"] = report.duration_s;
	j["latitude_deg"] = ctx.latitude_deg;
	j["earth_rate_removed_dph"] = ctx.earth_rate_removed_dph;
	j["transport_rate"] = ctx.transport_rate;
	j["rate_sampling"] = ctx.rate_sampling;
	j["input"] = ctx.input;
	j["calibration"] = ctx.calibration.empty() ? JsonValue() : JsonValue(ctx.calibration);
	j["calibration_earth_rate_dph"] = ctx.calibration_earth_rate_dph;
	writeTextFileAtomically(path, j.dump());
}

void writeDriftPlots(const std::string& dir, const nav::Trajectory& truth, const std::vector<nav::NamedTrajectory>& variants,
					 const nav::DriftReport& report)
{
	if (!mrpt::system::directoryExists(dir) && !mrpt::system::createDirectory(dir))
		throw std::runtime_error(dir + ": cannot create the plot directory");
	const double t0 = truth.front().t_s;
	auto colourOf = [](const std::string& name) {
		if (name == "raw") return plot_colour::kRed;
		if (name == "compensated") return plot_colour::kBlue;
		if (name == "ideal") return plot_colour::kGreen;
		return plot_colour::kPurple;
	};

	{
		PlotCanvas fig(1000, 900);
		LinePlot& p = fig.addPanel();
		p.title = "Dead-reckoned trajectories (vertical FOG heading + wheel odometry) over the truth";
		p.x_axis.label = "East [m]";
		p.y_axis.label = "North [m]";
		for (const auto& [name, traj] : variants)
		{
			PlotSeries s{name, {}, {}, colourOf(name), 1};
			for (const auto& q : traj)
			{
				s.x.push_back(q.x_m);
				s.y.push_back(q.y_m);
			}
			p.addSeries(s);
		}
		PlotSeries gt{"truth", {}, {}, plot_colour::kBlack, 1};
		gt.dashed = true;  // drawn last, dashed: visible over the variants it should match
		for (const auto& q : truth)
		{
			gt.x.push_back(q.x_m);
			gt.y.push_back(q.y_m);
		}
		p.addSeries(gt);
		fig.save(dir + "/trajectories.png");
	}
	{
		PlotCanvas fig(1000, 700);
		LinePlot& p = fig.addPanel(2.0);
		p.title = "Heading error vs truth";
		p.x_axis.label = "time [s]";
		p.y_axis.label = "heading error [deg]";
		LinePlot& q = fig.addPanel(1.0);
		q.x_axis.label = "time [s]";
		q.y_axis.label = "position error [m]";
		for (const auto& v : report.variants)
		{
			PlotSeries s{v.name, {}, v.heading_error_deg, colourOf(v.name), 2};
			PlotSeries e{v.name, {}, v.position_error_m, colourOf(v.name), 2};
			for (double t : v.t_s) s.x.push_back(t - t0);
			e.x = s.x;
			p.addSeries(s);
			q.addSeries(e);
		}
		fig.save(dir + "/heading_error.png");
	}
}

void writeOdometryRawlog(const std::string& path, const nav::Trajectory& traj, const std::vector<double>& imu_rate_z_rad_s)
{
	const auto obs = nav::makeOdometryObservations(traj, imu_rate_z_rad_s);
	writeFileAtomically(path, [&](const std::string& tmp) {
		mrpt::io::CFileGZOutputStream f;
		if (!f.open(tmp)) throw std::runtime_error(tmp + ": cannot open for writing");
		auto ar = mrpt::serialization::archiveFrom(f);
		for (const auto& o : obs) ar << *o;
		f.close();
	});
}

}  // namespace mrpt_fog::drift
