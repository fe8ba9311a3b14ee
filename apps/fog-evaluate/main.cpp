/* fog-evaluate: bias stability, range and Allan deviation of a FOG log, raw and compensated.
 *
 *   fog-evaluate -i IN [--cal CAL.yaml] [--tau 100] [--json F] [--plots DIR] [--label FOG]
 *
 * The bias is the gyro output (primary axis; with --cal the calibrated axis) minus the applied
 * table rate (when the log has one);
 * samples with the gyro powered off are left out. Earth rate is NOT removed: on a static run
 * its vertical component is a constant, which moves mean_dph only; stability, range,
 * peak-to-peak and the Allan deviation measure spread and are unaffected by it. */
#include "AppMain.h"
#include "CommandLine.h"
#include "Progress.h"
#include "PowerCycles.h"
#include "ThermistorScreeningReport.h"
#include "CalibrationSource.h"
#include "FieldWarning.h"
#include "RangeWarning.h"
#include "EvaluationPlots.h"
#include "RateEvaluation.h"

#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/io/FogLogIO.h>

#include <cmath>
#include <cstdio>
#include <iostream>
#include <memory>
#include <stdexcept>

using namespace mrpt_fog;
using namespace mrpt_fog::evaluate;

namespace
{
const char* const kHelp = R"(
EXAMPLES
  fog-evaluate -i datasets/chamber_B.rawlog
  fog-evaluate -i datasets/chamber_B.rawlog --cal cal.yaml --json ev.json --plots plots/
  fog-evaluate -i run.csv --cal cal.yaml --tau 300
)";
}  // namespace

namespace
{
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
		TCLAP::ValueArg<std::string> in("i", "input", "FOG log (.rawlog, .csv or .csv.gz)", true, "", "IN", cmd);
		TCLAP::ValueArg<std::string> cal("", "cal", "calibration YAML (fog-calibrate): also evaluate the compensated "
														"output",
										 false, "", "CAL.yaml", cmd);
		TCLAP::ValueArg<double> tau("", "tau", "averaging time of the stability and range figures [s]", false, 100.0,
									"S", cmd);
		TCLAP::ValueArg<std::string> json("", "json", "write the figures as JSON", false, "", "F.json", cmd);
		TCLAP::ValueArg<std::string> plots("", "plots",
										   "write bias_vs_time.png, bias_vs_temperature.png, allan_deviation.png here",
										   false, "", "DIR", cmd);
		TCLAP::ValueArg<std::string> label("", "label", "FOG sensor label in a rawlog with several", false, "", "FOG",
										   cmd);
		TCLAP::SwitchArg no_screen("", "no-screening",
								   "do not screen thermistor readings (stuck / spike / out of range -> dropout) before "
								   "compensating (fog-compensate's screening)",
								   cmd);
		TCLAP::SwitchArg quiet("q", "quiet", "No progress line on stderr while the log is read", cmd);
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-evaluate", kHelp)) return *rc;

		const double tau_s = tau.getValue();
		if (!std::isfinite(tau_s) || tau_s <= 0)
			throw std::invalid_argument("--tau must be a positive number of seconds, got " + num(tau_s));

		const std::string path = in.getValue();
		requireSafeOutputs({{"-i", path}, {"--cal", cal.getValue()}}, {{"--json", json.getValue()}});
		// The log is read once into a run spilled to a temporary file, screened on the way as
		// fog-compensate screens it (so that a log gives the same compensated figures here and
		// there); the figures are computed in passes (memory independent of the log's length).
		app::StreamScreening screener(!no_screen.getValue());
		app::Progress progress("fog-evaluate: reading " + path, quiet.getValue());
		const FogRun run = readFogRun(path, label.getValue(), screener.hook(),
									  [&](std::uint64_t n, std::uint64_t done, std::uint64_t total) { progress.update(n, done, total); });
		progress.finish();
		const ThermistorScreening screening = screener.result(run);
		if (run.size() < 2) throw std::invalid_argument(path + ": fewer than 2 samples");

		// With --cal the compensator works on the calibrated axis, and the raw figures are of that
		// same axis; without it, of the log's primary axis. Rows: time, raw bias [, compensated
		// bias] (bias = rate minus table rate, NaN while the gyro is off).
		const bool with_cal = !cal.getValue().empty();
		std::unique_ptr<CompensationResult> comp_series;
		RowSpill rows(with_cal ? 3 : 2);
		const auto biasAt = [](const FogSeries& c, std::size_t j, double rate) {
			if (!c.table_rate_dph.empty()) rate -= c.table_rate_dph[j];
			if (!c.power.empty() && c.power[j] == 0.0) rate = NAN;
			return rate;
		};
		// Gyro-off rows and turn-on events (0 -> 1 power steps), counted in the raw pass (apps/common/PowerCycles.h).
		app::PowerCycles power_cycles;
		const auto notePower = [&](const FogSeries& c, std::size_t j) {
			power_cycles.add(c.power.empty() ? NAN : c.power[j]);
		};
		if (with_cal)
		{
			GyroAxis cal_axis = GyroAxis::Z;
			comp_series = std::make_unique<CompensationResult>(compensateWithCalibration(
				cal.getValue(), path, run,
				[&](const FogSeries& c, std::size_t, std::size_t j0, std::size_t m, const Compensator::Output* out) {
					for (std::size_t j = j0; j < j0 + m; j++)
					{
						const double row[3] = {c.time_s[j], 0.0, biasAt(c, j, out[j - j0].compensated_dph)};
						rows.push(row);
					}
				}));
			cal_axis = comp_series->axis;
			// The raw column of the same rows (a second pass over the run).
			RowSpill with_raw(3);
			RowSpill::Reader rd(rows);
			const int a = static_cast<int>(cal_axis);
			run.forEachChunk([&](const FogSeries& c, std::size_t) {
				for (std::size_t j = 0; j < c.size(); j++)
				{
					const double* r = rd.next();
					notePower(c, j);
					const double row[3] = {r[0], biasAt(c, j, c.rate_dph[a][j]), r[2]};
					with_raw.push(row);
				}
			});
			rows = std::move(with_raw);
		}
		else
		{
			const int a = static_cast<int>(run.header().primaryAxis());
			run.forEachChunk([&](const FogSeries& c, std::size_t) {
				for (std::size_t j = 0; j < c.size(); j++)
				{
					notePower(c, j);
					const double row[2] = {c.time_s[j], biasAt(c, j, c.rate_dph[a][j])};
					rows.push(row);
				}
			});
		}
		const char axis = axisLetter(comp_series ? comp_series->axis : run.header().primaryAxis());
		RateEvaluation raw;
		std::unique_ptr<RateEvaluation> comp;
		try
		{
			raw = evaluateRate(rows, 1, tau_s);
			if (comp_series) comp = std::make_unique<RateEvaluation>(evaluateRate(rows, 2, tau_s));
		}
		catch (const std::invalid_argument& e)
		{
			throw std::invalid_argument(path + ": " + e.what());
		}

		const double duration_s = run.backTime_s() - run.frontTime_s();
		std::printf("fog-evaluate: %s: %zu samples, %.1f s, axis %c, tau %g s (%zu windows, tail %.1f s dropped)\n",
					path.c_str(), run.size(), duration_s, axis, tau_s,
					raw.stats.window_count, raw.stats.dropped_tail_s);
		std::printf("  %-30s %14s%s\n", "", "raw",
					!comp ? "" : comp_series->in_sample ? "  compensated*" : "    compensated");
		printRow("bias stability [deg/h]", raw.stats.stability_dph, comp.get(), comp ? comp->stats.stability_dph : 0);
		printRow("full-temp. range [deg/h]", raw.stats.range_dph, comp.get(), comp ? comp->stats.range_dph : 0);
		printRow("raw peak-to-peak [deg/h]", raw.stats.raw_peak_to_peak_dph, comp.get(),
				 comp ? comp->stats.raw_peak_to_peak_dph : 0);
		printRow("mean bias [deg/h]", raw.stats.mean_dph, comp.get(), comp ? comp->stats.mean_dph : 0);
		printRow("ARW N [deg/sqrt(h)]", raw.terms.arw_dpsh, comp.get(), comp ? comp->terms.arw_dpsh : 0);
		printRow("bias instability B [deg/h]", raw.terms.bias_instability_dph, comp.get(),
				 comp ? comp->terms.bias_instability_dph : 0);
		printRow("rate random walk K [deg/h/sqrt(h)]", raw.terms.rrw_dphsh, comp.get(),
				 comp ? comp->terms.rrw_dphsh : 0);
		printRow("quantisation Q [arcsec]", raw.terms.quantization_arcsec, comp.get(),
				 comp ? comp->terms.quantization_arcsec : 0);
		if (comp_series)
		{
			const auto& k = comp_series->counters;
			std::printf("  compensator: %zu fallback, %zu no-model, %zu clamped, %zu rate-warm-up, %zu rate-free start-up "
						"samples\n",
						k.fallback_samples, k.no_model_samples, k.clamped_samples, k.warmup_samples, k.rate_free_samples);
			if (comp_series->in_sample)
				std::printf("  * in-sample: this log is one of the calibration's runs\n");
			std::fputs(app::outOfRangeWarning(k, comp_series->extrapolation).c_str(), stdout);
			std::fputs(app::fieldWarning(comp_series->calibration, k, comp_series->log_has_field).c_str(), stderr);
		}
		if (comp_series) std::fputs(app::screeningText(screening, !no_screen.getValue()).c_str(), stdout);
		if (power_cycles.gyro_off_rows)
			std::printf("  gyro off: %zu rows (no gyro sample: left out of every figure, thermistors kept); turn-on "
						"events: %zu\n",
						power_cycles.gyro_off_rows, power_cycles.turn_ons);
		std::printf("  (Earth rate is not removed: it is in the mean only; stability, range and Allan terms "
					"measure spread)\n");

		std::vector<std::string> figures;
		if (!plots.getValue().empty())
		{
			// The plots read the run and the bias rows in passes (memory: what they draw).
			PlotInputs pin;
			pin.run = &run;
			pin.rows = &rows;
			pin.raw = &raw;
			pin.comp = comp.get();
			pin.tau_s = tau_s;
			figures = writeEvaluationPlots(plots.getValue(), pin);
			for (const auto& f : figures) std::printf("  wrote %s\n", f.c_str());
		}

		if (!json.getValue().empty())
		{
			JsonValue j = JsonValue::object();
			j["input"] = path;
			j["samples"] = run.size();
			j["duration_s"] = duration_s;
			j["axis"] = std::string(1, axis);
			j["tau_s"] = tau_s;
			j["stability_definition"] = "std (N-1) of non-overlapping tau_s averages of gyro rate minus table rate";
			j["earth_rate"] = "not removed: a constant, it moves mean_dph only";
			j["gyro_off_rows"] = static_cast<unsigned long>(power_cycles.gyro_off_rows);
			j["turn_on_events"] = static_cast<unsigned long>(power_cycles.turn_ons);
			j["raw"] = toJson(raw);
			if (comp)
			{
				j["calibration"] = cal.getValue();
				j["compensated"] = toJson(*comp);
				const auto& k = comp_series->counters;
				j["compensated"]["in_sample"] = comp_series->in_sample;
				j["compensated"]["fallback_samples"] = k.fallback_samples;
				j["compensated"]["no_model_samples"] = k.no_model_samples;
				j["compensated"]["clamped_samples"] = k.clamped_samples;
				j["compensated"]["rate_warmup_samples"] = k.warmup_samples;
				j["compensated"]["rate_free_samples"] = k.rate_free_samples;
				j["compensated"]["out_of_range"] = app::outOfRangeJson(k, comp_series->extrapolation);
				if (comp_series->calibration.magnetic)
					j["compensated"]["magnetic"] = app::fieldJson(comp_series->calibration, k, comp_series->log_has_field);
				j["screening"] = app::screeningJson(screening, !no_screen.getValue());
				j["improvement"]["stability_ratio"] = raw.stats.stability_dph / comp->stats.stability_dph;
				j["improvement"]["range_ratio"] = raw.stats.range_dph / comp->stats.range_dph;
			}
			JsonValue fj = JsonValue::array();
			for (const auto& f : figures) fj.push_back(f);
			j["plots"] = fj;
			writeTextFileAtomically(json.getValue(), j.dump());
		}
		return 0;
	});
}
