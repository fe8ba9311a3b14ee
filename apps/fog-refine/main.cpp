/* fog-refine: a calibration that learns its bias offset and aging from field logs.
 *
 *   fog-refine --cal CAL.yaml -i FIELD.rawlog [-i FIELD2.rawlog]... -o REFINED.yaml [--json F]
 *
 * Each field log's vertical FOG is compensated with CAL.yaml and its standstills update the
 * bias offset (FieldLog.h); the logs' offsets are combined into the calibration's field offset
 * (model/FieldOffset.h), with an aging trend when the logs span several dates, and written with
 * the unchanged thermal model to a NEW file: CAL.yaml is kept, and an existing output is never
 * overwritten. */
#include "AppMain.h"
#include "CommandLine.h"
#include "FieldLog.h"
#include "Options.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/model/CalibrationYaml.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <sys/stat.h>

using namespace mrpt_fog;

namespace
{
const char* const kHelp = R"(
WHAT IT DOES
  A thermal calibration cannot hold the offset a FOG picks at each turn-on, nor how its bias
  creeps as it ages. fog-refine measures it in field logs: the vertical FOG compensated with
  --cal, the vehicle's standstills (wheel odometry stopped and the gyro seeing no rotation) where
  the rate should read the vertical Earth rate, and a Kalman filter of the offset (fog-drift's
  standstill updates, docs/reference/field-refinement.md). Per log: the offset at its turn-on
  and its 1-sigma. Over the logs: their weighted mean (weights 1 / (sigma^2 + repeatability^2):
  each turn-on draws its own offset), or, when the logs span more than a day, a straight line
  in time (the aging trend, deg/h per day), referred to the latest log.
  The output is --cal's text with a field_offset section (offset, trend, their 1-sigma, the
  revision, the previous file and the logs) in place of any earlier one: a new file, versioned;
  --cal is kept and an existing -o is never overwritten. fog-drift applies the field offset at
  each drive's date. A log without a standstill long enough teaches nothing (said per log).

EXAMPLES
  fog-refine --cal cal.yaml -i field_day1.rawlog -o cal_r1.yaml
  fog-refine --cal cal_r1.yaml -i field_m1.rawlog -i field_m2.rawlog -i field_m3.rawlog -o cal_r2.yaml --json refine.json
)";

std::string readText(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	if (!in) throw std::runtime_error(path + ": cannot open");
	std::ostringstream ss;
	ss << in.rdbuf();
	return ss.str();
}

bool exists(const std::string& path)
{
	struct stat st;
	return ::stat(path.c_str(), &st) == 0;
}
}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-refine", [&] {
		TCLAP::CmdLine cmd("fog-refine: a calibration that learns its bias offset and aging from field logs", ' ', "0.1");
		app::InputArg cal("", "cal", "the calibration to refine (kept unchanged)", true, "", "CAL.yaml", cmd);
		app::InputMultiArg in("i", "input", "field log with standstills (FOG + wheel odometry); repeat", true,
							  "FIELD.rawlog", cmd);
		app::OutputArg out("o", "output", "the refined calibration (a new file; never overwritten)", true, "",
						   "REFINED.yaml", cmd);
		app::OutputArg json("", "json", "write each log's measurement and the new offset as JSON", false, "", "F.json", cmd);
		app::RealArg rep(cmd, "turn-on-repeatability-dph",
						 "1-sigma turn-on to turn-on repeatability of the offset (prior of each log, scatter between logs)",
						 "deg/h", app::Range::aboveUpTo(0, 1e4), 1.0, "DPH");
		app::RealArg arw(cmd, "gyro-arw-deg-rt-h", "angle random walk of the gyro", "deg/sqrt(h)",
						 app::Range::aboveUpTo(0, 100), 0.001, "N");
		app::RealArg bi(cmd, "gyro-bias-instability-dph", "bias instability of the gyro", "deg/h",
						app::Range::closed(0, 1e4), 0.005, "B");
		app::RealArg min_still(cmd, "min-standstill-s", "shortest standstill used", "s", app::Range::closed(0, 86400), 10.0,
							   "S");
		app::RealArg lat(cmd, "latitude-deg", "latitude (default: each log's metadata)", "deg", app::Range::closed(-90, 90),
						 NAN, "DEG");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-refine", kHelp)) return *rc;
		if (exists(out.getValue()))
			throw std::runtime_error("-o " + out.getValue() + ": exists; fog-refine writes a new file and keeps every earlier one");

		const std::string cal_text = readText(cal.getValue());
		const CalibrationSet cals = loadCalibrationSet(cal.getValue());
		const Calibration* zcal = cals.forAxis(GyroAxis::Z);
		if (!zcal) throw std::runtime_error(cal.getValue() + ": axes: no calibration for axis z (the heading gyro)");
		const std::optional<FieldOffset> previous = fieldOffsetFromYaml(cal_text, cal.getValue());

		refine::FieldLogSettings st;
		st.turn_on_repeatability_dph = rep.getValue();
		st.noise.arw_deg_rt_h = arw.getValue();
		st.noise.bias_instability_dph = bi.getValue();
		st.min_still_s = min_still.getValue();
		if (lat.isSet()) st.latitude_deg = lat.getValue();

		std::vector<refine::FieldLogOffset> logs;
		for (const auto& p : in.getValue())
		{
			logs.push_back(refine::measureFieldLog(p, *zcal, previous, st));
			const auto& l = logs.back();
			std::printf("fog-refine: %s: %zu samples, %zu standstill update(s)", p.c_str(), l.samples, l.updates.size());
			if (l.measured)
				std::printf(", offset %+.4f +- %.4f deg/h (calibration's field offset %+.4f applied)", l.offset_dph,
							l.sigma_dph, l.applied_dph);
			std::printf("\n");
			if (!l.note.empty()) std::printf("  %s\n", l.note.c_str());
		}
		FieldOffset f = refine::combineFieldLogs(logs, rep.getValue(), previous);
		f.previous = cal.getValue();
		writeTextFileAtomically(out.getValue(), withFieldOffset(cal_text, f));
		std::printf("fog-refine: %s: field offset revision %d: %+.4f +- %.4f deg/h at the latest log, trend %+.3g +- %.3g "
					"deg/h per day (%s); %s kept\n",
					out.getValue().c_str(), f.revision, f.offset_dph, f.sigma_dph, f.aging_dph_per_day,
					f.aging_sigma_dph_per_day,
					f.aging_dph_per_day == 0 && f.aging_sigma_dph_per_day == 0 ? "one date: no trend" : "fitted or kept",
					cal.getValue().c_str());
		if (!json.getValue().empty())
		{
			JsonValue j = JsonValue::object();
			j["calibration"] = cal.getValue();
			j["output"] = out.getValue();
			JsonValue list = JsonValue::array();
			for (const auto& l : logs)
			{
				JsonValue o = JsonValue::object();
				o["path"] = l.path;
				o["t_unix_s"] = l.t_unix_s;
				o["measured"] = l.measured;
				o["offset_dph"] = l.measured ? JsonValue(l.offset_dph) : JsonValue();
				o["sigma_dph"] = l.measured ? JsonValue(l.sigma_dph) : JsonValue();
				o["applied_field_offset_dph"] = l.applied_dph;
				o["standstill_updates"] = static_cast<unsigned long>(l.updates.size());
				o["short_standstills"] = static_cast<unsigned long>(l.short_standstills);
				o["note"] = l.note.empty() ? JsonValue() : JsonValue(l.note);
				list.push_back(o);
			}
			j["logs"] = list;
			JsonValue& fo = j["field_offset"] = JsonValue::object();
			fo["offset_dph"] = f.offset_dph;
			fo["sigma_dph"] = f.sigma_dph;
			fo["aging_dph_per_day"] = f.aging_dph_per_day;
			fo["aging_sigma_dph_per_day"] = f.aging_sigma_dph_per_day;
			fo["reference_unix_s"] = f.reference_unix_s;
			fo["revision"] = f.revision;
			writeTextFileAtomically(json.getValue(), j.dump());
		}
		return 0;
	});
}
