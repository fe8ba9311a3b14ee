/* fog-odometry: a vehicle rawlog with the odometry's heading taken from the compensated FOG.
 *
 *   fog-odometry -i VEHICLE.rawlog --cal CAL.yaml -o OUT.rawlog
 *
 * Every object is kept, in order and in the input's format; the wheel odometry gets the FOG
 * heading (heading/FogOdometryRawlog.h). The program parses, calls the library and prints. */
#include "AppMain.h"
#include "CommandLine.h"
#include "Options.h"
#include "Progress.h"
#include "ThermistorScreeningReport.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/FieldOffset.h>
#include <mrpt_fog_heading/FogOdometryRawlog.h>

#include <cmath>
#include <cstdio>
#include <optional>

using namespace mrpt_fog;

namespace
{
const char* const kHelp = R"(
WHAT IT DOES
  Reads any MRPT rawlog of a vehicle (observations-only, or actions-observations:
  CActionCollection + CSensoryFrame), with every observation class (lidar scans, cameras, GPS,
  other IMUs... are passed through untouched), and writes the same rawlog, in the same format,
  with the wheel odometry's heading replaced by the compensated FOG's:
    observations-only     each CObservationOdometry '--odometry-label' holds the pose dead-
                          reckoned from the wheel distance and the FOG heading;
    actions-observations  each CActionRobotMovement2D holds the increment between two such
                          poses and a FOG motion model (Gaussian: a3 = 0, a4 = --fog-scale-factor-ppm,
                          minStdPHI = --fog-bias-dph x sqrt(dt x --fog-horizon-s), a1 =
                          --distance-frac, minStdXY = --min-std-xy-m; docs/guide/localization.md). A step
                          with the gyro off keeps MRPT's default wheel model.
  The FOG: CObservationFOG '--fog-label', compensated sample by sample with the calibration's
  z axis (thermistor screening first), the calibration's field offset removed (fog-refine's
  field_offset section, if any), the calibration's Earth rate added back once, integrated
  with the drive's vertical Earth rate removed (latitude from the FOG's metadata, or
  --latitude-deg). The output is in the wheel odometry's frame: it starts at the first odometry
  pose. While the gyro is off (power 0) the wheels' heading change is used and counted.
  Then run MRPT's localization on it, e.g. pf-localization with an .ini naming OUT.rawlog and
  your map (docs/guide/your-vehicle.md).

TRUTH (optional)
  When the input holds CObservationRobotPose '--truth-label', or --truth names a held-back
  rawlog with them, the FOG odometry's and the wheels' heading and position errors are printed
  (each track moved rigidly onto the truth at its first pose; --compare-s limits the span).
FIELD REFINEMENT (on by default; --no-field-refinement)
  While the vehicle stands still (wheels stopped, the gyro sees no rotation) the compensated rate
  should read the vertical Earth rate; a Kalman filter of the turn-on bias offset learns from it
  and corrects every later sample once the offset differs from 0 by more than 3 of its sigma
  (docs/reference/field-refinement.md). No standstill: no update, the thermal model alone.
  JSON: field_refinement.

EXAMPLES
  fog-odometry -i vehicle.rawlog --cal cal.yaml -o vehicle_fog.rawlog
  fog-odometry -i vehicle.rawlog --cal cal.yaml -o out.rawlog --truth truth.rawlog --compare-s 600 --json s.json
)";

JsonValue errorsJson(const heading::TrackErrors& e)
{
	JsonValue j = JsonValue::object();
	j["compared"] = static_cast<unsigned long>(e.compared);
	j["heading_rms_deg"] = e.heading_rms_deg;
	j["heading_max_deg"] = e.heading_max_deg;
	j["heading_final_deg"] = e.heading_final_deg;
	j["position_rms_m"] = e.position_rms_m;
	j["position_max_m"] = e.position_max_m;
	j["position_final_m"] = e.position_final_m;
	j["span_s"] = e.t_last_s - e.t_first_s;
	return j;
}
}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-odometry", [&]() -> int {
		TCLAP::CmdLine cmd("fog-odometry: a vehicle rawlog with the odometry's heading from the compensated FOG "
						   "(every other object kept, in order and format). Details and examples below.",
						   ' ', "0.1");
		app::InputArg arg_in("i", "input", "Vehicle rawlog (either MRPT format)", true, "", "IN.rawlog", cmd);
		app::InputArg arg_cal("", "cal", "Calibration YAML (fog-calibrate); its z axis is used", true, "", "CAL.yaml", cmd);
		app::OutputArg arg_out("o", "output", "Output rawlog", true, "", "OUT.rawlog", cmd);
		TCLAP::ValueArg<std::string> arg_fog("", "fog-label", "Label of the CObservationFOG", false, "FOG", "L", cmd);
		TCLAP::ValueArg<std::string> arg_odo("", "odometry-label", "Label of the CObservationOdometry", false, "ODOMETRY",
											 "L", cmd);
		TCLAP::ValueArg<std::string> arg_truth_label("", "truth-label", "Label of the CObservationRobotPose truth", false,
													 "GROUND_TRUTH", "L", cmd);
		app::InputArg arg_truth("", "truth", "Held-back truth rawlog to compare with", false, "", "T.rawlog", cmd);
		app::RealArg arg_compare(cmd, "compare-s", "Compare with the truth over this span (default: all)", "s",
								 app::Range::aboveUpTo(0, INFINITY), INFINITY, "S");
		app::RealArg arg_lat(cmd, "latitude-deg", "Drive latitude (default: the FOG's metadata)", "deg",
							 app::Range::closed(-90, 90), NAN, "DEG");
		app::RealArg arg_bias(cmd, "fog-bias-dph", "Motion model: FOG bias uncertainty", "deg/h", app::Range::closed(0, 1e4),
							  0.5, "DPH");
		app::RealArg arg_horizon(cmd, "fog-horizon-s", "Motion model: random-walk horizon", "s", app::Range::closed(0, 1e6),
								 60.0, "S");
		app::RealArg arg_sf(cmd, "fog-scale-factor-ppm", "Motion model: heading error per turned angle", "ppm",
							app::Range::closed(0, 1e6), 2000.0, "PPM");
		app::RealArg arg_dist(cmd, "distance-frac", "Motion model: distance std per metre", "-", app::Range::closed(0, 10),
							  0.003, "F");
		app::RealArg arg_minxy(cmd, "min-std-xy-m", "Motion model: position std per step", "m", app::Range::closed(0, 1e3),
							   0.05, "M");
		app::OutputArg arg_json("", "json", "Write the summary as JSON", false, "", "FILE", cmd);
		TCLAP::SwitchArg arg_no_screen("", "no-screening", "Do not screen thermistor readings before compensating", cmd);
		TCLAP::SwitchArg arg_quiet("q", "quiet", "No progress line on stderr", cmd);
		TCLAP::SwitchArg arg_no_refine("", "no-field-refinement",
									   "No standstill updates of the compensated gyro's turn-on bias offset", cmd);
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-odometry", kHelp)) return *rc;

		const CalibrationSet cals = loadCalibrationSet(arg_cal.getValue());
		const Calibration* zcal = cals.forAxis(GyroAxis::Z);
		if (!zcal) throw std::runtime_error(arg_cal.getValue() + ": no calibration for axis z (the heading gyro)");

		heading::FogOdometryOptions o;
		o.fog_label = arg_fog.getValue();
		o.odometry_label = arg_odo.getValue();
		o.truth_label = arg_truth_label.getValue();
		o.truth_path = arg_truth.getValue();
		o.compare_s = arg_compare.getValue();
		o.pipeline.latitude_deg = arg_lat.getValue();
		o.pipeline.screen_thermistors = !arg_no_screen.getValue();
		o.pipeline.field_refinement = !arg_no_refine.getValue();
		o.pipeline.field_offset = loadFieldOffset(arg_cal.getValue());  // what fog-refine learned, if any
		o.motion.heading_bias_dph = arg_bias.getValue();
		o.motion.horizon_s = arg_horizon.getValue();
		o.motion.scale_factor_ppm = arg_sf.getValue();
		o.motion.distance_frac = arg_dist.getValue();
		o.motion.min_std_xy_m = arg_minxy.getValue();
		app::Progress progress("fog-odometry: " + arg_in.getValue(), arg_quiet.getValue());
		o.progress = [&](std::uint64_t done, std::uint64_t total) { progress.update(0, done, total); };
		const heading::FogOdometryReport r = heading::writeFogOdometry(arg_in.getValue(), arg_out.getValue(), zcal, o);
		progress.finish();

		std::printf("fog-odometry: %s -> %s (%s, %zu objects in, %zu out)\n", arg_in.getValue().c_str(),
					arg_out.getValue().c_str(), rawlogFormatName(r.format), r.objects_in, r.objects_out);
		std::printf("  odometry given the FOG heading: %zu; written as read: %zu; poses with the wheels' heading (gyro "
					"off or after the FOG): %zu\n",
					r.odometry_rewritten, r.odometry_unchanged, r.pipeline.wheel_poses);
		std::printf("  FOG samples: %zu (integrated %zu, gyro off %zu, turn-ons %zu); latitude %.4f deg; calibration "
					"Earth rate added back: %.4f deg/h (latitude from the %s)\n",
					r.pipeline.fog_samples, r.pipeline.integrated_samples, r.pipeline.gyro_off_samples,
					r.pipeline.turn_ons, r.latitude_deg, r.earth.add_back_dph, heading::latitudeSourceName(r.earth.source));
		bool same = r.counts_in.size() == r.counts_out.size();
		for (const auto& [key, n] : r.counts_in)
		{
			const auto it = r.counts_out.find(key);
			const std::size_t m = it == r.counts_out.end() ? 0 : it->second;
			std::printf("  %-48s %8zu in %8zu out\n", key.c_str(), n, m);
			same &= m == n;
		}
		if (!same) std::printf("  warning: the counts differ\n");
		if (r.compensation)
		{
			const auto& c = *r.compensation;
			if (c.fallback_samples || c.no_model_samples || c.clamped_samples)
				std::printf("  compensation: %zu samples, %zu on a fallback model, %zu without model, %zu clamped to "
							"the calibrated range\n",
							c.samples, c.fallback_samples, c.no_model_samples, c.clamped_samples);
		}
		const auto printErr = [](const char* name, const heading::TrackErrors& e) {
			std::printf("  %-10s vs truth over %.1f s (%zu poses): heading RMS %.4f deg, max %.4f deg; position RMS "
						"%.3f m, final %.3f m\n",
						name, e.t_last_s - e.t_first_s, e.compared, e.heading_rms_deg, e.heading_max_deg,
						e.position_rms_m, e.position_final_m);
		};
		if (r.fog_vs_truth) printErr("FOG", *r.fog_vs_truth);
		if (r.wheels_vs_truth) printErr("wheels", *r.wheels_vs_truth);
		if (!r.fog_vs_truth) std::printf("  no truth: heading errors cannot be told (give --truth)\n");
		if (!r.field_refinement)
			std::printf("  field refinement: off\n");
		else if (r.standstill_updates.empty())
			std::printf("  field refinement: no standstill long enough to beat the prior: no update (the thermal model "
						"alone)\n");
		else
			std::printf("  field refinement: %zu standstill update(s); turn-on offset %+.4f +- %.4f deg/h, %s\n",
						r.standstill_updates.size(), r.offset_dph, r.offset_sigma_dph,
						r.offset_applied ? "applied" : "within 3 sigma of the prior: not applied");

		if (!arg_json.getValue().empty())
		{
			JsonValue j = JsonValue::object();
			j["input"] = arg_in.getValue();
			j["output"] = arg_out.getValue();
			j["format"] = std::string(rawlogFormatName(r.format));
			j["objects_in"] = static_cast<unsigned long>(r.objects_in);
			j["objects_out"] = static_cast<unsigned long>(r.objects_out);
			j["odometry_rewritten"] = static_cast<unsigned long>(r.odometry_rewritten);
			j["odometry_unchanged"] = static_cast<unsigned long>(r.odometry_unchanged);
			j["wheel_poses"] = static_cast<unsigned long>(r.pipeline.wheel_poses);
			j["fog_samples"] = static_cast<unsigned long>(r.pipeline.fog_samples);
			j["latitude_deg"] = r.latitude_deg;
			JsonValue& ci = j["counts_in"] = JsonValue::object();
			for (const auto& [key, n] : r.counts_in) ci[key] = static_cast<unsigned long>(n);
			JsonValue& co = j["counts_out"] = JsonValue::object();
			for (const auto& [key, n] : r.counts_out) co[key] = static_cast<unsigned long>(n);
			j["counts_equal"] = same;
			if (r.fog_vs_truth) j["fog_vs_truth"] = errorsJson(*r.fog_vs_truth);
			if (r.wheels_vs_truth) j["wheels_vs_truth"] = errorsJson(*r.wheels_vs_truth);
			JsonValue& fr = j["field_refinement"] = JsonValue::object();
			fr["ran"] = r.field_refinement;
			JsonValue ups = JsonValue::array();
			for (const auto& u : r.standstill_updates)
			{
				JsonValue x = JsonValue::object();
				x["still_from_s"] = u.start_s;
				x["still_to_s"] = u.end_s;
				x["samples"] = static_cast<unsigned long>(u.samples);
				x["mean_reading_dph"] = u.mean_reading_dph;
				x["offset_after_dph"] = u.offset_after_dph;
				x["sigma_after_dph"] = u.sigma_after_dph;
				x["applied"] = u.applied;
				ups.push_back(x);
			}
			fr["updates"] = ups;
			fr["offset_dph"] = r.offset_dph;
			fr["offset_sigma_dph"] = r.offset_sigma_dph;
			fr["applied"] = r.offset_applied;
			writeTextFileAtomically(arg_json.getValue(), j.dump());
		}
		return app::kExitOk;
	});
}
