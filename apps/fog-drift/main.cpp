/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a vehicle drive.
 *
 *   fog-drift -i DRIVE.rawlog --cal CAL.yaml [--json F] [--plots DIR] [--odometry-out F.rawlog]
 *
 * Reads the drive (FOG "FOG" with thermal error, "FOG_IDEAL" without, wheel odometry
 * "ODOMETRY", truth "GROUND_TRUTH"), compensates "FOG" with the calibration, integrates the
 * heading of each gyro (Earth rate at the drive's latitude removed) with the odometry, and
 * compares the three dead-reckoned trajectories with the truth. */
#include "AppMain.h"
#include "LogInput.h"
#include "CommandLine.h"
#include "Options.h"
#include "DriftOutputs.h"
#include "DriveData.h"
#include "DriveEvaluation.h"
#include "VariantPipeline.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_nav/DriftReport.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/FieldOffset.h>
#include <mrpt_fog_heading/CalibrationEarthRate.h>
#include <mrpt_fog_heading/HeadingWithoutTruth.h>
#include <mrpt_fog_nav/StandstillDetector.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#ifdef __GLIBC__
#include <malloc.h>
#endif

using namespace mrpt_fog;

namespace
{
const char* const kHelp = R"(
WHAT IT SHOWS
  Each gyro (raw, compensated with --cal, ideal = the same noise without thermal error) is
  integrated to a heading (Earth rate at the drive's latitude removed) and dead-reckoned with
  the wheel odometry; the heading and position errors against the truth give, per gyro:
    heading_error_rms_deg            RMS of the heading error over the drive (the headline)
    heading_error_max_deg / final    largest and last |error| (a drive ending in a turn reads
                                     the gyro's lag in the final value: do not judge by it alone)
    heading_drift_between_turns_dph  common slope of the error on the straights (each straight
                                     keeps its own offset): the residual bias
    turn_scale_factor_ppm            error each turn adds per degree turned (drift removed):
                                     the scale-factor error the turns expose
  Turns and straights are found on the truth's yaw rate (> 1 deg/s turn, < 0.2 deg/s for
  >= 30 s straight).

GYRO OFF (power 0 rows: an empty rate, or any value, which is no measurement)
  What the vehicle turned while the gyro was off cannot be known from the gyro. Each powered
  span is navigated as a drive of its own: at its start (the turn-on) heading and position
  are re-aligned from the truth, as at the start of the drive, and every figure above is
  computed on the powered spans only (straights are cut at the stretches, turns overlapping
  one are left out; "final" is the last span's). The stretches are listed with the truth's
  heading change over each (what no gyro saw); JSON: gyro_off. The compensator restarts its
  warm-up term at each turn-on.

THREE-AXIS FOG (a triad: rate_x/y/z_dph, fog-sim --profile drive --triad)
  With a calibration of all three axes (or none), each gyro variant runs the 3-D strapdown
  (ThreeAxis: the full Earth rate removed, started from the true attitude); the heading
  figures above then come from its yaw, and per variant it adds the roll and pitch errors
  (RMS, max, final) and per axis the thermal error left, RMS of the 100 s means of
  (gyro - ideal) [deg/h]
  (JSON: three_axis). The calibration must not hold the Earth rate of its mount
  (earth_rate handling in_table_rate: fog-calibrate on runs stating earth_rate_dph.<axis>).
  A calibration of z alone: the vertical gyro alone, as for a single-axis FOG.

SEVERAL DRIVES
  Repeat -i: every drive's figures, then the median, quartiles and range of each figure and of
  the ratios compensated/raw (heading RMS, drift between turns) and compensated/ideal (heading
  RMS). Drives to try: fog-sim --profile drive --seed N [--cabin PRESET|FILE.yaml]
  (scripts/drift_over_drives.sh makes a set and runs this).

FIELD REFINEMENT (compensated single-axis gyro; on by default, --no-field-refinement)
  No chamber calibration holds the offset a FOG picks at each turn-on, nor its aging. While the
  vehicle stands still (wheels stopped and the gyro sees no rotation: --standstill-source) the
  compensated rate should read the vertical Earth rate; a Kalman filter of the offset (prior:
  0 +- the calibration's held-out stability and --turn-on-repeatability-dph combined; noise:
  --gyro-arw-deg-rt-h, --gyro-bias-instability-dph) takes what it reads beyond that and
  subtracts its estimate from every later sample (causal), once the estimate differs from the
  prior by more than --significance-sigma (3) of its sigma: a calibration the standstills do
  not contradict is left alone (0: the plain filter, always). The first and last second of each
  standstill are left out; a standstill shorter than --min-standstill-s, or too short to beat
  what is known, changes nothing. A drive without a standstill is not changed (the output says
  so). JSON: field_refinement (each update, the offset and its 1-sigma).

EXAMPLES
  fog-drift -i datasets/drive.rawlog --cal cal.yaml --json drift.json --csv drift.csv --plots plots/
  fog-drift -i d1.rawlog -i d2.rawlog -i d3.rawlog --cal cal.yaml --json drives.json
)";

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
#ifdef __GLIBC__
	// Whole-drive vectors (tens of MB each, made and freed per gyro variant) in their own
	// mappings, returned to the system when freed: glibc's adaptive threshold would otherwise
	// move them to the heap, whose fragments stay resident (peak RSS 431 -> 323 MB on a 423 k
	// sample drive).
	mallopt(M_MMAP_THRESHOLD, 256 * 1024);
#endif
	return app::runApp("fog-drift", [&] {
		TCLAP::CmdLine cmd("fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive", ' ',
						   "0.1");
		app::InputMultiArg in("i", "input",
										"drive rawlog (FOG, FOG_IDEAL, ODOMETRY, GROUND_TRUTH); repeat for several "
										"drives: then each drive's figures and their median, quartiles and range",
										true, "DRIVE.rawlog", cmd);
		app::InputArg cal("", "cal", "calibration YAML for the FOG (fog-calibrate); without it the "
														"compensated variant is left out",
										 false, "", "CAL.yaml", cmd);
		app::OutputArg json("", "json", "write the drift figures as JSON", false, "", "F.json", cmd);
		app::OutputArg csv("", "csv",
										 "write the per-sample heading and position errors of each gyro (one drive)",
										 false, "", "F.csv", cmd);
		app::OutputDirArg plots("", "plots", "write trajectories.png and heading_error.png here (one drive)",
										   false, "", "DIR", cmd);
		app::OutputArg odo_out("", "odometry-out",
											 "write the compensated (else raw) dead-reckoned trajectory as a rawlog of "
											 "CObservationOdometry + CObservationIMU for pf-localization (one drive)",
											 false, "", "F.rawlog", cmd);
		app::RealArg lat(cmd, "latitude-deg", "latitude (default: from the drive's metadata)", "deg",
						 app::Range::closed(-90, 90), NAN, "DEG");
		app::RealArg cal_lat(cmd, "cal-latitude-deg",
							 "latitude of the calibration runs (default: the calibration file's latitude_deg, else the "
							 "drive's): a static calibration's bias absorbs the vertical Earth rate there, which the "
							 "compensator then removes; fog-drift adds it back before its own Earth-rate removal so "
							 "that it is not removed twice",
							 "deg", app::Range::closed(-90, 90), NAN, "DEG");
		TCLAP::SwitchArg cal_no_earth("", "cal-no-earth-rate",
									  "the calibration runs' table rate already included the Earth rate (their bias "
									  "does not contain it; a version 2 file says so itself: earth_rate.handling)",
									  cmd);
		TCLAP::SwitchArg transport("", "transport-rate",
								   "also remove the vertical transport rate (for real drives over the curved Earth; "
								   "the simulator's drive is flat-Earth)",
								   cmd);
		TCLAP::ValueArg<std::string> sampling("", "rate-sampling",
											  "gyro samples are the mean rate over the preceding interval ('average', "
											  "digital FOGs and fog-sim) or 'instantaneous' (trapezoid rule)",
											  false, "average", "KIND", cmd);
		TCLAP::SwitchArg no_screen("", "no-screening",
								   "do not screen the FOG's thermistor readings (stuck / spike / out of range -> "
								   "dropout, fallback model) before compensating",
								   cmd);
		TCLAP::SwitchArg no_refine("", "no-field-refinement",
								   "do not update the compensated gyro's bias offset at standstills (the thermal "
								   "model alone)",
								   cmd);
		app::RealArg turn_on_rep(cmd, "turn-on-repeatability-dph",
								 "1-sigma turn-on to turn-on repeatability of the bias offset: with the calibration's "
								 "held-out stability it is the prior of the standstill updates",
								 "deg/h", app::Range::aboveUpTo(0, 1e4), 1.0, "DPH");
		app::RealArg arw(cmd, "gyro-arw-deg-rt-h", "angle random walk of the gyro (the standstill measurement's noise)",
						 "deg/sqrt(h)", app::Range::aboveUpTo(0, 100), 0.001, "N");
		app::RealArg bias_inst(cmd, "gyro-bias-instability-dph", "bias instability of the gyro (not taken for the offset)",
							   "deg/h", app::Range::closed(0, 1e4), 0.005, "B");
		TCLAP::ValueArg<std::string> still_src("", "standstill-source",
											   "what tells a standstill: 'both' (wheels stopped and the gyro sees no "
											   "rotation), 'odometry' or 'gyro'",
											   false, "both", "SRC", cmd);
		app::RealArg min_still(cmd, "min-standstill-s", "shortest standstill used for an update (plus 1 s left out at each end)",
							   "s", app::Range::closed(0, 86400), 10.0, "S");
		app::RealArg signif(cmd, "significance-sigma",
							"apply the standstill estimate once it differs from the prior by more than this many of its "
							"sigma (0: always, the plain Kalman filter)",
							"sigma", app::Range::closed(0, 100), 3.0, "K");
		TCLAP::SwitchArg quiet("q", "quiet", "no progress line on stderr while a drive is read", cmd);
		TCLAP::SwitchArg in_memory("", "in-memory",
								   "hold the whole drive in memory, as --plots, "
								   "--transport-rate and a triad FOG do (otherwise a single-axis drive is read twice "
								   "and streamed: memory does not grow with the drive; the same figures)",
								   cmd);
		app::LogInput log_input(cmd, "fog-drift");
		TCLAP::ValueArg<std::string> fog_label("", "fog-label", "label of the CObservationFOG", false, "FOG", "L", cmd);
		TCLAP::ValueArg<std::string> odo_label("", "odometry-label", "label of the CObservationOdometry", false,
											   "ODOMETRY", "L", cmd);
		TCLAP::ValueArg<std::string> truth_label("", "truth-label", "label of the CObservationRobotPose truth", false,
												 "GROUND_TRUTH", "L", cmd);
		app::RealArg gps_speed(cmd, "gps-min-speed-mps", "without truth: GPS course over ground used above this speed",
							   "m/s", app::Range::closed(0, 1000), 5.0, "MPS");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-drift", kHelp)) return *rc;

		drift::DriveSettings st;
		if (sampling.getValue() == "instantaneous") st.heading.sampling = nav::RateSampling::Instantaneous;
		else if (sampling.getValue() == "average") st.heading.sampling = nav::RateSampling::IntervalAverage;
		else throw std::runtime_error("--rate-sampling: '" + sampling.getValue() + "' is not instantaneous|average");
		st.heading.transport_rate = transport.getValue();
		st.cal_path = cal.getValue();
		st.read_options = log_input.options();
		if (std::isfinite(lat.getValue())) st.latitude_deg = lat.getValue();
		if (std::isfinite(cal_lat.getValue())) st.cal_latitude_deg = cal_lat.getValue();
		st.cal_no_earth_rate = cal_no_earth.getValue();
		st.screen_thermistors = !no_screen.getValue();
		st.quiet = quiet.getValue();
		st.keep_series = !csv.getValue().empty();
		st.in_memory = in_memory.getValue();
		st.labels.fog = fog_label.getValue();
		st.labels.odometry = odo_label.getValue();
		st.labels.truth = truth_label.getValue();
		st.refinement.enabled = !no_refine.getValue();
		st.refinement.turn_on_repeatability_dph = turn_on_rep.getValue();
		st.refinement.noise.arw_deg_rt_h = arw.getValue();
		st.refinement.noise.bias_instability_dph = bias_inst.getValue();
		st.refinement.min_still_s = min_still.getValue();
		st.refinement.significance_sigma = signif.getValue();
		if (still_src.getValue() == "both") st.refinement.standstill.source = nav::StandstillSource::OdometryAndGyro;
		else if (still_src.getValue() == "odometry") st.refinement.standstill.source = nav::StandstillSource::Odometry;
		else if (still_src.getValue() == "gyro") st.refinement.standstill.source = nav::StandstillSource::Gyro;
		else throw std::runtime_error("--standstill-source: '" + still_src.getValue() + "' is not both|odometry|gyro");
		// The trajectories the outputs draw or write are kept; the others go once measured.
		st.keep_trajectories = !plots.getValue().empty()  ? drift::KeptTrajectories::All
							   : !odo_out.getValue().empty() ? drift::KeptTrajectories::ForOdometry
															 : drift::KeptTrajectories::None;
		const auto& inputs = in.getValue();
		if (inputs.size() > 1 && (!plots.getValue().empty() || !odo_out.getValue().empty() || !csv.getValue().empty()))
			throw std::runtime_error("--plots, --csv and --odometry-out take one drive (-i given " +
									 std::to_string(inputs.size()) + " times)");

		std::vector<drift::DriveEvaluation> evals;
		std::vector<std::map<std::string, double>> tables;
		for (const auto& path : inputs)
		{
			drift::DriveEvaluation e;
			try
			{
				e = drift::evaluateDrive(path, st);
			}
			catch (const drift::NoTruthError& err)
			{
				// A vehicle's own log: what can be known without a truth
				if (inputs.size() > 1 || st.cal_path.empty() || !plots.getValue().empty() || !csv.getValue().empty() ||
					!odo_out.getValue().empty())
					throw std::runtime_error(std::string(err.what()) +
											 " (without a truth fog-drift compares the compensated with the raw heading: "
											 "give one drive and --cal, without --plots, --csv or --odometry-out)");
				heading::NoTruthOptions nt;
				nt.fog_label = st.labels.fog;
				// the compensated variant's rules, as with a truth (VariantPipeline.h)
				heading::HeadingOptions h = st.heading;
				h.latitude_deg = st.latitude_deg ? *st.latitude_deg : NAN;  // NaN: the FOG's metadata
				nt.pipeline = drift::compensatedOptionsFor(st, h, st.refinement.enabled, loadFieldOffset(st.cal_path));
				nt.gps_min_speed_mps = gps_speed.getValue();
				const CalibrationSet cals = loadCalibrationSet(st.cal_path);
				const Calibration* zcal = cals.forAxis(GyroAxis::Z);
				if (!zcal) throw std::runtime_error(st.cal_path + ": no calibration for axis z (the heading gyro)");
				const heading::NoTruthReport r = heading::compareHeadingsWithoutTruth(path, *zcal, nt);
				std::fputs(drift::noTruthText(path, r).c_str(), stdout);
				if (!json.getValue().empty()) writeTextFileAtomically(json.getValue(), drift::noTruthJson(path, r).dump());
				return app::kExitOk;
			}
			const nav::DriftReport& rep = e.report;
			std::printf("fog-drift: %s: %.0f s, %.1f m driven, latitude %.4f deg (Earth rate %.4f deg/h removed)\n",
						path.c_str(), rep.duration_s, rep.distance_m, e.latitude_deg,
						heading::verticalEarthRate_dph(e.latitude_deg));
			for (const auto& note : e.option_conflicts) std::printf("  note: %s\n", note.c_str());
			std::printf("  %zu turns (%.0f deg turned), %zu straights (%.0f s) found on the truth\n", e.segments.turns.size(),
						e.figures.begin()->second.turned_deg, e.segments.straights.size(),
						e.figures.begin()->second.straight_time_s);
			if (!e.gyro_off.empty()) std::fputs(drift::gyroOffText(e).c_str(), stdout);
			if (!cal.getValue().empty())
				std::fputs((st.refinement.enabled ? drift::refinementText(e.refinement, e.drive.fog.epoch_s)
												  : std::string("  field refinement: off (--no-field-refinement)\n"))
							   .c_str(),
						   stdout);
			std::printf("  %-12s %10s %10s %10s %14s %12s %12s\n", "gyro", "hdg RMS", "hdg max", "hdg final",
						"drift betw.", "turn SF", "pos final");
			std::printf("  %-12s %10s %10s %10s %14s %12s %12s\n", "", "[deg]", "[deg]", "[deg]", "turns [deg/h]", "[ppm]",
						"[m]");
			for (const auto& v : rep.variants)
			{
				const auto& f = e.figures.at(v.name);
				std::printf("  %-12s %10.4f %10.4f %10.4f %14.4f %12.1f %12.2f\n", v.name.c_str(), f.heading_error_rms_deg,
							f.heading_error_max_deg, f.heading_error_final_deg, f.heading_drift_between_turns_dph,
							f.turn_scale_factor_ppm, v.position_error_final_m);
			}
			if (!e.three_axis_note.empty()) std::printf("  triad FOG: %s\n", e.three_axis_note.c_str());
			if (e.three_axis)
			{
				std::printf("  3-D strapdown (triad x, y, z; full Earth rate removed): attitude errors [deg] and thermal "
							"error left per axis (RMS of 100 s means of gyro - ideal) [deg/h]\n");
				std::printf("  %-12s %10s %10s %10s %10s %10s %10s %10s %10s %10s\n", "gyro", "roll RMS", "roll max",
							"roll fin.", "pitch RMS", "pitch max", "pitch fin.", "x [dph]", "y [dph]", "z [dph]");
				for (const auto& v : rep.variants)
				{
					const auto& a = e.attitude.at(v.name);
					const auto it = e.rate_error_rms_dph.find(v.name);
					const auto cell = [&](std::size_t i) { return it == e.rate_error_rms_dph.end() ? NAN : it->second[i]; };
					std::printf("  %-12s %10.5f %10.5f %10.5f %10.5f %10.5f %10.5f %10.4f %10.4f %10.4f\n", v.name.c_str(),
								a.roll_error_rms_deg, a.roll_error_max_deg, a.roll_error_final_deg, a.pitch_error_rms_deg,
								a.pitch_error_max_deg, a.pitch_error_final_deg, cell(0), cell(1), cell(2));
				}
			}
			tables.push_back(drift::driveFigureTable(e));
			if (!cal.getValue().empty())
			{
				const auto& t = tables.back();
				std::printf("  compensated / raw: heading RMS %.3f, drift between turns %.3f; compensated / ideal heading "
							"RMS %.2f\n",
							t.at("ratio.heading_rms_compensated_over_raw"),
							t.at("ratio.drift_between_turns_compensated_over_raw"),
							t.at("ratio.heading_rms_compensated_over_ideal"));
			}
			evals.push_back(std::move(e));
		}
		std::map<std::string, drift::Spread> over;
		if (evals.size() > 1)
		{
			for (const auto& kv : tables.front())
			{
				std::vector<double> v;
				for (const auto& t : tables)  // a figure some drives lack (a triad among single-axis drives): NaN
					v.push_back(t.count(kv.first) ? t.at(kv.first) : NAN);
				over[kv.first] = drift::spreadOf(v);
			}
			std::printf("fog-drift: over %zu drives: median [quartiles] (min .. max)\n", evals.size());
			for (const auto& kv : over)
			{
				if (kv.second.n == 0) continue;
				std::printf("  %-52s %10.4g [%.4g, %.4g] (%.4g .. %.4g)\n", kv.first.c_str(), kv.second.median,
							kv.second.q1, kv.second.q3, kv.second.min, kv.second.max);
			}
		}

		if (!json.getValue().empty())
		{
			std::vector<drift::DriftContext> ctxs;
			for (const auto& e : evals)
			{
				drift::DriftContext ctx;
				ctx.input = e.input;
				ctx.calibration = cal.getValue();
				ctx.latitude_deg = e.latitude_deg;
				ctx.earth_rate_removed_dph = heading::verticalEarthRate_dph(e.latitude_deg);
				ctx.transport_rate = st.heading.transport_rate;
				ctx.rate_sampling = sampling.getValue();
				ctx.calibration_earth_rate_dph = e.calibration_earth_rate_dph;
				ctx.calibration_latitude_source = e.calibration_latitude_source;
				ctx.input_notices = log_input.json(e.input);
				ctxs.push_back(ctx);
			}
			drift::writeDriftJson(json.getValue(), evals, ctxs, over);
		}
		if (evals.size() == 1)
		{
			const drift::DriveEvaluation& e = evals.front();
			if (!csv.getValue().empty())
			{
				if (e.spilled) drift::writeDriftCsv(csv.getValue(), *e.spilled, e.report);
				else drift::writeDriftCsv(csv.getValue(), e.drive.truth, e.report);
			}
			if (!plots.getValue().empty()) drift::writeDriftPlots(plots.getValue(), e.drive.truth, e.variants, e.report);
			if (!odo_out.getValue().empty() && e.spilled)
			{
				const nav::TrajectoryPoint p0 = drift::writeOdometryRawlog(odo_out.getValue(), *e.spilled);
				std::printf("  odometry rawlog (%s): %s; pf-localization: initial_odo_x=%.6f initial_odo_y=%.6f "
							"initial_odo_phi=%.9f\n",
							e.spilled->odometry_variant.c_str(), odo_out.getValue().c_str(), p0.x_m, p0.y_m, p0.yaw_rad);
			}
			else if (!odo_out.getValue().empty())
			{
				const std::size_t i = cal.getValue().empty() ? 0 : 1;  // compensated when available
				const auto& r = e.results[i];
				const nav::Trajectory& traj = e.variants[i].second;
				drift::writeOdometryRawlog(odo_out.getValue(), traj, interpAt(r.t_s, r.yaw_rate_rad_s, traj));
				const auto& p0 = traj.front();
				std::printf("  odometry rawlog (%s): %s; pf-localization: initial_odo_x=%.6f initial_odo_y=%.6f "
							"initial_odo_phi=%.9f\n",
							e.variants[i].first.c_str(), odo_out.getValue().c_str(), p0.x_m, p0.y_m, p0.yaw_rad);
			}
		}
		return 0;
	});
}
