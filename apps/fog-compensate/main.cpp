/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* fog-compensate: applies a calibration to a FOG log, sample by sample (causal, as it would run
 * on the vehicle), and writes a stock-MRPT rawlog or a CSV with raw and compensated columns. */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/io/GzStream.h>
#include <mrpt_fog/io/NumberText.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/Compensator.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <sstream>

#include "AppMain.h"
#include "LogInput.h"
#include "FieldWarning.h"
#include "RangeWarning.h"
#include "CommandLine.h"
#include "Options.h"
#include "Progress.h"
#include "PowerCycles.h"
#include "ThermistorScreeningReport.h"

using namespace mrpt_fog;

namespace
{
const char* const kHelp = R"(
WHAT IT DOES
  Removes the thermal bias: compensated = raw - bias(temperatures, causal rates), sample by
  sample with only past samples (what a real-time implementation computes). A thermistor
  dropout switches to the calibration's fallback model without it (and back when it returns);
  temperatures or rates outside the calibrated range follow the calibration's extrapolation
  policy (default linear: each signal's polynomial continued along its edge tangent; clamp
  holds the edge value); a warning gives the share of such samples and how far out. Counts
  of both are printed. A calibration made for another thermistor layout is refused.

THERMISTOR SCREENING (on by default)
  Before compensation every thermistor reading is screened causally (ThermistorHealth): a
  reading stuck at one value for >= 30 s while another thermistor moved >= 0.2 C, a spike
  (a jump > 0.5 C + 0.2 C/s x elapsed time, shorter than 20 s), or a value outside
  [-80, 150] C is treated as a dropout, so the fallback model takes over until the sensor
  behaves again. The counts are printed (and under "screening" in --json). The output keeps
  the temperatures as read. --no-screening feeds the readings to the compensator unchanged.

OUTPUT (by extension of -o)
  .rawlog   stock MRPT observations: per sample a CObservationIMU (compensated rates in
            IMU_WX/WY/WZ [rad/s], mean temperature in IMU_TEMPERATURE) and a
            CObservationRawDAQ '<label>_THERMISTORS' (thermistors [degC], NaN = dropout).
  .csv      time_s, raw_rate_<a>_dph, bias_<a>_dph, compensated_rate_<a>_dph, flags,
            temp_<name>_C...  flags: 1 fallback, 2 no model, 4 clamped, 8 rate warm-up,
            16 rate-free start-up model (rates not yet estimable: start, burst, gap).
            With a calibration of several axes: the four columns per axis (flags_<a>).

MAGNETIC TERM
  A calibration with a magnetic section (written by fog-discrepancy --write-cal) adds
  dph_per_uT x the applied axial field to the bias, the field read from the log's field_uT
  column sample by sample. Without that column (or on empty cells) the term is left out and a
  warning on stderr says on how many samples ("magnetic" in --json).

SEVERAL AXES
  Every axis in the calibration file is compensated with its own model (a calibration axis
  missing from the log is an error); log axes without a calibration are written raw (said).
  Power-off rows (power 0, empty rate cell): the thermistors keep feeding the rate estimator,
  no compensated rate is written (empty cells; no IMU rate in the rawlog), and the number of
  turn-on events (power back to 1) is printed.

EXAMPLES
  fog-compensate -i datasets/chamber_B.rawlog --cal cal.yaml -o chamber_B_comp.rawlog
  fog-compensate -i run.csv --cal cal.yaml -o run_comp.csv --json summary.json
)";

/** fog-compensate's CSV: time_s, raw, bias, compensated (calibrated axis), flags, temperatures,
 * one row at a time. */
class CompensatedCsvWriter
{
   public:
	CompensatedCsvWriter(const std::string& path, const FogSeries& layout, const std::vector<char>& axes,
						 const std::string& cal_path)
		: out_(path), gz_(out_.writePath(), false, 6, path)
	{
		std::ostringstream o;
		o << "# sensor: " << layout.sensor_label << "\n# compensated_by: fog-compensate\n# calibration: " << cal_path << "\n";
		o << "time_s";
		for (char axis : axes)
			o << ",raw_rate_" << axis << "_dph,bias_" << axis << "_dph,compensated_rate_" << axis << "_dph,flags"
			  << (axes.size() > 1 ? std::string("_") + axis : std::string());
		for (const auto& t : layout.thermistors) o << ",temp_" << t.name << "_C";
		o << "\n";
		gz_.write(o.str());
	}
	/** raw[i] and r[i]: the i-th calibrated axis. */
	void write(double t, const std::vector<double>& raw, const std::vector<Compensator::Output>& r,
			   const std::vector<double>& temps)
	{
		// gyro off (power 0, no rate sample): raw and compensated cells empty, the bias kept
		auto cell = [&](double v, bool comma = true) {
			if (comma) row_ += ',';
			if (!std::isnan(v)) row_ += io::formatNumber(v);
		};
		row_.clear();
		cell(t, false);
		for (std::size_t i = 0; i < r.size(); i++)
		{
			cell(raw[i]);
			row_ += ',' + io::formatNumber(r[i].bias_dph);
			cell(r[i].compensated_dph);
			row_ += ',' + std::to_string(static_cast<int>(r[i].flags));
		}
		for (double v : temps) cell(v);
		row_ += '\n';
		gz_.write(row_);
	}
	void close()
	{
		gz_.close();
		out_.commit();
	}

   private:
	AtomicOutput out_;
	io::GzWriter gz_;
	std::string row_;
};
/** The compensator's sample counters as members of `j` (clamped_signals only in the top-level
 * block, the per-axis blocks leave it out). */
void putCounters(JsonValue& j, const CompensationCounters& k, bool with_clamped_signals)
{
	j["samples"] = static_cast<unsigned long>(k.samples);
	j["fallback_samples"] = static_cast<unsigned long>(k.fallback_samples);
	j["no_model_samples"] = static_cast<unsigned long>(k.no_model_samples);
	j["clamped_samples"] = static_cast<unsigned long>(k.clamped_samples);
	if (with_clamped_signals) j["clamped_signals"] = static_cast<unsigned long>(k.clamped_signals);
	j["warmup_samples"] = static_cast<unsigned long>(k.warmup_samples);
	j["rate_free_samples"] = static_cast<unsigned long>(k.rate_free_samples);
	j["model_switches"] = static_cast<unsigned long>(k.model_switches);
}
}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-compensate", [&]() -> int {
		TCLAP::CmdLine cmd("fog-compensate: remove the thermal bias from a FOG log with a calibration from "
						   "fog-calibrate (causal, sample by sample). Details and examples below.",
						   ' ', "0.1");
		app::InputArg arg_in("i", "input", "FOG log (.rawlog, .csv, .csv.gz)", true, "", "IN", cmd);
		app::InputArg arg_cal("", "cal", "Calibration YAML (fog-calibrate)", true, "", "CAL.yaml", cmd);
		app::OutputArg arg_out("o", "output", "Output (.rawlog or .csv)", true, "", "OUT", cmd);
		TCLAP::ValueArg<std::string> arg_label("", "label", "FOG sensor label in rawlogs with several", false, "", "L", cmd);
		app::OutputArg arg_json("", "json", "Write the summary as JSON", false, "", "FILE", cmd);
		TCLAP::SwitchArg arg_quiet("q", "quiet", "No progress line on stderr", cmd);
		TCLAP::SwitchArg arg_no_screen("", "no-screening",
									   "Do not screen thermistor readings (stuck / spike / out of range) before "
									   "compensating",
									   cmd);
		app::LogInput log_input(cmd, "fog-compensate");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-compensate", kHelp)) return *rc;

		const std::string out = arg_out.getValue(), ext = fileExtension(out);
		if (ext != ".rawlog" && ext != ".csv")
			throw std::runtime_error("output '" + out + "': unknown file type '" + ext + "' (expected .rawlog or .csv)");
		const CalibrationSet cals = loadCalibrationSet(arg_cal.getValue());

		// Sample by sample: read, screen, compensate, write. Memory does not grow with the log.
		FogLogReader reader(arg_in.getValue(), arg_label.getValue(), ReadLimits{}, nullptr, log_input.options());
		const FogSeries& layout = reader.header();
		const auto withInput = [&](const std::exception& e) {
			return std::runtime_error(arg_in.getValue() + " with " + arg_cal.getValue() + ": " + e.what());
		};
		// One compensator per calibrated axis (all in the file); other axes of the log pass raw.
		std::vector<int> axis_index;
		std::vector<char> axis_letter;
		std::vector<std::unique_ptr<Compensator>> comps;
		bool any_warmup = false;
		for (const Calibration& cal : cals.axes)
		{
			const char axis = axisLetter(cal.axis);
			if (!layout.has_axis[static_cast<int>(cal.axis)])
				throw withInput(std::invalid_argument(std::string("the log has no ") + axis + " axis, which the calibration is for"));
			axis_index.push_back(static_cast<int>(cal.axis));
			axis_letter.push_back(axis);
			try
			{
				comps.push_back(std::make_unique<Compensator>(cal, layout.thermistors));
			}
			catch (const std::invalid_argument& e)
			{
				throw withInput(e);
			}
			any_warmup |= static_cast<bool>(cal.warmup);
		}
		std::string uncalibrated;
		for (int a = 0; a < 3; a++)
			if (layout.has_axis[a] && !cals.forAxis(static_cast<GyroAxis>(a)))
				uncalibrated += std::string(uncalibrated.empty() ? "" : ", ") + axisLetter(static_cast<GyroAxis>(a));
		const bool screen = !arg_no_screen.getValue();
		ThermistorHealth health(layout.thermistorCount());
		std::unique_ptr<FogLogWriter> rawlog_out;
		std::unique_ptr<CompensatedCsvWriter> csv_out;
		if (ext == ".csv") csv_out = std::make_unique<CompensatedCsvWriter>(out, layout, axis_letter, arg_cal.getValue());
		else rawlog_out = std::make_unique<FogLogWriter>(out, layout, RawlogForm::Stock);
		// Turn-ons for the warm-up term (as compensate() does): before the log, and 0 -> 1 power steps.
		if (any_warmup)
		{
			try
			{
				for (std::size_t i = 0; i < comps.size(); i++)
					if (cals.axes[i].warmup) comps[i]->notePowerOnFromMetadata(layout);
			}
			catch (const std::invalid_argument& e)
			{
				throw withInput(e);
			}
		}
		app::Progress progress("fog-compensate", arg_quiet.getValue());
		FogSample x;
		std::vector<double> temps, raw(comps.size());
		std::vector<Compensator::Output> r(comps.size());
		app::PowerCycles power_cycles;
		while (reader.next(x))
		{
			temps = x.temp_C;  // the output keeps the temperatures as read
			if (screen) health.step(x.time_s, temps.data());
			const bool turn_on = power_cycles.add(x.power);
			for (std::size_t i = 0; i < comps.size(); i++)
			{
				if (turn_on && cals.axes[i].warmup) comps[i]->notePowerOn(x.time_s);
				raw[i] = x.rate_dph[axis_index[i]];
				if (comps[i]->readsField()) comps[i]->noteField(x.field_uT);  // NaN when the log has none
				r[i] = comps[i]->step(x.time_s, raw[i], temps.data());
			}
			if (csv_out) csv_out->write(x.time_s, raw, r, x.temp_C);
			else
			{
				for (std::size_t i = 0; i < comps.size(); i++) x.rate_dph[axis_index[i]] = r[i].compensated_dph;
				rawlog_out->write(x);
			}
			progress.update(reader.samplesRead(), reader.fileBytesRead(), reader.fileBytes());
		}
		if (csv_out) csv_out->close();
		else rawlog_out->close();
		progress.finish();
		ThermistorScreening screening;
		if (screen)
			for (std::size_t i = 0; i < layout.thermistorCount(); i++)
			{
				screening.names.push_back(layout.thermistors[i].name);
				screening.counters.push_back(health.counters(i));
				const auto& c = health.counters(i);
				screening.rejected_readings += c.out_of_range + c.spike + c.stuck;
			}
		const bool several = comps.size() > 1;
		std::printf("fog-compensate: %s -> %s (%zu samples, axis %s)\n", arg_in.getValue().c_str(), out.c_str(),
					comps.front()->counters().samples,
					several ? (std::string(axis_letter.begin(), axis_letter.end()) + " (one model each)").c_str()
							: std::string(1, axis_letter.front()).c_str());
		if (!uncalibrated.empty())
			std::printf("  axis %s: not in the calibration, written raw\n", uncalibrated.c_str());
		for (std::size_t i = 0; i < comps.size(); i++)
		{
			const auto& k = comps[i]->counters();
			const std::string ind = several ? "    " : "  ";
			if (several) std::printf("  axis %c:\n", axis_letter[i]);
			std::printf("%sfallback model used: %zu samples; no model (>= 2 thermistors missing): %zu samples\n",
						ind.c_str(), k.fallback_samples, k.no_model_samples);
			std::printf("%sclamped to the calibrated range: %zu samples (%zu signal values); rate warm-up: %zu samples; "
						"rate-free start-up model: %zu samples; model switches: %zu\n",
						ind.c_str(), k.clamped_samples, k.clamped_signals, k.warmup_samples, k.rate_free_samples,
						k.model_switches);
		}
		if (reader.hasPower())
			std::printf("  gyro off: %zu rows (bias tracked on the thermistors, no compensated sample where the rate "
						"is empty); turn-on events: %zu\n",
						power_cycles.gyro_off_rows, power_cycles.turn_ons);
		std::fputs(app::screeningText(screening, screen).c_str(), stdout);
		for (std::size_t i = 0; i < comps.size(); i++)
			std::fputs(app::outOfRangeWarning(comps[i]->counters(), cals.axes[i].extrapolation).c_str(), stdout);
		for (std::size_t i = 0; i < comps.size(); i++)
			std::fputs(app::fieldWarning(cals.axes[i], comps[i]->counters(), reader.hasField()).c_str(), stderr);
		if (!arg_json.getValue().empty())
		{
			JsonValue j = JsonValue::object();
			j["input"] = arg_in.getValue();
			j["input_notices"] = log_input.json();
			j["calibration"] = arg_cal.getValue();
			j["output"] = out;
			const auto& k = comps.front()->counters();
			const Calibration& cal = cals.axes.front();
			putCounters(j, k, true);
			j["gyro_off_rows"] = static_cast<unsigned long>(power_cycles.gyro_off_rows);
			j["turn_on_events"] = static_cast<unsigned long>(power_cycles.turn_ons);
			j["screening"] = app::screeningJson(screening, screen);
			j["out_of_range"] = app::outOfRangeJson(k, cal.extrapolation);
			if (cal.magnetic) j["magnetic"] = app::fieldJson(cal, k, reader.hasField());
			if (several)  // the counters above are the first calibrated axis'; every axis here
			{
				JsonValue& ja = j["axes"] = JsonValue::object();
				for (std::size_t i = 0; i < comps.size(); i++)
				{
					const auto& c = comps[i]->counters();
					JsonValue& a = ja[std::string(1, axis_letter[i])] = JsonValue::object();
					putCounters(a, c, false);
					a["out_of_range"] = app::outOfRangeJson(c, cals.axes[i].extrapolation);
					if (cals.axes[i].magnetic) a["magnetic"] = app::fieldJson(cals.axes[i], c, reader.hasField());
				}
			}
			writeTextFileAtomically(arg_json.getValue(), j.dump());
		}
		return app::kExitOk;
	});
}
