/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "DriftOutputs.h"

#include "FieldWarning.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/system/filesystem.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/plot/PlotCanvas.h>
#include <mrpt_fog_nav/OdometryRawlog.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::drift
{
namespace
{
JsonValue driveJson(const DriveEvaluation& e, const DriftContext& ctx)
{
	const nav::DriftReport& report = e.report;
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
	auto figTable = [&](const char* key, double nav::HeadingFigures::*field) {
		JsonValue& t = j[key];
		t = JsonValue::object();
		for (const char* n : names)
		{
			const auto it = e.figures.find(n);
			t[n] = it == e.figures.end() || !std::isfinite(it->second.*field) ? JsonValue() : JsonValue(it->second.*field);
		}
	};
	table("heading_error_final_deg", &nav::DriftSeries::heading_error_final_deg);
	table("heading_error_max_deg", &nav::DriftSeries::heading_error_max_deg);
	table("heading_error_final_signed_deg", &nav::DriftSeries::heading_error_final_signed_deg);
	table("position_error_final_m", &nav::DriftSeries::position_error_final_m);
	table("position_error_max_m", &nav::DriftSeries::position_error_max_m);
	table("position_error_final_pct", &nav::DriftSeries::position_error_final_pct);
	figTable("heading_error_rms_deg", &nav::HeadingFigures::heading_error_rms_deg);
	figTable("heading_drift_between_turns_dph", &nav::HeadingFigures::heading_drift_between_turns_dph);
	figTable("turn_scale_factor_ppm", &nav::HeadingFigures::turn_scale_factor_ppm);
	const auto tab = driveFigureTable(e);
	JsonValue& r = j["ratios"] = JsonValue::object();
	for (const auto& kv : tab)
		if (kv.first.rfind("ratio.", 0) == 0) r[kv.first.substr(6)] = std::isfinite(kv.second) ? JsonValue(kv.second) : JsonValue();
	if (e.three_axis)  // the triad's attitude and per-axis figures (driveFigureTable keys)
	{
		JsonValue& t3 = j["three_axis"] = JsonValue::object();
		for (const auto& kv : tab)
			if (kv.first.rfind("roll_", 0) == 0 || kv.first.rfind("pitch_", 0) == 0 || kv.first.rfind("rate_error_", 0) == 0)
				t3[kv.first] = std::isfinite(kv.second) ? JsonValue(kv.second) : JsonValue();
	}
	if (!e.figures.empty())
	{
		const auto& f = e.figures.begin()->second;
		JsonValue& sg = j["segments"] = JsonValue::object();
		sg["turns"] = static_cast<unsigned long>(f.turns);
		sg["turned_deg"] = f.turned_deg;
		sg["straights"] = static_cast<unsigned long>(f.straights);
		sg["straight_time_s"] = f.straight_time_s;
	}
	{
		// the gyro-off stretches (always present: total_s 0 and no stretch on a powered drive)
		JsonValue& g = j["gyro_off"] = JsonValue::object();
		double total = 0;
		JsonValue list = JsonValue::array();
		for (const auto& s : e.gyro_off)
		{
			total += s.duration_s();
			JsonValue o = JsonValue::object();
			o["off_s"] = s.off_s - e.drive.fog.epoch_s;
			o["on_s"] = s.on_s - e.drive.fog.epoch_s;
			o["duration_s"] = s.duration_s();
			o["samples"] = static_cast<unsigned long>(s.samples);
			o["from_start"] = s.from_start;
			o["to_end"] = s.to_end;
			o["truth_heading_change_deg"] =
				std::isfinite(s.truth_heading_change_deg) ? JsonValue(s.truth_heading_change_deg) : JsonValue();
			list.push_back(o);
		}
		g["total_s"] = total;
		g["stretches"] = list;
		g["powered_spans"] = static_cast<unsigned long>(e.powered_spans);
		g["powered_spans_navigated"] = static_cast<unsigned long>(e.powered_spans_navigated);
		g["figures_over"] = e.gyro_off.empty() ? "the whole drive"
											   : "powered spans only, each re-aligned from the truth (heading and "
												 "position) at its start; heading not observable while the gyro is off";
	}
	j["distance_m"] = report.distance_m;
	j["duration_s"] = report.duration_s;
	j["latitude_deg"] = ctx.latitude_deg;
	j["earth_rate_removed_dph"] = ctx.earth_rate_removed_dph;
	j["transport_rate"] = ctx.transport_rate;
	j["rate_sampling"] = ctx.rate_sampling;
	j["input"] = ctx.input;
	j["input_notices"] = ctx.input_notices;
	j["calibration"] = ctx.calibration.empty() ? JsonValue() : JsonValue(ctx.calibration);
	j["calibration_earth_rate_dph"] = ctx.calibration_earth_rate_dph;
	j["calibration_latitude_source"] =
		ctx.calibration_latitude_source.empty() ? JsonValue() : JsonValue(ctx.calibration_latitude_source);
	j["option_conflicts"] = JsonValue::arrayOf(e.option_conflicts);
	if (e.magnetic_term)  // only for a calibration with a magnetic section: other reports keep their keys
		j["magnetic_field_warning"] =
			e.field_warning.empty() ? JsonValue() : JsonValue(app::fieldWarningMessage(e.field_warning));
	return j;
}
}  // namespace

std::string gyroOffText(const DriveEvaluation& e)
{
	if (e.gyro_off.empty()) return "";
	double total = 0;
	for (const auto& s : e.gyro_off) total += s.duration_s();
	std::string out = formatValue("  gyro off %.1f s", total) + " in " + std::to_string(e.gyro_off.size()) +
					  (e.gyro_off.size() == 1 ? " stretch" : " stretches") +
					  ": heading not observable there; drift figures computed on the powered spans only (" +
					  std::to_string(e.powered_spans_navigated) + " of " + std::to_string(e.powered_spans) +
					  " navigated), each re-aligned from the truth (heading and position) at its start\n";
	for (const auto& s : e.gyro_off)
	{
		out += formatValue("    off %.1f", s.off_s - e.drive.fog.epoch_s) + formatValue(" .. %.1f s", s.on_s - e.drive.fog.epoch_s) +
			   formatValue(" (%.1f s", s.duration_s()) + ", " + std::to_string(s.samples) + " samples" +
			   (s.from_start ? ", from the start" : "") + (s.to_end ? ", to the end" : "") + "): truth heading change " +
			   (std::isfinite(s.truth_heading_change_deg) ? formatValue("%.1f deg", s.truth_heading_change_deg)
														  : std::string("unknown (outside the truth)")) +
			   "\n";
	}
	return out;
}

void writeDriftJson(const std::string& path, const std::vector<DriveEvaluation>& drives,
					const std::vector<DriftContext>& ctxs, const std::map<std::string, Spread>& over)
{
	if (drives.size() == 1)
	{
		writeTextFileAtomically(path, driveJson(drives.front(), ctxs.front()).dump());
		return;
	}
	JsonValue j = JsonValue::object();
	JsonValue& d = j["drives"] = JsonValue::array();
	for (std::size_t i = 0; i < drives.size(); i++) d.push_back(driveJson(drives[i], ctxs[i]));
	JsonValue& o = j["over_drives"] = JsonValue::object();
	o["drives"] = static_cast<unsigned long>(drives.size());
	for (const auto& kv : over)
	{
		JsonValue s = JsonValue::object();
		s["n"] = static_cast<unsigned long>(kv.second.n);
		const auto num = [](double v) { return std::isfinite(v) ? JsonValue(v) : JsonValue(); };
		s["median"] = num(kv.second.median);
		s["q1"] = num(kv.second.q1);
		s["q3"] = num(kv.second.q3);
		s["min"] = num(kv.second.min);
		s["max"] = num(kv.second.max);
		o[kv.first] = s;
	}
	writeTextFileAtomically(path, j.dump());
}

namespace
{
/** One variant's series, row by row: (t, heading error, position error). */
using SeriesCursor = std::function<bool(double& t, double& heading_deg, double& position_m)>;

/** The CSV of writeDriftCsv: per truth pose (nextTruth: absolute t, yaw [rad]) a row with each
 * variant's errors where it was compared at that time, rows without any left out. */
void writeDriftCsvRows(const std::string& path, const std::vector<std::string>& names, double t0,
					   const std::function<bool(double& t, double& yaw_rad)>& nextTruth, std::vector<SeriesCursor> series)
{
	// Row by row into the file (the whole text in memory was ~100 B per sample, issue 14).
	writeFileAtomically(path, [&](const std::string& tmp) {
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f) throw std::runtime_error("cannot write '" + path + "': cannot open: " + std::strerror(errno));
		f.precision(10);
		f << "time_s,truth_yaw_deg";
		for (const auto& n : names) f << ",heading_error_" << n << "_deg,position_error_" << n << "_m";
		f << "\n";
		// every variant is evaluated at the truth times inside its span: each one's next row
		struct Row
		{
			bool valid = false;
			double t = 0, e = 0, pos = 0;
		};
		std::vector<Row> cur(series.size());
		for (std::size_t i = 0; i < series.size(); i++) cur[i].valid = series[i](cur[i].t, cur[i].e, cur[i].pos);
		std::ostringstream row;
		row.precision(10);
		double gt_t = 0, gt_yaw = 0;
		while (nextTruth(gt_t, gt_yaw))
		{
			bool any = false;
			row.str("");
			row << gt_t - t0 << "," << gt_yaw * 180.0 / M_PI;
			for (std::size_t i = 0; i < series.size(); i++)
			{
				Row& c = cur[i];
				while (c.valid && c.t < gt_t) c.valid = series[i](c.t, c.e, c.pos);
				if (c.valid && c.t == gt_t)
				{
					row << "," << c.e << "," << c.pos;
					any = true;
				}
				else
					row << ",,";
			}
			if (any) f << row.str() << "\n";
		}
		f.close();
		if (!f) throw std::runtime_error("cannot write '" + path + "': write error (disk full?)");
	});
}
}  // namespace

void writeDriftCsv(const std::string& path, const nav::Trajectory& truth, const nav::DriftReport& report)
{
	std::vector<std::string> names;
	std::vector<SeriesCursor> series;
	std::vector<std::size_t> idx(report.variants.size(), 0);
	for (std::size_t i = 0; i < report.variants.size(); i++)
	{
		const auto& v = report.variants[i];
		names.push_back(v.name);
		series.push_back([&v, &k = idx[i]](double& t, double& e, double& pos) {
			if (k >= v.t_s.size()) return false;
			t = v.t_s[k], e = v.heading_error_deg[k], pos = v.position_error_m[k];
			k++;
			return true;
		});
	}
	std::size_t g = 0;
	writeDriftCsvRows(path, names, truth.front().t_s,
					  [&](double& t, double& yaw) {
						  if (g >= truth.size()) return false;
						  t = truth[g].t_s, yaw = truth[g].yaw_rad;
						  g++;
						  return true;
					  },
					  std::move(series));
}

void writeDriftCsv(const std::string& path, const SpilledSeries& spilled, const nav::DriftReport& report)
{
	if (spilled.variants.size() != report.variants.size())
		throw std::invalid_argument("writeDriftCsv: spilled series and report variants differ in number");
	if (spilled.truth.rows() == 0) throw std::runtime_error("cannot write '" + path + "': the drive has no truth pose");
	std::vector<std::string> names;
	std::vector<std::unique_ptr<RowSpill::Reader>> readers;
	std::vector<SeriesCursor> series;
	for (std::size_t i = 0; i < report.variants.size(); i++)
	{
		names.push_back(report.variants[i].name);
		readers.push_back(std::make_unique<RowSpill::Reader>(*spilled.variants[i]));
		series.push_back([r = readers.back().get()](double& t, double& e, double& pos) {
			const double* row = r->next();
			if (!row) return false;
			t = row[0], e = row[1], pos = row[2];
			return true;
		});
	}
	RowSpill::Reader truth(spilled.truth);
	double t0 = 0;
	{
		RowSpill::Reader first(spilled.truth);
		t0 = first.next()[0];
	}
	writeDriftCsvRows(path, names, t0,
					  [&](double& t, double& yaw) {
						  const double* row = truth.next();
						  if (!row) return false;
						  t = row[0], yaw = row[1];
						  return true;
					  },
					  std::move(series));
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
		LinePlot& p = fig.addPanel(1.0, "East [m]", "North [m]",
								   "Dead-reckoned trajectories (vertical FOG heading + wheel odometry) over the truth");
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
		LinePlot& p = fig.addPanel(2.0, "time [s]", "heading error [deg]", "Heading error vs truth");
		LinePlot& q = fig.addPanel(1.0, "time [s]", "position error [m]");
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
	if (imu_rate_z_rad_s.size() != traj.size())
		throw std::invalid_argument("writeOdometryRawlog: imu_rate_z_rad_s size differs from the trajectory");
	writeFileAtomically(path, [&](const std::string& tmp) {
		mrpt::io::CFileGZOutputStream f;
		if (!f.open(tmp)) throw std::runtime_error(tmp + ": cannot open for writing");
		auto ar = mrpt::serialization::archiveFrom(f);
		// A few thousand poses at a time: the MRPT objects of the whole drive were ~1 KB per
		// pose (issue 14). With the rates given, a chunk's objects are the whole call's.
		constexpr std::size_t kChunk = 4096;
		for (std::size_t b = 0; b < traj.size(); b += kChunk)
		{
			const std::size_t e = std::min(traj.size(), b + kChunk);
			const nav::Trajectory part(traj.begin() + static_cast<std::ptrdiff_t>(b), traj.begin() + static_cast<std::ptrdiff_t>(e));
			const std::vector<double> rates(imu_rate_z_rad_s.begin() + static_cast<std::ptrdiff_t>(b),
											imu_rate_z_rad_s.begin() + static_cast<std::ptrdiff_t>(e));
			for (const auto& o : nav::makeOdometryObservations(part, rates)) ar << *o;
		}
		f.close();
	});
}

nav::TrajectoryPoint writeOdometryRawlog(const std::string& path, const SpilledSeries& spilled)
{
	nav::TrajectoryPoint first_pose;
	{
		RowSpill::Reader r(spilled.odometry_poses);
		const double* p = r.next();
		if (!p) throw std::runtime_error("cannot write '" + path + "': no dead-reckoned pose to write");
		first_pose.t_s = p[0], first_pose.x_m = p[1], first_pose.y_m = p[2], first_pose.yaw_rad = p[3];
	}
	RowSpill::Reader rates(spilled.odometry_rates);
	const double* r0 = rates.next();
	if (!r0) throw std::runtime_error("cannot write '" + path + "': no gyro rate to write");
	// the main path's interpAt(rate times, rates, pose times), walked once: the first rate at or
	// after the pose's time and the one before it
	const double y_front = r0[1];
	double t_prev = 0, y_prev = 0, t_cur = r0[0], y_cur = r0[1];
	bool have_prev = false, cur_valid = true;
	const auto rateAt = [&](double tq) {
		while (cur_valid && t_cur < tq)
		{
			t_prev = t_cur, y_prev = y_cur, have_prev = true;
			if (const double* r = rates.next()) t_cur = r[0], y_cur = r[1];
			else cur_valid = false;
		}
		if (!cur_valid) return y_prev;  // after the last rate: the last one
		if (!have_prev) return y_front;  // at or before the first
		const double f = (tq - t_prev) / (t_cur - t_prev);
		return y_prev + f * (y_cur - y_prev);
	};
	writeFileAtomically(path, [&](const std::string& tmp) {
		mrpt::io::CFileGZOutputStream f;
		if (!f.open(tmp)) throw std::runtime_error(tmp + ": cannot open for writing");
		auto ar = mrpt::serialization::archiveFrom(f);
		constexpr std::size_t kChunk = 4096;  // as writeOdometryRawlog(traj, rates)
		RowSpill::Reader poses(spilled.odometry_poses);
		nav::Trajectory part;
		std::vector<double> part_rates;
		const auto flush = [&] {
			for (const auto& o : nav::makeOdometryObservations(part, part_rates)) ar << *o;
			part.clear(), part_rates.clear();
		};
		while (const double* p = poses.next())
		{
			nav::TrajectoryPoint q;
			q.t_s = p[0], q.x_m = p[1], q.y_m = p[2], q.yaw_rad = p[3];
			part.push_back(q);
			part_rates.push_back(rateAt(q.t_s));
			if (part.size() == kChunk) flush();
		}
		if (!part.empty()) flush();
		f.close();
	});
	return first_pose;
}

}  // namespace mrpt_fog::drift
