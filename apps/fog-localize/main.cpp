/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading.
 *
 *   fog-localize [--drive F] [--cal CAL.yaml] [--out DIR] [--json F] [--seeds N]
 *
 * Builds a world around the drive's true route (World.h), simulates laser scans with MRPT,
 * builds the odometry of each gyro (wheel distance + raw / compensated / ideal FOG heading, as
 * fog-drift does), runs MRPT's Monte Carlo localization for each gyro over several filter
 * seeds, and reports the position and heading error per stretch kind; the open (observation-
 * poor) stretches are where the FOG is judged. */
#include "AppMain.h"
#include "CalibrationChoice.h"
#include "CommandLine.h"
#include "Compensation.h"
#include "DriveData.h"
#include "HeadingDeadReckoning.h"
#include "Localization.h"
#include "LocalizationErrors.h"
#include "LocalizeOutputs.h"
#include "Sensors.h"
#include "World.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/filesystem.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/Rotation.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

using namespace mrpt_fog;
using namespace mrpt_fog::localize;
namespace fs = std::filesystem;

namespace
{
const char* const kHelp = R"(
What it does
  0. Calibration of the compensated gyro: --cal as given; without it, fitted here as
     `fog-calibrate -i CHAMBER -i RATETABLE --model multipoint` does: the bias on the static
     samples, the scale factor vs temperature on the rate-table run's table segments. The drive
     turns, and a bias-only calibration leaves the scale factor's heading error at every turn
     in the compensated gyro: without a rate-table run (--ratetable none, or no bundled
     datasets/ratetable_A.rawlog) the fit is bias only and fog-localize says so. The
     calibration used is printed and recorded in --json (calibration.{path, source,
     fitted_on, bias_model, scale_factor, description}).
  1. World: an occupancy grid (2 m cells) around the drive's true route. Urban stretches have
     building facades both sides; 3 open fields (nothing in laser range) lie on the route's 3
     most turning 4 km windows (--fields turns, the default) or on its 3 longest straights
     (--fields straights: >= 2 km, 800 m of urban road kept at both ends); the longest
     remaining straight holds a 1.5 km tunnel (walls 6 m either side). Written as
     map.gridmap.gz (pf-localization's map_file) and map.png.
  2. Sensor: a 360 deg laser (181 rays, 60 m, 5 cm noise) simulated with MRPT's
     COccupancyGridMap2D::laserScanSimulator at the true pose, one scan per --scan-period-s.
  3. Odometry per gyro: wheel distance + heading integrated from the raw, compensated and
     ideal FOG (Earth rate removed, as fog-drift), dead-reckoned from the true start.
  4. MRPT's CMonteCarloLocalization2D (CParticleFilter, standard proposal) with a Gaussian
     motion model whose heading noise is a FOG's (bias uncertainty and scale-factor terms, no
     per-metre heading noise) and an online odometry-scale calibration on urban stretches; the
     same filter for every gyro; --seeds filter seeds per gyro (the world and the scans are the
     same for all).
  5. Errors against the truth per scan; RMS per stretch kind pooled over seeds; worst open
     stretch; divergence = > 10 m error in an urban stretch 60 s after its start.
  Heading matters only where the map does not fix it: in urban stretches and in the tunnel the
  laser fixes heading (the tunnel's walls fix heading and lateral position, not the position
  along the road); the open stretches are the figure of merit (position_rms_m in --json).
  6. Whether the open fields can judge the gyro (heading_relevance in --json): per field, the
     raw gyro's heading drift over it against the heading error the map-matching leaves at its
     entry (ideal gyro); over the fields, the ideal gyro's position RMS / the raw one's, the
     best any compensation could reach. Above 0.5 it prints CANNOT TELL: the map-matching, not
     the gyro, sets the error (on the bundled drive's straights the ideal gyro gives 0.86x raw).

Outputs in --out: map.gridmap.gz, map.png, localize_<gyro>.rawlog (actions-observations:
  CActionRobotMovement2D with the FOG motion model + CSensoryFrame with the scan),
  pf-localization_<gyro>.ini (runs MRPT's pf-localization app on them), ground_truth.txt,
  errors.png (position and heading error vs time, open stretches shaded), localize.json.

Examples
  fog-localize --out loc --json loc.json                       # bundled drive, calibration fitted on chamber A + rate table A
  fog-localize --ratetable none --out loc_bias --json b.json   # the same with a bias-only calibration
  fog-localize --drive datasets/drive.rawlog --cal cal.yaml --seeds 10 --out loc
)";

fs::path defaultDatasetsDir()
{
	if (fs::exists("datasets/drive.rawlog")) return "datasets";
	return fs::path(MRPT_FOG_SOURCE_DIR) / "datasets";
}

/** Pose of a dead-reckoned trajectory at each time (linear / shortest-arc interpolation). */
std::vector<mrpt::poses::CPose2D> posesAt(const nav::Trajectory& traj, const std::vector<double>& t)
{
	std::vector<mrpt::poses::CPose2D> out;
	out.reserve(t.size());
	for (double tk : t)
	{
		const nav::TrajectoryPoint p = nav::interpolate(traj, tk);
		out.emplace_back(p.x_m, p.y_m, p.yaw_rad);
	}
	return out;
}
}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-localize", [&]() -> int {
		TCLAP::CmdLine cmd("fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG "
						   "heading on a simulated world around a drive",
						   ' ', "0.1");
		TCLAP::ValueArg<std::string> arg_drive("", "drive", "drive rawlog (FOG, FOG_IDEAL, ODOMETRY, GROUND_TRUTH) "
															"[default: the bundled datasets/drive.rawlog]",
											   false, "", "F", cmd);
		TCLAP::ValueArg<std::string> arg_cal("", "cal", "calibration YAML [default: fitted here on --chamber and "
														"--ratetable (bias + scale factor), written to DIR/calibration.yaml]",
											 false, "", "CAL.yaml", cmd);
		TCLAP::ValueArg<std::string> arg_chamber("", "chamber", "chamber run for the fit when no --cal [default: the "
																"bundled datasets/chamber_A.rawlog]",
												 false, "", "F", cmd);
		TCLAP::ValueArg<std::string> arg_table("", "ratetable",
											   "rate-table run of the same gyro for the scale-factor fit when no --cal, "
											   "or 'none' (bias only) [default: the bundled datasets/ratetable_A.rawlog "
											   "if present, else none, said on stdout]",
											   false, "", "F|none", cmd);
		TCLAP::ValueArg<std::string> arg_out("o", "out", "output folder [default: fog-localize-out]", false,
											 "fog-localize-out", "DIR", cmd);
		TCLAP::ValueArg<std::string> arg_json("", "json", "write the figures as JSON", false, "", "F", cmd);
		TCLAP::ValueArg<unsigned> arg_seeds("", "seeds", "filter seeds per gyro (>= 1)", false, 5, "N", cmd);
		TCLAP::ValueArg<unsigned> arg_seed0("", "first-seed", "first filter seed", false, 1, "S", cmd);
		TCLAP::ValueArg<unsigned> arg_particles("", "particles", "particles per filter", false, 300, "N", cmd);
		TCLAP::ValueArg<double> arg_period("", "scan-period-s", "time between scans (and filter steps) [s]", false, 1.0,
										   "S", cmd);
		TCLAP::ValueArg<double> arg_bias("", "fog-bias-dph",
										 "motion model: FOG bias uncertainty the filter allows [deg/h]", false, 0.5,
										 "DPH", cmd);
		TCLAP::ValueArg<double> arg_horizon("", "fog-horizon-s",
											"motion model: heading random walk per step = bias * sqrt(dt * horizon) [s]",
											false, 60.0, "S", cmd);
		TCLAP::ValueArg<double> arg_sf("", "fog-scale-factor-ppm",
									   "motion model: heading error per turned angle [ppm]", false, 2000.0, "PPM", cmd);
		TCLAP::ValueArg<double> arg_pow("", "pow-factor", "likelihood exponent of a scan (rays are not independent)",
										false, 1.0, "X", cmd);
		TCLAP::ValueArg<double> arg_rough("", "roughening-k",
										  "jitter after each resampling, std K * range * N^(-1/3) per dimension "
										  "(Gordon-Salmond-Smith 1993 roughening; 0 = off)",
										  false, 0.0, "K", cmd);
		TCLAP::ValueArg<unsigned> arg_dec("", "lf-decimation", "use every N-th laser ray in the likelihood", false, 1,
										  "N", cmd);
		TCLAP::ValueArg<std::string> arg_fields("", "fields",
												"where the open fields go: 'turns' (the 3 most turning 4 km windows: "
												"the gyro's bias and its scale-factor error at each turn act) or "
												"'straights' (the 3 longest straights: the bias only; on the bundled "
												"drive the map-matching's entry error dominates there)",
												false, "turns", "turns|straights", cmd);
		TCLAP::SwitchArg arg_noscale("", "no-scale-calibration",
									 "do not calibrate the wheel odometry's distance scale on urban stretches", cmd);
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-localize", kHelp)) return *rc;
		if (arg_seeds.getValue() < 1) throw std::runtime_error("--seeds: must be >= 1");
		if (!(arg_rough.getValue() >= 0)) throw std::runtime_error("--roughening-k: must be >= 0");
		if (arg_particles.getValue() < 10) throw std::runtime_error("--particles: must be >= 10");
		if (!(arg_period.getValue() >= 0.1 && arg_period.getValue() <= 10))
			throw std::runtime_error("--scan-period-s: must be within [0.1, 10] s");
		WorldOptions wopt;
		wopt.placement = fieldPlacementFromString(arg_fields.getValue());
		const auto t_start = std::chrono::steady_clock::now();

		const fs::path out = arg_out.getValue();
		fs::create_directories(out);
		const std::string drive_path =
			arg_drive.getValue().empty() ? (defaultDatasetsDir() / "drive.rawlog").string() : arg_drive.getValue();
		CalibrationRequest creq;
		creq.given_path = arg_cal.getValue();
		if (creq.given_path.empty())
		{
			creq.chamber_path = arg_chamber.getValue().empty() ? (defaultDatasetsDir() / "chamber_A.rawlog").string()
															   : arg_chamber.getValue();
			if (arg_table.getValue() == "none")
				creq.ratetable_path.reset();
			else if (!arg_table.getValue().empty())
				creq.ratetable_path = arg_table.getValue();
			else if (const fs::path t = defaultDatasetsDir() / "ratetable_A.rawlog"; fs::exists(t))
				creq.ratetable_path = t.string();
			else
				std::printf("fog-localize: no rate-table run (%s): the calibration models the bias only\n", t.c_str());
			creq.write_path = (out / "calibration.yaml").string();
		}
		else if (!arg_chamber.getValue().empty() || !arg_table.getValue().empty())
			throw std::runtime_error("--chamber/--ratetable choose the runs of a fit: not with --cal");
		const CalibrationChoice calib = chooseCalibration(creq);
		const std::string& cal_path = calib.path;
		std::printf("fog-localize: calibration %s\n", describeCalibration(calib).c_str());

		// Drive, gyro variants (as fog-drift), truth.
		const drift::DriveData drive = drift::readDrive(drive_path);
		if (!drive.fog_ideal) throw std::runtime_error(drive_path + ": no FOG_IDEAL stream (the ideal gyro is needed)");
		if (!drive.latitude_deg) throw std::runtime_error(drive_path + ": no latitude_deg in the FOG metadata");
		drift::HeadingOptions hopt;
		hopt.latitude_deg = *drive.latitude_deg;
		// The Earth rate the calibration's bias absorbed, at the latitude the file records (a file
		// without one is taken as made at the drive's latitude).
		const Calibration& cal_file = calib.cal;
		double cal_earth_dph = 0.0;
		if (cal_file.earth_rate == EarthRateHandling::InBias)
		{
			const double cal_lat_deg = std::isfinite(cal_file.latitude_deg) ? cal_file.latitude_deg : hopt.latitude_deg;
			if (!std::isfinite(cal_file.latitude_deg))
				std::printf("fog-localize: %s records no latitude: assuming the drive's %.4f deg\n", cal_path.c_str(),
							hopt.latitude_deg);
			cal_earth_dph = units::kEarthRate_dph * std::sin(cal_lat_deg * units::kDegToRad);
		}
		std::vector<double> comp = drift::compensatedRate_dph(drive.fog, calib.cal, cal_path, true);
		for (double& r : comp) r += cal_earth_dph;  // the static calibration absorbed it: removed once, by the strapdown
		const std::vector<double> t_fog = drift::absoluteTimes(drive.fog);
		const std::vector<std::pair<std::string, nav::Trajectory>> gyros = {
			{"raw", drift::deadReckonVariant(t_fog, drive.fog.rate_dph[2], drive, hopt).trajectory},
			{"compensated", drift::deadReckonVariant(t_fog, comp, drive, hopt).trajectory},
			{"ideal", drift::deadReckonVariant(drift::absoluteTimes(*drive.fog_ideal), drive.fog_ideal->rate_dph[2], drive,
											   hopt)
						  .trajectory}};

		// World and scans.
		LaserOptions lopt;
		const World world = buildWorld(drive.truth, wopt);
		double t0 = drive.truth.front().t_s, t1 = drive.truth.back().t_s;
		for (const auto& g : gyros)
		{
			t0 = std::max(t0, g.second.front().t_s);
			t1 = std::min(t1, g.second.back().t_s);
		}
		std::vector<double> scan_t;
		// Scans half a period after the start: times that are not whole seconds (pf-localization
		// reads a ground-truth file's first column as time only when it is not an integer).
		for (double t = t0 + 0.5 * arg_period.getValue(); t <= t1; t += arg_period.getValue()) scan_t.push_back(t);
		const auto scans = simulateScans(*world.grid, drive.truth, scan_t, lopt);
		MclOptions mopt;
		mopt.particles = arg_particles.getValue();
		mopt.motion.heading_bias_dph = arg_bias.getValue();
		mopt.motion.horizon_s = arg_horizon.getValue();
		mopt.motion.scale_factor_ppm = arg_sf.getValue();
		mopt.pow_factor = arg_pow.getValue();
		mopt.lf_decimation = arg_dec.getValue();
		mopt.roughening_k = arg_rough.getValue();
		mopt.calibrate_odometry_scale = !arg_noscale.getValue();
		if (!(mopt.motion.heading_bias_dph > 0) || !(mopt.motion.horizon_s > 0) || !(mopt.motion.scale_factor_ppm >= 0) ||
			!(mopt.pow_factor > 0 && mopt.pow_factor <= 1) || mopt.lf_decimation < 1)
			throw std::runtime_error("motion/likelihood options: bias and horizon > 0, scale factor >= 0, pow-factor in "
									 "(0, 1], lf-decimation >= 1");
		applyLikelihoodOptions(*world.grid, mopt, lopt.range_m);
		const nav::TrajectoryPoint p0 = nav::interpolate(drive.truth, scan_t.front());
		const mrpt::poses::CPose2D start(p0.x_m, p0.y_m, p0.yaw_rad);

		std::printf("fog-localize: %s: %.0f s, %.1f km; world: %zu stretches, %zu scans\n", drive_path.c_str(), t1 - t0,
					world.route_length_m / 1000.0, world.stretches.size(), scans.size());
		for (const auto& s : world.stretches)
			std::printf("  %-7s %7.0f - %7.0f s  %6.2f - %6.2f km\n", stretchKindName(s.kind), s.t_begin_s - t0,
						s.t_end_s - t0, s.s_begin_m / 1000, s.s_end_m / 1000);

		LocalizeResults results;
		results.drive = drive_path;
		results.calibration = calib;
		results.t0_s = t0;
		for (const auto& [name, traj] : gyros)
		{
			const auto odo = posesAt(traj, scan_t);
			GyroResult gr;
			gr.name = name;
			for (unsigned s = 0; s < arg_seeds.getValue(); ++s)
			{
				const unsigned seed = arg_seed0.getValue() + s;
				const MclRun run = runMcl(world, scans, scan_t, odo, start, mopt, seed);
				gr.runs.push_back(computeErrors(run, drive.truth, world.stretches));
				gr.seeds.push_back(seed);
				gr.final_scale.push_back(run.odometry_scale.back());
				if (s == 0) gr.first_run = run;
			}
			gr.summary = summarize(gr.runs, world.stretches);
			std::vector<double> odo_err_deg;
			for (std::size_t k = 0; k < scan_t.size(); ++k)
				odo_err_deg.push_back(nav::wrapToPi(odo[k].phi() - nav::interpolate(drive.truth, scan_t[k]).yaw_rad) * 180.0 / M_PI);
			gr.heading_budget = headingBudget(gr.runs, world.stretches, odo_err_deg);
			gr.odometry = odo;
			results.gyros.push_back(std::move(gr));
		}
		{
			const GyroResult& raw = results.gyros.front();
			const GyroResult& ideal = results.gyros.back();
			results.relevance = headingRelevance(raw.summary, raw.heading_budget, ideal.summary, ideal.heading_budget);
		}
		results.runtime_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t_start).count();
		printSummary(results, world);
		writeOutputs(out.string(), arg_json.getValue(), results, world, scans, scan_t, drive.truth, mopt, lopt);
		return 0;
	});
}
