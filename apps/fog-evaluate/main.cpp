/* fog-evaluate: bias stability, range and Allan deviation of a FOG log, raw and compensated.
 *
 *   fog-evaluate -i IN [--cal CAL.yaml] [--axis x|y|z] [--tau 100] [--json F] [--plots DIR] [--label FOG]
 *
 * The bias is the gyro output (each axis of the log; with --cal each calibrated axis, a table
 * each) minus the applied table rate (when the log has one);
 * samples with the gyro powered off are left out. Earth rate is NOT removed: on a static run
 * its vertical component is a constant, which moves mean_dph only; stability, range,
 * peak-to-peak and the Allan deviation measure spread and are unaffected by it. */
#include "AppMain.h"
#include "LogInput.h"
#include "CommandLine.h"
#include "Options.h"
#include "Progress.h"
#include "PowerCycles.h"
#include "ThermistorScreeningReport.h"
#include "CalibrationSource.h"
#include "FieldWarning.h"
#include "RangeWarning.h"
#include "EvaluationPlots.h"
#include "RateEvaluation.h"
#include "AxisEvaluation.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/CalibrationYaml.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <optional>
#include <stdexcept>

using namespace mrpt_fog;
using namespace mrpt_fog::evaluate;

namespace
{
const char* const kHelp = R"(
AXES
  Each axis is evaluated in a table of its own: with --cal every axis the calibration holds
  (each compensated by its own model), without it every axis of the log; --axis picks one. With
  several axes, --json holds one object per axis under "axes". The log may be fog-compensate's
  output (its compensated rates are then the rates evaluated).

EXAMPLES
  fog-evaluate -i datasets/chamber_B.rawlog --cal cal.yaml --json eval.json
  fog-evaluate -i triad.rawlog --cal cal3.yaml --axis x
  fog-evaluate --format vendor.yaml -i vendor_run.csv --cal cal.yaml
)";

std::string num(double v, const char* f = "%.6g") { return std::isfinite(v) ? formatValue(f, v) : "n/a"; }

void printRow(const std::string& name, double raw, const RateEvaluation* comp, double comp_value)
{
	std::printf("  %-30s %14s", name.c_str(), num(raw).c_str());
	if (comp) std::printf(" %14s", num(comp_value).c_str());
	std::printf("\n");
}
}  // namespace

int main(int argc, char** argv)
{
	app::returnLargeBlocksToSystem();
	return app::runApp("fog-evaluate", [&] {
		TCLAP::CmdLine cmd("fog-evaluate: bias stability (std of tau-s averages), full-temperature range and Allan "
						   "deviation of a FOG log, raw and (with --cal) compensated",
						   ' ', "0.1");
		app::InputArg in("i", "input", "FOG log (.rawlog, .csv or .csv.gz)", true, "", "IN", cmd);
		app::InputArg cal("", "cal", "calibration YAML (fog-calibrate): also evaluate the compensated "
														"output",
										 false, "", "CAL.yaml", cmd);
		app::RealArg tau(cmd, "tau", "averaging time of the stability and range figures", "s",
						 app::Range::aboveUpTo(0, 1e6), 100.0, "S");
		app::OutputArg json("", "json", "write the figures as JSON", false, "", "F.json", cmd);
		app::OutputDirArg plots("", "plots",
										   "write bias_vs_time.png, bias_vs_temperature.png, allan_deviation.png here",
										   false, "", "DIR", cmd);
		TCLAP::ValueArg<std::string> label("", "label", "FOG sensor label in a rawlog with several", false, "", "FOG",
										   cmd);
		TCLAP::SwitchArg no_screen("", "no-screening",
								   "do not screen thermistor readings (stuck / spike / out of range -> dropout) before "
								   "compensating (fog-compensate's screening)",
								   cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "No progress line on stderr while the log is read", cmd);
		TCLAP::ValueArg<std::string> axis_arg("", "axis",
											  "evaluate this axis only (default: every calibrated axis with --cal, every "
											  "axis of the log without)",
											  false, "", "x|y|z", cmd);
		app::LogInput log_input(cmd, "fog-evaluate");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-evaluate", kHelp)) return *rc;

		const double tau_s = tau.getValue();

		const std::string path = in.getValue();
		// The log is read once into a run spilled to a temporary file, screened on the way as
		// fog-compensate screens it (so that a log gives the same compensated figures here and
		// there); the figures are computed in passes (memory independent of the log's length, issue 14).
		app::StreamScreening screener(!no_screen.getValue());
		app::Progress progress("fog-evaluate: reading " + path, quiet.getValue());
		const FogRun run = readFogRun(path, label.getValue(), screener.hook(),
									  [&](std::uint64_t n, std::uint64_t done, std::uint64_t total) { progress.update(n, done, total); },
									  log_input.options());
		progress.finish();
		const ThermistorScreening screening = screener.result(run);
		if (run.size() < 2) throw std::invalid_argument(path + ": fewer than 2 samples");

		// The axes: with --cal each calibrated axis (the compensator of each works on its own
		// axis), without it each axis of the log; --axis picks one.
		std::optional<GyroAxis> only;
		if (axis_arg.isSet())
		{
			const std::string& v = axis_arg.getValue();
			if (v != "x" && v != "y" && v != "z") throw std::invalid_argument("--axis must be x, y or z, got '" + v + "'");
			only = static_cast<GyroAxis>(v[0] - 'x');
		}
		const bool with_cal = !cal.getValue().empty();
		CalibrationSet cals;
		std::vector<GyroAxis> axes;
		if (with_cal)
		{
			cals = loadCalibrationSet(cal.getValue());
			for (const auto& c : cals.axes)
				if (!only || c.axis == *only) axes.push_back(c.axis);
			if (axes.empty())
				throw std::invalid_argument(cal.getValue() + ": no calibration for axis " + std::string(1, axisLetter(*only)) +
											" (--axis)");
		}
		else
		{
			for (int a = 0; a < 3; a++)
				if (run.header().has_axis[a] && (!only || static_cast<int>(*only) == a)) axes.push_back(static_cast<GyroAxis>(a));
			if (axes.empty())
				throw std::invalid_argument(path + ": the log has no axis " + std::string(1, axisLetter(*only)) + " (--axis)");
		}
		std::vector<AxisReport> reports;
		for (GyroAxis a : axes)
		{
			if (!run.header().has_axis[static_cast<int>(a)])
				throw std::invalid_argument(cal.getValue() + ": cannot compensate this log: the calibration's axis " +
											std::string(1, axisLetter(a)) + " is not in " + path);
			reports.push_back(evaluateAxis(run, path, a, with_cal ? cals.forAxis(a) : nullptr, cal.getValue(), tau_s));
		}
		const bool several = reports.size() > 1;

		const double duration_s = run.backTime_s() - run.frontTime_s();
		for (const AxisReport& r : reports)
		{
			const RateEvaluation& raw = r.raw;
			const RateEvaluation* comp = r.comp.get();
			std::printf("fog-evaluate: %s: %zu samples, %.1f s, axis %c, tau %g s (%zu windows, tail %.1f s dropped)\n",
						path.c_str(), run.size(), duration_s, axisLetter(r.axis), tau_s, raw.stats.window_count,
						raw.stats.dropped_tail_s);
			std::printf("  %-30s %14s%s\n", "", "raw",
						!comp ? "" : r.compensation->in_sample ? "  compensated*" : "    compensated");
			printRow("bias stability [deg/h]", raw.stats.stability_dph, comp, comp ? comp->stats.stability_dph : 0);
			printRow("full-temp. range [deg/h]", raw.stats.range_dph, comp, comp ? comp->stats.range_dph : 0);
			printRow("raw peak-to-peak [deg/h]", raw.stats.raw_peak_to_peak_dph, comp,
					 comp ? comp->stats.raw_peak_to_peak_dph : 0);
			printRow("mean bias [deg/h]", raw.stats.mean_dph, comp, comp ? comp->stats.mean_dph : 0);
			printRow("ARW N [deg/sqrt(h)]", raw.terms.arw_dpsh, comp, comp ? comp->terms.arw_dpsh : 0);
			printRow("bias instability B [deg/h]", raw.terms.bias_instability_dph, comp,
					 comp ? comp->terms.bias_instability_dph : 0);
			printRow("rate random walk K [deg/h/sqrt(h)]", raw.terms.rrw_dphsh, comp, comp ? comp->terms.rrw_dphsh : 0);
			printRow("quantisation Q [arcsec]", raw.terms.quantization_arcsec, comp,
					 comp ? comp->terms.quantization_arcsec : 0);
			if (r.compensation)
			{
				const auto& k = r.compensation->counters;
				std::printf("  compensator: %zu fallback, %zu no-model, %zu clamped, %zu rate-warm-up, %zu rate-free start-up "
							"samples\n",
							k.fallback_samples, k.no_model_samples, k.clamped_samples, k.warmup_samples, k.rate_free_samples);
				if (r.compensation->in_sample) std::printf("  * in-sample: this log is one of the calibration's runs\n");
				std::fputs(app::outOfRangeWarning(k, r.compensation->extrapolation).c_str(), stdout);
				std::fputs(app::fieldWarning(r.compensation->calibration, k, r.compensation->log_has_field).c_str(), stderr);
			}
		}
		const app::PowerCycles& power_cycles = reports.front().power_cycles;
		if (with_cal) std::fputs(app::screeningText(screening, !no_screen.getValue()).c_str(), stdout);
		if (power_cycles.gyro_off_rows)
			std::printf("  gyro off: %zu rows (no gyro sample: left out of every figure, thermistors kept); turn-on "
						"events: %zu\n",
						power_cycles.gyro_off_rows, power_cycles.turn_ons);
		std::printf("  (Earth rate is not removed: it is in the mean only; stability, range and Allan terms "
					"measure spread)\n");

		std::vector<std::string> figures;
		if (!plots.getValue().empty())
		{
			// The plots read the run and the bias rows in passes (memory: what they draw); one axis.
			const AxisReport& r = reports.front();
			if (several)
				std::printf("  plots: axis %c (the first evaluated; --axis picks another)\n", axisLetter(r.axis));
			PlotInputs pin;
			pin.run = &run;
			pin.rows = &r.rows;
			pin.raw = &r.raw;
			pin.comp = r.comp.get();
			pin.tau_s = tau_s;
			figures = writeEvaluationPlots(plots.getValue(), pin);
			for (const auto& f : figures) std::printf("  wrote %s\n", f.c_str());
		}

		if (!json.getValue().empty())
		{
			const auto axisJson = [&](const AxisReport& r) {
				JsonValue j = JsonValue::object();
				j["axis"] = std::string(1, axisLetter(r.axis));
				j["raw"] = toJson(r.raw);
				if (r.comp)
				{
					const RateEvaluation& comp = *r.comp;
					j["compensated"] = toJson(comp);
					const auto& k = r.compensation->counters;
					j["compensated"]["in_sample"] = r.compensation->in_sample;
					j["compensated"]["fallback_samples"] = k.fallback_samples;
					j["compensated"]["no_model_samples"] = k.no_model_samples;
					j["compensated"]["clamped_samples"] = k.clamped_samples;
					j["compensated"]["rate_warmup_samples"] = k.warmup_samples;
					j["compensated"]["rate_free_samples"] = k.rate_free_samples;
					j["compensated"]["out_of_range"] = app::outOfRangeJson(k, r.compensation->extrapolation);
					if (r.compensation->calibration.magnetic)
						j["compensated"]["magnetic"] =
							app::fieldJson(r.compensation->calibration, k, r.compensation->log_has_field);
					j["improvement"]["stability_ratio"] = r.raw.stats.stability_dph / comp.stats.stability_dph;
					j["improvement"]["range_ratio"] = r.raw.stats.range_dph / comp.stats.range_dph;
				}
				return j;
			};
			JsonValue j = JsonValue::object();
			j["input"] = path;
			j["input_notices"] = log_input.json();
			j["samples"] = run.size();
			j["duration_s"] = duration_s;
			if (!several)
			{
				JsonValue one = axisJson(reports.front());
				j["axis"] = one["axis"];
			}
			j["tau_s"] = tau_s;
			j["stability_definition"] = "std (N-1) of non-overlapping tau_s averages of gyro rate minus table rate";
			j["earth_rate"] = "not removed: a constant, it moves mean_dph only";
			j["gyro_off_rows"] = static_cast<unsigned long>(power_cycles.gyro_off_rows);
			j["turn_on_events"] = static_cast<unsigned long>(power_cycles.turn_ons);
			if (several)
			{
				JsonValue& ja = j["axes"] = JsonValue::object();
				for (const auto& r : reports) ja[std::string(1, axisLetter(r.axis))] = axisJson(r);
			}
			else
			{
				JsonValue one = axisJson(reports.front());
				j["raw"] = one["raw"];
				if (with_cal)
				{
					j["compensated"] = one["compensated"];
					j["improvement"] = one["improvement"];
				}
			}
			if (with_cal)
			{
				j["calibration"] = cal.getValue();
				j["screening"] = app::screeningJson(screening, !no_screen.getValue());
			}
			JsonValue fj = JsonValue::array();
			for (const auto& f : figures) fj.push_back(f);
			j["plots"] = fj;
			writeTextFileAtomically(json.getValue(), j.dump());
		}
		return 0;
	});
}
