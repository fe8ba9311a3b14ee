/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* fog-convert: FOG logs between lab CSV and MRPT rawlog (by file extension), with an optional
 * stock-MRPT output (CObservationIMU + CObservationRawDAQ) readable without the plugin. */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/io/LogFormat.h>
#include <mrpt_fog/io/NumberText.h>
#include <mrpt_fog/obs/CObservationFOG.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <map>

#include "AppMain.h"
#include "LogInput.h"
#include "CommandLine.h"
#include "Options.h"
#include "Progress.h"
#include "PowerCycles.h"

using namespace mrpt_fog;

namespace
{
const char* const kFormatHelp = R"(
WHAT IT DOES
  Converts a FOG log between the lab CSV format and MRPT rawlogs, chosen by the file
  extensions: .csv / .csv.gz (gzip) <-> .rawlog (also rawlog -> rawlog, csv -> csv).
  Readers check the whole file: a truncated or partly unreadable input is an error (never a
  silently shorter output), and on any error no file is left under the -o name.

CSV FORMAT
  '# key: value' metadata lines, then one header row, then one row per sample:
    # sensor: FOG                              (sensor label; default FOG)
    # epoch_s: 1700000000                      (UNIX time [s] of time_s = 0)
    # latitude_deg: 30.5
    # thermistor Ti1: side=inner angle_deg=0   (side = inner|outer|other)
    # thermistor To1: side=outer angle_deg=0
    time_s,rate_z_dph,temp_Ti1_C,temp_To1_C
    0,0.1234,25.01,25.30
    0.1,0.1240,,25.31                          (empty cell = thermistor dropout)
  Columns: time_s [s] (required, strictly increasing); rate_x_dph, rate_y_dph, rate_z_dph
  [deg/h] (at least one); temp_<name>_C [degC] per thermistor; optional table_rate_dph,
  field_uT, power (1 on, 0 off). Unknown '#' keys are kept. CRLF line ends are accepted.

RAWLOG
  gz-compressed, observations-only: a CObservationComment with the run metadata, then one
  mrpt_fog::CObservationFOG per sample; other observations (odometry, IMU, other FOG labels)
  are kept, merged by timestamp. Timestamps resolve 100 ns. MRPT tools read it with the
  plugin: rawlog-edit -p /path/to/libmrpt_fog.so --info -i run.rawlog
  --to-stock writes stock classes instead (readable by any MRPT tool without the plugin):
  per sample a CObservationIMU (IMU_WX/WY/WZ [rad/s], mean temperature in IMU_TEMPERATURE)
  and a CObservationRawDAQ '<label>_THERMISTORS' (AIN_double, one channel per thermistor,
  NaN = dropout).

LOGGER FILES
  A logger's own CSV (other column names, units, delimiter) is read through a format file
  (docs/reference/format-files.md): --guess-format LOG prints a draft from the file's header,
  to check; --format F.yaml then converts once. The values are converted to s, deg/h and degC.

EXAMPLES
  fog-convert --guess-format vendor.csv > vendor.yaml
  fog-convert --format vendor.yaml -i vendor.csv -o run.rawlog
  fog-convert -i chamber.csv -o chamber.rawlog --json summary.json
  fog-convert -i drive.rawlog --label FOG_IDEAL -o ideal.csv
  fog-convert -i chamber.rawlog -o chamber_stock.rawlog --to-stock
)";

bool isRawlog(const std::string& path) { return fileExtension(path) == ".rawlog"; }

void requireKnownExtension(const std::string& path, const char* what)
{
	const std::string ext = fileExtension(path);
	if (ext != ".rawlog" && ext != ".csv" && ext != ".csv.gz")
		throw std::runtime_error(std::string(what) + " '" + path + "': unknown file type '" + ext +
								 "' (expected .rawlog, .csv or .csv.gz)");
}

}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-convert", [&]() -> int {
		TCLAP::CmdLine cmd(
			"fog-convert: FOG logs between lab CSV (.csv, .csv.gz) and MRPT rawlog (.rawlog), by file "
			"extension. Format summary and examples below.",
			' ', "0.1");
		app::InputArg arg_in("i", "input", "Input log (.csv, .csv.gz or .rawlog; any logger file with --format)", false, "", "IN", cmd);
		app::OutputArg arg_out("o", "output", "Output log (.csv, .csv.gz or .rawlog)", false, "", "OUT", cmd);
		app::InputArg arg_guess("", "guess-format",
			"Print a draft format file for this logger CSV (from its header: names and bracketed units such as "
			"\"Gyro Z [deg/s]\"), to check and then use with --format; nothing else is done", false, "", "LOG", cmd);
		TCLAP::ValueArg<std::string> arg_label("", "label",
			"FOG sensor label to take from a rawlog holding several (e.g. FOG_IDEAL)", false, "", "L", cmd);
		app::OutputArg arg_json("", "json", "Write a JSON summary (counts, time span, sensors, "
			"thermistors, axes, dropouts) to FILE", false, "", "FILE", cmd);
		TCLAP::SwitchArg arg_quiet("q", "quiet", "No progress line on stderr", cmd);
		TCLAP::SwitchArg arg_stock("", "to-stock", "Write stock MRPT CObservationIMU + CObservationRawDAQ instead "
			"of CObservationFOG (output must be .rawlog)", cmd);
		app::LogInput log_input(cmd, "fog-convert");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-convert", kFormatHelp)) return *rc;

		if (arg_guess.isSet())
		{
			std::cout << guessLogFormat(arg_guess.getValue());
			return app::kExitOk;
		}
		const std::string in = arg_in.getValue(), out = arg_out.getValue();
		if (in.empty() || out.empty()) throw std::invalid_argument("-i IN and -o OUT are required (or --guess-format LOG)");
		if (log_input.formatPath().empty() || isRawlog(in)) requireKnownExtension(in, "input");
		requireKnownExtension(out, "output");
		if (arg_stock.getValue() && !isRawlog(out))
			throw std::runtime_error("--to-stock writes a rawlog: the output '" + out + "' must end in .rawlog");

		// Read sample by sample and write as we go: memory does not grow with the log.
		const bool to_rawlog = isRawlog(out), stock = arg_stock.getValue();
		std::vector<mrpt::obs::CObservation::Ptr> pending;  // other observations met while reading
		std::map<std::string, std::size_t> fog_labels, other_classes;
		std::size_t others_seen = 0;
		FogLogReader reader(
			in, arg_label.getValue(), ReadLimits{},
			[&](const mrpt::obs::CObservation::Ptr& o) {
				others_seen++;
				if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o)) fog_labels[f->sensorLabel]++;
				other_classes[o->GetRuntimeClass()->className]++;
				if (to_rawlog) pending.push_back(o);
			},
			log_input.options());
		const FogSeries& s = reader.header();
		FogLogWriter writer(out, s, stock ? RawlogForm::Stock : RawlogForm::Fog);
		std::size_t others_written = 0;
		const auto flushOthers = [&] {
			for (const auto& o : pending)
			{
				if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o); f && stock)
				{
					writer.writeOther(*f->toIMU());
					writer.writeOther(*f->toRawDAQ());
					others_written += 2;
				}
				else
				{
					writer.writeOther(*o);
					others_written++;
				}
			}
			pending.clear();
		};
		std::vector<std::size_t> dropouts_of(s.thermistorCount(), 0);
		app::PowerCycles power_cycles;
		double t0 = 0, t1 = 0;
		app::Progress progress("fog-convert", arg_quiet.getValue());
		FogSample x;
		while (reader.next(x))
		{
			flushOthers();
			writer.write(x);
			if (reader.samplesRead() == 1) t0 = x.time_s;
			t1 = x.time_s;
			for (std::size_t i = 0; i < x.temp_C.size(); i++) dropouts_of[i] += std::isnan(x.temp_C[i]);
			power_cycles.add(x.power);
			progress.update(reader.samplesRead(), reader.fileBytesRead(), reader.fileBytes());
		}
		flushOthers();
		writer.close();
		progress.finish();
		const std::size_t samples = reader.samplesRead();
		fog_labels[s.sensor_label] += samples;
		if (!to_rawlog && others_seen > 0)
			std::cerr << "fog-convert: note: " << others_seen << " other observations of the rawlog (not FOG sensor '"
					  << s.sensor_label << "') have no place in a CSV and were not written\n";

		// Summary.
		std::size_t dropouts = 0;
		for (auto n : dropouts_of) dropouts += n;
		std::string axes;
		for (int a = 0; a < 3; a++)
			if (s.has_axis[a]) axes += axes.empty() ? "" : ",", axes += axisLetter(static_cast<GyroAxis>(a));
		std::cout << "fog-convert: " << in << " -> " << out << (stock ? " (stock IMU+DAQ)" : "") << "\n  sensor '"
				  << s.sensor_label << "': " << samples << " samples, axes " << axes << ", " << s.thermistorCount()
				  << " thermistors, " << dropouts << " dropouts, time " << io::formatNumber(t0) << " .. "
				  << io::formatNumber(t1) << " s\n";
		if (reader.hasPower())
			std::cout << "  gyro off on " << power_cycles.gyro_off_rows << " rows (thermistors kept, no gyro sample), " << power_cycles.turn_ons
					  << " turn-on events\n";
		if (to_rawlog)
			std::cout << "  wrote " << writer.objectsWritten() << " objects (" << others_written << " other observations)\n";

		if (!arg_json.getValue().empty())
		{
			JsonValue j = JsonValue::object();
			j["input"] = in;
			j["input_notices"] = log_input.json();
			j["output"] = out;
			j["output_kind"] = to_rawlog ? (stock ? "rawlog-stock" : "rawlog") : "csv";
			j["sensor"] = s.sensor_label;
			j["samples"] = static_cast<unsigned long>(samples);
			if (isRawlog(in)) j["input_objects"] = static_cast<unsigned long>(reader.objectsRead());
			j["other_observations"] = static_cast<unsigned long>(others_seen);
			j["objects_written"] = static_cast<unsigned long>(to_rawlog ? writer.objectsWritten() : 0);
			JsonValue& sensors = j["fog_sensors"] = JsonValue::object();
			for (const auto& [label, n] : fog_labels) sensors[label] = static_cast<unsigned long>(n);
			JsonValue& classes = j["other_classes"] = JsonValue::object();
			for (const auto& [cls, n] : other_classes) classes[cls] = static_cast<unsigned long>(n);
			j["epoch_s"] = s.epoch_s;
			j["time_start_s"] = t0;
			j["time_end_s"] = t1;
			j["time_span_s"] = t1 - t0;
			JsonValue& ax = j["axes"] = JsonValue::array();
			for (int a = 0; a < 3; a++)
				if (s.has_axis[a]) ax.push_back(std::string(1, axisLetter(static_cast<GyroAxis>(a))));
			JsonValue& th = j["thermistors"] = JsonValue::array();
			for (std::size_t i = 0; i < s.thermistorCount(); i++)
			{
				JsonValue t = JsonValue::object();
				t["name"] = s.thermistors[i].name;
				t["side"] = toString(s.thermistors[i].side);
				t["angle_deg"] = s.thermistors[i].angle_deg;
				t["dropouts"] = static_cast<unsigned long>(dropouts_of[i]);
				th.push_back(t);
			}
			j["dropouts"] = static_cast<unsigned long>(dropouts);
			j["gyro_off_rows"] = static_cast<unsigned long>(power_cycles.gyro_off_rows);
			j["turn_on_events"] = static_cast<unsigned long>(power_cycles.turn_ons);
			JsonValue& opt = j["optional_columns"] = JsonValue::array();
			if (reader.hasTableRate()) opt.push_back("table_rate_dph");
			if (reader.hasField()) opt.push_back("field_uT");
			if (reader.hasPower()) opt.push_back("power");
			writeTextFileAtomically(arg_json.getValue(), j.dump());
		}
		return app::kExitOk;
	});
}
