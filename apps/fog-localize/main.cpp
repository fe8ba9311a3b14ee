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
#include "LogInput.h"
#include "GyroOffOdometry.h"
#include "Localization.h"
#include "LocalizationErrors.h"
#include "LocalizeOutputs.h"
#include "Options.h"
#include "PipelineRate.h"
#include "Sensors.h"
#include "VariantOdometry.h"
#include "World.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt/system/filesystem.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/FieldOffset.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/CalibrationEarthRate.h>
#include <mrpt_fog_heading/DriveLog.h>
#include <mrpt_fog_heading/HeadingPipeline.h>
#include <mrpt_fog_heading/PowerSpans.h>
#include <mrpt_fog_nav/Rotation.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>

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
  Gyro off (power 0 rows: no gyro sample): each powered span is dead-reckoned alone; a filter
     step that touches a gyro-off stretch moves the particles by the wheel odometry alone
     (distance and the wheels' own heading change) under MRPT's default Gaussian model, what
     pf-localization applies to wheel odometry (--wheel-heading-deg-per-m, --wheel-heading-per-turn);
     at the turn-on the particles are re-drawn around a fix as at the start (--gyro-off-recovery
     refix, the default; 'none' goes on). Those scans are left out of the stretch figures and
     reported apart (gyro_off in --json), as fog-drift computes its figures on the powered spans.
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

}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-localize", [&]() -> int {
		TCLAP::CmdLine cmd("fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG "
						   "heading on a simulated world around a drive",
						   ' ', "0.1");
		app::InputArg arg_drive("", "drive", "drive rawlog (FOG, FOG_IDEAL, ODOMETRY, GROUND_TRUTH) "
															"[default: the bundled datasets/drive.rawlog]",
											   false, "", "F", cmd);
		app::InputArg arg_cal("", "cal", "calibration YAML [default: fitted here on --chamber and "
														"--ratetable (bias + scale factor), written to DIR/calibration.yaml]",
											 false, "", "CAL.yaml", cmd);
		app::InputArg arg_chamber("", "chamber", "chamber run for the fit when no --cal [default: the "
																"bundled datasets/chamber_A.rawlog]",
												 false, "", "F", cmd);
		app::InputArg arg_table("", "ratetable",
											   "rate-table run of the same gyro for the scale-factor fit when no --cal, "
											   "or 'none' (bias only) [default: the bundled datasets/ratetable_A.rawlog "
											   "if present, else none, said on stdout]",
											   false, "", "F|none", cmd);
		app::OutputDirArg arg_out("o", "out", "output folder [default: fog-localize-out]", false,
											 "fog-localize-out", "DIR", cmd);
		app::OutputArg arg_json("", "json", "write the figures as JSON", false, "", "F", cmd);
		app::CountArg arg_seeds(cmd, "seeds", "filter seeds per gyro", "filter runs", 1, 1000, 5);
		app::CountArg arg_seed0(cmd, "first-seed", "first filter seed", "seed", 0, 4294966295ull, 1, "S");
		app::CountArg arg_particles(cmd, "particles", "particles per filter", "particles", 10, 100000, 300);
		app::RealArg arg_period(cmd, "scan-period-s", "time between scans (and filter steps)", "s",
								app::Range::closed(0.1, 10), 1.0, "S");
		app::RealArg arg_bias(cmd, "fog-bias-dph", "motion model: FOG bias uncertainty the filter allows", "deg/h",
							  app::Range::closed(0, 1e4), 0.5, "DPH");
		app::RealArg arg_horizon(cmd, "fog-horizon-s",
								 "motion model: heading random walk per step = bias * sqrt(dt * horizon)", "s",
								 app::Range::closed(0, 1e6), 60.0, "S");
		app::RealArg arg_sf(cmd, "fog-scale-factor-ppm", "motion model: heading error per turned angle", "ppm",
							app::Range::closed(0, 1e5), 2000.0, "PPM");
		app::RealArg arg_pow(cmd, "pow-factor", "likelihood exponent of a scan (rays are not independent)", "1",
							 app::Range::aboveUpTo(0, 10), 1.0);
		app::RealArg arg_rough(cmd, "roughening-k",
							   "jitter after each resampling, std K * range * N^(-1/3) per dimension "
							   "(Gordon-Salmond-Smith 1993 roughening; 0 = off)",
							   "1", app::Range::closed(0, 10), 0.0, "K");
		app::CountArg arg_dec(cmd, "lf-decimation", "use every N-th laser ray in the likelihood", "rays", 1, 1000, 1);
		TCLAP::ValueArg<std::string> arg_fields("", "fields",
												"where the open fields go: 'turns' (the 3 most turning 4 km windows: "
												"the gyro's bias and its scale-factor error at each turn act) or "
												"'straights' (the 3 longest straights: the bias only; on the bundled "
												"drive the map-matching's entry error dominates there)",
												false, "turns", "turns|straights", cmd);
		app::RealArg arg_wheel_a3(cmd, "wheel-heading-deg-per-m",
								  "motion model where the gyro is off (power 0; the wheel odometry alone): heading std "
								  "per metre driven (MRPT's default Gaussian model's a3, what pf-localization applies "
								  "to wheel odometry)",
								  "deg/m", app::Range::closed(0, 90), 1.0, "DEG");
		app::RealArg arg_wheel_a4(cmd, "wheel-heading-per-turn",
								  "motion model where the gyro is off: heading std per turned angle (MRPT's default a4)",
								  "1", app::Range::closed(0, 10), 0.05);
		const char* const recovery_help =
			"at a turn-on after a gyro-off stretch: 'refix' re-draws the particles around a position and heading "
			"fix as at the start (the truth, standing for GNSS, as fog-drift re-aligns there), 'none' goes on "
			"from the wheel-only steps";
		TCLAP::ValueArg<std::string> arg_recovery("", "gyro-off-recovery", recovery_help, false, "refix", "refix|none",
												  cmd);
		TCLAP::SwitchArg arg_noscale("", "no-scale-calibration",
									 "do not calibrate the wheel odometry's distance scale on urban stretches", cmd);
		app::LogInput log_input(cmd, "fog-localize");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-localize", kHelp)) return *rc;
		const GyroOffRecovery recovery = gyroOffRecoveryFromString(arg_recovery.getValue());
		WorldOptions wopt;
		wopt.placement = fieldPlacementFromString(arg_fields.getValue());
		const auto t_start = std::chrono::steady_clock::now();

		const fs::path out = arg_out.getValue();
		fs::create_directories(out);
		const std::string drive_path =
			arg_drive.getValue().empty() ? (defaultDatasetsDir() / "drive.rawlog").string() : arg_drive.getValue();
		CalibrationRequest creq;
		creq.given_path = arg_cal.getValue();
		creq.read_options = log_input.options();
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
		const heading::DriveData drive = heading::readDrive(drive_path, {}, {}, log_input.options());
		if (!drive.fog_ideal) throw std::runtime_error(drive_path + ": no FOG_IDEAL stream (the ideal gyro is needed)");
		if (!drive.latitude_deg) throw std::runtime_error(drive_path + ": no latitude_deg in the FOG metadata");
		// Each gyro variant through its own heading pipeline (HeadingPipeline.h; VariantOdometry.h:
		// aligned from the truth at each powered span's start, its attitude dead-reckoned with the
		// wheel distances from the truth's position). The compensated one: thermistor screening,
		// the causal compensator, the calibration's field offset (fog-refine) and the calibration's
		// Earth rate added back (the Earth-rate rule, CalibrationEarthRate.h: the static
		// calibration absorbed it; the strapdown removes the drive's own). No standstill updates:
		// the filter is judged on the thermal model. Gyro-off stretches (power 0: no gyro sample;
		// GyroOffOdometry.h): each powered span is dead-reckoned alone, and the filter steps on the
		// wheel odometry where the gyro is off.
		heading::PipelineOptions popt;
		popt.latitude_deg = *drive.latitude_deg;
		popt.sampling = nav::RateSampling::IntervalAverage;  // fog-sim: mean over (t - dt, t]
		popt.alignment = heading::Alignment::ByCaller;
		popt.field_refinement = false;
		const auto powerOf = [&](const FogSeries& s) {
			heading::PowerSpanBuilder b;
			for (std::size_t k = 0; k < s.size(); k++) b.add(s.epoch_s + s.time_s[k], s.power.empty() ? NAN : s.power[k]);
			b.finish();
			if (b.powered().empty())
				throw std::runtime_error(drive_path + ": " + s.sensor_label + ": the gyro is off throughout");
			return b;
		};
		const heading::PowerSpanBuilder fog_power = powerOf(drive.fog);
		const auto uncalibrated = [&](const FogSeries& s, const heading::PowerSpanBuilder& power) {
			heading::HeadingPipeline pipe(s, popt, nullptr);
			return deadReckonPoweredSpans(pipe, s, power, drive, "", drive_path);
		};
		const auto compensated = [&]() {
			heading::PipelineOptions o = popt;
			o.field_offset = loadFieldOffset(cal_path);
			std::unique_ptr<heading::HeadingPipeline> pipe;
			try
			{
				pipe = std::make_unique<heading::HeadingPipeline>(drive.fog, o, &calib.cal);
			}
			catch (const std::exception& ex)
			{
				throw std::runtime_error(cal_path + ": cannot compensate the drive's FOG: " + ex.what());
			}
			const heading::CalibrationEarthRate& earth = pipe->earthRate();
			if (earth.bias_holds_earth_rate && earth.source == heading::LatitudeSource::Drive)
				std::printf("fog-localize: %s records no latitude: assuming the drive's %.4f deg\n", cal_path.c_str(),
							popt.latitude_deg);
			std::vector<nav::Trajectory> spans = deadReckonPoweredSpans(*pipe, drive.fog, fog_power, drive, cal_path, drive_path);
			app::reportPipelineCompensation(*pipe, calib.cal, o.screen_thermistors, !drive.fog.field_uT.empty());
			return spans;
		};
		std::vector<nav::Trajectory> comp_spans = compensated();  // its reports first, as before
		const std::vector<std::pair<std::string, std::vector<nav::Trajectory>>> gyros = {
			{"raw", uncalibrated(drive.fog, fog_power)},
			{"compensated", std::move(comp_spans)},
			{"ideal", uncalibrated(*drive.fog_ideal, powerOf(*drive.fog_ideal))}};

		// World and scans.
		LaserOptions lopt;
		const World world = buildWorld(drive.truth, wopt);
		double t0 = drive.truth.front().t_s, t1 = drive.truth.back().t_s;
		for (const auto& g : gyros)
		{
			t0 = std::max(t0, g.second.front().front().t_s);
			t1 = std::min(t1, g.second.back().back().t_s);
		}
		std::vector<double> scan_t;
		// Scans half a period after the start: times that are not whole seconds (pf-localization
		// reads a ground-truth file's first column as time only when it is not an integer).
		for (double t = t0 + 0.5 * arg_period.getValue(); t <= t1; t += arg_period.getValue()) scan_t.push_back(t);
		const auto scans = simulateScans(*world.grid, drive.truth, scan_t, lopt);
		MclOptions mopt;
		mopt.particles = arg_particles.get<unsigned>();
		mopt.motion.heading_bias_dph = arg_bias.getValue();
		mopt.motion.horizon_s = arg_horizon.getValue();
		mopt.motion.scale_factor_ppm = arg_sf.getValue();
		mopt.pow_factor = arg_pow.getValue();
		mopt.lf_decimation = arg_dec.get<unsigned>();
		mopt.roughening_k = arg_rough.getValue();
		mopt.calibrate_odometry_scale = !arg_noscale.getValue();
		mopt.wheel_only_motion.gaussianModel.a3 = arg_wheel_a3.getValue() * M_PI / 180.0;
		mopt.wheel_only_motion.gaussianModel.a4 = arg_wheel_a4.getValue();
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
		results.input_notices = log_input.json();
		results.calibration = calib;
		results.t0_s = t0;
		results.gyro_off = fog_power.stretches();
		results.gyro_off_recovery = recovery;
		for (const auto& g : results.gyro_off) results.gyro_off_overlap_s.push_back(overlapByKind(world.stretches, g.off_s, g.on_s));
		for (const auto& [name, spans] : gyros)
		{
			const ScanOdometry so = odometryAtScans(spans, drive.odometry, scan_t, start);
			const auto& odo = so.poses;
			GyroResult gr;
			gr.name = name;
			gr.odometry_step = so.step;
			// the turn-ons: the first scan of a powered span after a wheel-only step
			std::vector<Refix> refixes;
			if (recovery == GyroOffRecovery::Refix)
				for (std::size_t k = 1; k + 1 < scan_t.size(); ++k)
					if (so.step[k] == StepSource::WheelOnly && so.step[k + 1] == StepSource::Gyro)
					{
						const nav::TrajectoryPoint p = nav::interpolate(drive.truth, scan_t[k]);
						refixes.push_back({k, mrpt::poses::CPose2D(p.x_m, p.y_m, p.yaw_rad)});
					}
			gr.refixes = refixes.size();
			for (unsigned s = 0; s < arg_seeds.get<unsigned>(); ++s)
			{
				const unsigned seed = arg_seed0.get<unsigned>() + s;
				const MclRun run = runMcl(world, scans, scan_t, odo, so.step, refixes, start, mopt, seed);
				gr.runs.push_back(computeErrors(run, drive.truth, world.stretches));
				gr.seeds.push_back(seed);
				gr.final_scale.push_back(run.odometry_scale.back());
				if (s == 0) gr.first_run = run;
			}
			gr.summary = summarize(gr.runs, world.stretches);
			gr.wheel_only = wheelOnlyFigures(gr.runs);
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
		printSummary(results, world, mopt.wheel_only_motion.gaussianModel);
		writeOutputs(out.string(), arg_json.getValue(), results, world, scans, scan_t, drive.truth, mopt, lopt);
		return 0;
	});
}
