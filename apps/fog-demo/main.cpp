/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* fog-demo: the main job end to end. Calibrates the multi-point model on chamber run A,
 * validates it on run B, compensates the vehicle drive and compares heading drift of the raw,
 * compensated and ideal gyros; writes a report folder. Runs the project's own programs so that
 * every figure in the report comes with the command that reproduces it. */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/NumberFormat.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "AppMain.h"
#include "CommandLine.h"
#include "Options.h"
#include "JsonFigures.h"
#include "StepRunner.h"

using namespace mrpt_fog;
using namespace mrpt_fog::demo;
namespace fs = std::filesystem;

namespace
{
const char* const kHelp = R"(
WHAT IT DOES
  The main job of mrpt_fog, end to end, on the bundled datasets (datasets/, simulated by
  fog-sim; missing files are simulated into <out>/datasets first):
   1. fog-calibrate, the default calibration: every calibration run the datasets hold
      (chamber runs A and C, the rate-table runs, the cold-start runs) and no other option; the
      model is chosen from the data (bias terms by held-out error, the warm-up term from the
      turn-ons, the scale factor from the rate tables: docs/guide/calibration.md), validated on
      chamber run B (a different temperature profile, never seen by the fit); also chamber run A
      alone and runs A + C, each validated on B;
   2. fog-evaluate: 100 s bias stability, range and Allan deviation, raw vs compensated, on
      A (in-sample) and B (held out), with plots;
   3. fog-drift: compensate the vehicle drive sample by sample (causal, as in real time),
      integrate heading with the Earth rate removed and dead-reckon with the wheel odometry,
      for the raw, compensated and ideal (no thermal error) gyros, against the ground truth;
   4. fog-localize (when built): MRPT particle-filter localization on a simulated world around
      the drive, odometry heading from the raw / compensated / ideal FOG, 5 filter seeds:
      position RMS on the observation-poor (open-field) stretches, with the default calibration;
   5. fog-paper (when built): the seed paper's Tables 1-3 beside ours;
   6. stages of the thermal error model, each compensating the bundled drive plus --drives
      simulated drives (fog-sim --profile drive, seeds 11.., cabins winter / mild / hot in
      turn; fog-drift -i ... over all of them): bias only (chamber A), + scale factor vs
      temperature (+ the rate-table runs), and the default calibration (every run: + warm-up
      and the second chamber run), as an explanation of what each part buys; the median
      heading RMS of the default calibration over the drives leads the report. Stages whose
      runs the datasets folder lacks are skipped, said in the report.
  The report folder holds summary.md (key figures, tables, the command behind each), the
  calibration YAML, every program's JSON, PNG plots and logs.

EXAMPLES
  fog-demo --out report
  fog-demo --drives 2 --out quick_report
  fog-demo --no-stages --out quicker_report
  fog-demo --datasets /path/to/datasets --out report
)";

std::string fmt(double v, const char* f = "%.4g") { return std::isfinite(v) ? formatValue(f, v) : "n/a"; }

std::string ratio(double num, double den)
{
	if (!std::isfinite(num) || !std::isfinite(den) || den == 0) return "n/a";
	return fmt(num / den, "%.3g");
}

const char* const kMarker = ".fog-demo-report";

/** The output folder: created if absent; an existing non-empty folder is only reused when a
 * previous fog-demo made it (nothing else the user had is overwritten). */
void prepareOutDir(const fs::path& out)
{
	if (fs::exists(out))
	{
		if (!fs::is_directory(out)) throw std::runtime_error("--out '" + out.string() + "' exists and is not a directory");
		if (!fs::is_empty(out) && !fs::exists(out / kMarker))
			throw std::runtime_error("--out '" + out.string() +
									 "' is a non-empty folder not made by fog-demo; refusing to write into it");
	}
	fs::create_directories(out);
	writeTextFileAtomically((out / kMarker).string(), "written by fog-demo\n");
}

struct Datasets
{
	std::string chamber_A, chamber_B, drive;
};

fs::path defaultDatasetsDir()
{
	if (fs::exists("datasets/chamber_A.rawlog")) return "datasets";
	return fs::path(MRPT_FOG_SOURCE_DIR) / "datasets";
}

}  // namespace

int main(int argc, char** argv)
{
	return app::runApp("fog-demo", [&]() -> int {
		TCLAP::CmdLine cmd("fog-demo: mrpt_fog end to end (calibrate, validate, compensate, navigate)", ' ', "0.1");
		app::OutputDirArg arg_out("o", "out", "report folder [default: fog-demo-report]", false,
											 "fog-demo-report", "DIR", cmd);
		app::InputArg arg_data("d", "datasets",
											  "folder with chamber_A.rawlog, chamber_B.rawlog, drive.rawlog "
											  "[default: ./datasets, else the source tree's datasets/]",
											  false, "", "DIR", cmd);
		TCLAP::ValueArg<std::string> arg_model("m", "model", "bias-model preset [default: multipoint]", false,
											   "multipoint", "PRESET", cmd);
		app::CountArg arg_drives(cmd, "drives",
								 "simulated drives (besides the bundled one) for the stage figures [default: 9]",
								 "drives", 0, 100, 9);
		TCLAP::SwitchArg arg_no_stages("", "no-stages",
									   "bias-only stage on the bundled drive only (no rate-table / warm-up calibrations, no "
									   "simulated drives): a quicker run",
									   cmd);
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-demo", kHelp)) return *rc;

		const fs::path out = fs::absolute(arg_out.getValue());
		prepareOutDir(out);
		const fs::path data = fs::absolute(arg_data.getValue().empty() ? defaultDatasetsDir() : fs::path(arg_data.getValue()));
		const fs::path json = out / "json", plots = out / "plots";
		fs::create_directories(json);
		fs::create_directories(plots);

		// Which datasets must be simulated first.
		struct Need
		{
			const char* file;
			const char* profile;
		};
		const Need needs[] = {{"chamber_A.rawlog", "seed"}, {"chamber_B.rawlog", "B"}, {"drive.rawlog", "drive"}};
		std::vector<Need> missing;
		for (const auto& n : needs)
			if (!fs::exists(data / n.file)) missing.push_back(n);

		const std::string bin = executableDir();
		StepRunner tmp_probe(bin, (out / "logs").string(), 0);
		bool have_paper = true;
		try
		{
			tmp_probe.program("fog-paper");
		}
		catch (const std::exception&)
		{
			have_paper = false;
		}
		bool have_localize = true;
		try
		{
			tmp_probe.program("fog-localize");
		}
		catch (const std::exception&)
		{
			have_localize = false;
		}
		// The calibration runs the datasets hold (the default calibration takes every one) and the
		// stages of the thermal error model (the runs each needs must be in the datasets folder).
		const fs::path table_run = data / "ratetable_A.rawlog", warm_run = data / "warmup.rawlog";
		const fs::path transient_run = data / "ratetable_transient.rawlog";
		const fs::path warm_run_b = data / "warmup_B.rawlog";
		const fs::path second_chamber_run = data / "chamber_C.rawlog";
		const bool have_transient = fs::exists(transient_run);
		const std::string table_runs = have_transient ? "rate table A + transient rate table" : "rate table A";
		const bool stages_on = !arg_no_stages.getValue();
		const bool have_table = stages_on && fs::exists(table_run);
		const bool have_second_chamber = fs::exists(second_chamber_run);
		std::vector<fs::path> other_runs;  // every calibration run besides chamber A, in this order
		for (const fs::path& r : {second_chamber_run, table_run, transient_run, warm_run, warm_run_b})
			if (fs::exists(r)) other_runs.push_back(r);
		const bool default_stage = stages_on && !other_runs.empty();
		const int n_drives = stages_on ? arg_drives.get<int>() : 0;
		const int stage_steps = n_drives + 1 + (have_table ? 2 : 0) + (default_stage ? 1 : 0);
		const int total = static_cast<int>(missing.size()) + 5 + (have_second_chamber ? 1 : 0) + (have_paper ? 1 : 0) +
						  (have_localize ? 1 : 0) + stage_steps;
		StepRunner run(bin, (out / "logs").string(), total);

		std::cout << "fog-demo: datasets from " << data.string() << ", report in " << out.string() << "\n";
		Datasets ds;
		auto path_of = [&](const char* file) -> std::string {
			for (const auto& m : missing)
				if (std::string(m.file) == file) return (out / "datasets" / file).string();
			return (data / file).string();
		};
		for (const auto& m : missing)
		{
			fs::create_directories(out / "datasets");
			run.run({std::string("sim_") + m.profile,
					 std::string("simulating ") + m.file + " (profile " + m.profile + "; not found in " + data.string() + ")",
					 {run.program("fog-sim"), "--profile", m.profile, "--seed", "20240501", "--rate-hz", "10", "-o",
					  path_of(m.file)}});
		}
		ds.chamber_A = path_of("chamber_A.rawlog");
		ds.chamber_B = path_of("chamber_B.rawlog");
		ds.drive = path_of("drive.rawlog");
		const std::string cal = (out / "calibration.yaml").string();

		const std::string cal_A = (out / "calibration_chamber_A.yaml").string();
		// the model preset only when asked for (the default chooses from the data)
		std::vector<std::string> model_arg;
		if (arg_model.isSet()) model_arg = {"--model", arg_model.getValue()};
		{
			std::vector<std::string> argv{run.program("fog-calibrate"), "-i", ds.chamber_A};
			for (const auto& r : other_runs) argv.insert(argv.end(), {"-i", r.string()});
			argv.insert(argv.end(), model_arg.begin(), model_arg.end());
			argv.insert(argv.end(), {"--validate", ds.chamber_B, "-o", cal, "--json", (json / "calibrate.json").string()});
			run.run({"calibrate",
					 "the default calibration: every calibration run of the datasets (" + std::to_string(1 + other_runs.size()) +
						 "), nothing else; validating on run B",
					 argv});
		}
		{
			std::vector<std::string> argv{run.program("fog-calibrate"), "-i", ds.chamber_A};
			argv.insert(argv.end(), model_arg.begin(), model_arg.end());
			argv.insert(argv.end(), {"--validate", ds.chamber_B, "-o", cal_A, "--json", (json / "calibrate_A.json").string()});
			run.run({"calibrate_A", "calibrating on chamber run A alone, validating on run B", argv});
		}
		if (have_second_chamber)
			run.run({"calibrate_two_runs",
					 "calibrating '" + arg_model.getValue() + "' on chamber runs A + C (a sine, 2-3 C/min ramps), validating on run B",
					 {run.program("fog-calibrate"), "-i", ds.chamber_A, "-i", second_chamber_run.string(), "--model",
					  arg_model.getValue(), "--validate", ds.chamber_B, "-o", (out / "calibration_two_runs.yaml").string(),
					  "--json", (json / "calibrate_two_runs.json").string()}});
		run.run({"evaluate_A", "evaluating on chamber run A (in-sample)",
				 {run.program("fog-evaluate"), "-i", ds.chamber_A, "--cal", cal, "--json", (json / "evaluate_A.json").string(),
				  "--plots", (plots / "chamber_A").string()}});
		run.run({"evaluate_B", "evaluating on chamber run B (held out)",
				 {run.program("fog-evaluate"), "-i", ds.chamber_B, "--cal", cal, "--json", (json / "evaluate_B.json").string(),
				  "--plots", (plots / "chamber_B").string()}});
		run.run({"drift", "compensating the vehicle drive and comparing heading drift",
				 {run.program("fog-drift"), "-i", ds.drive, "--cal", cal, "--json", (json / "drift.json").string(), "--plots",
				  (plots / "drift").string(), "--odometry-out", (out / "odometry_compensated.rawlog").string()}});
		if (have_localize)
		{
			run.run({"localize",
					 "MRPT particle-filter localization with raw / compensated / ideal FOG heading (fog-localize; the "
					 "default calibration)",
					 {run.program("fog-localize"), "--drive", ds.drive, "--cal", cal, "--out", (out / "localize").string(),
					  "--json", (json / "localize.json").string()}});
		}
		if (have_paper)
		{
			fs::create_directories(plots / "paper");
			run.run({"paper", "reproducing the seed paper's Tables 1-3 on runs A and B (fog-paper)",
					 {run.program("fog-paper"), "--run-a", ds.chamber_A, "--run-b", ds.chamber_B, "--json",
					  (json / "paper.json").string(), "--plots", (plots / "paper").string()}});
		}

		// 6. stages over several drives
		struct Stage
		{
			std::string id, label, runs, cal;
		};
		std::vector<Stage> stages{{"bias", "bias only", "chamber A", cal_A}};
		const std::string cal_sf = (out / "calibration_scale_factor.yaml").string();
		if (have_table)
		{
			std::vector<std::string> argv{run.program("fog-calibrate"), "-i", ds.chamber_A, "-i", table_run.string()};
			if (have_transient) argv.insert(argv.end(), {"-i", transient_run.string()});
			argv.insert(argv.end(), model_arg.begin(), model_arg.end());
			// these runs hold a turn-on only in the transient table run: the stage is bias + scale factor
			argv.insert(argv.end(), {"-o", cal_sf, "--json", (json / "calibrate_scale_factor.json").string()});
			run.run({"calibrate_scale_factor", "stage + scale factor: calibrating on chamber run A + the rate-table run(s)", argv});
			stages.push_back({"scale_factor", "+ scale factor vs temperature", "chamber A + " + table_runs, cal_sf});
		}
		if (default_stage)
		{
			std::string runs = "chamber A";
			for (const auto& r : other_runs) runs += " + " + r.stem().string();
			stages.push_back({"default", "the default calibration (every run; + warm-up from the turn-ons)", runs, cal});
		}
		std::vector<std::string> drive_inputs{ds.drive};
		const char* const cabins[] = {"drive_cabin", "drive_cabin_mild", "drive_cabin_hot"};
		if (n_drives > 0) fs::create_directories(out / "drives");
		for (int k = 0; k < n_drives; k++)
		{
			const std::string seed = std::to_string(11 + k), cabin = cabins[k % 3];
			const std::string f = (out / "drives" / ("drive_seed" + seed + "_" + cabin + ".rawlog")).string();
			run.run({"sim_drive_" + seed, "simulating drive seed " + seed + " (" + cabin + ")",
					 {run.program("fog-sim"), "--profile", "drive", "--cabin", cabin, "--seed", seed, "-o", f}});
			drive_inputs.push_back(f);
		}
		for (const auto& st : stages)
		{
			std::vector<std::string> argv{run.program("fog-drift")};
			for (const auto& d : drive_inputs) argv.insert(argv.end(), {"-i", d});
			argv.insert(argv.end(), {"--cal", st.cal, "--json", (json / ("drives_" + st.id + ".json")).string()});
			run.run({"drives_" + st.id,
					 "stage '" + st.label + "': heading over " + std::to_string(drive_inputs.size()) + " drive(s)", argv});
		}
		// fog-drift writes over_drives only for several drives; one drive: its own figures
		const auto stageFigure = [&](const JsonFigures& j, const std::string& key, const char* q) {
			if (drive_inputs.size() > 1) return j.numberAt({"over_drives", key, q});
			const auto dot = key.find('.');
			if (key.rfind("ratio.", 0) == 0) return j.numberAt({"ratios", key.substr(6)});
			return j.numberAt({key.substr(0, dot), key.substr(dot + 1)});
		};

		const JsonFigures evA((json / "evaluate_A.json").string());
		const JsonFigures evB((json / "evaluate_B.json").string());
		const JsonFigures drift((json / "drift.json").string());

		const double rawB = evB.number("raw.stability_dph"), compB = evB.number("compensated.stability_dph");
		const double hRaw = drift.number("heading_error_final_deg.raw");
		const double hComp = drift.number("heading_error_final_deg.compensated");
		const double hIdeal = drift.number("heading_error_final_deg.ideal");

		std::ostringstream md;
		md << "# mrpt_fog demo report\n\n"
		   << "The default calibration (`fog-calibrate` on every calibration run of the datasets, no other option: the "
		   << "model chosen from the data), validated on chamber run B, applied causally to a vehicle drive; every "
		   << "section below uses it (`calibration.yaml`) unless it says otherwise. Datasets: `" << data.string() << "`.\n\n";
		md << "## Headline\n\n";
		{
			const JsonFigures last((json / ("drives_" + stages.back().id + ".json")).string());
			const std::string n = std::to_string(drive_inputs.size());
			const char* med = "median";
			md << "- Heading over " << n << " drive" << (drive_inputs.size() > 1 ? "s (median)" : "")
			   << ", calibration '" << stages.back().label << "' (" << stages.back().runs << "): heading RMS raw "
			   << fmt(stageFigure(last, "heading_error_rms_deg.raw", med)) << " deg, compensated "
			   << fmt(stageFigure(last, "heading_error_rms_deg.compensated", med)) << " deg, ideal gyro "
			   << fmt(stageFigure(last, "heading_error_rms_deg.ideal", med)) << " deg (compensated/raw "
			   << fmt(stageFigure(last, "ratio.heading_rms_compensated_over_raw", med), "%.3g") << ", target <= 0.1; "
			   << "compensated/ideal " << fmt(stageFigure(last, "ratio.heading_rms_compensated_over_ideal", med), "%.3g")
			   << ", target <= 2). Each stage's share: the table below.\n";
		}
		md << "- Held-out 100 s bias stability (run B): raw " << fmt(rawB) << " deg/h -> compensated " << fmt(compB)
		   << " deg/h (x" << ratio(compB, rawB) << ").\n";
		if (have_second_chamber)
		{
			const JsonFigures two((json / "calibrate_two_runs.json").string());
			const double raw2 = two.number("validation.raw.stability_dph"), comp2 = two.number("validation.compensated.stability_dph");
			md << "- The same with a two-run calibration (chamber runs A + C; C: a +-20 C sine of 30 min period and 2-3 C/min "
			   << "ramps, time scales run A never shows): raw " << fmt(raw2) << " deg/h -> compensated " << fmt(comp2)
			   << " deg/h (x" << ratio(comp2, raw2) << ", raw/compensated " << fmt(raw2 / comp2, "%.3g") << "; `calibration_two_runs.yaml`).\n";
		}
		md
		   << "- Final heading error after the drive: raw " << fmt(hRaw) << " deg, compensated " << fmt(hComp)
		   << " deg, ideal gyro " << fmt(hIdeal) << " deg (compensated/raw = " << ratio(hComp, hRaw)
		   << ", compensated/ideal = " << ratio(hComp, hIdeal) << ").\n"
		   << "- Final position error: raw " << fmt(drift.number("position_error_final_m.raw")) << " m, compensated "
		   << fmt(drift.number("position_error_final_m.compensated")) << " m, ideal "
		   << fmt(drift.number("position_error_final_m.ideal")) << " m over " << fmt(drift.number("distance_m") / 1000.0)
		   << " km.\n\n";
		md << "## Stages of the thermal error model, heading over " << drive_inputs.size() << " drive(s)\n\n"
		   << "Drives: the bundled one" << (n_drives > 0 ? " + fog-sim drives seeds 11.." + std::to_string(10 + n_drives) +
																  " (cabins winter / mild / hot in turn)"
															: std::string())
		   << ". Median [quartiles] over the drives"
		   << (drive_inputs.size() > 1 ? "" : " (one drive: its own figures)") << ".\n\n"
		   << "| stage | calibration runs | heading RMS compensated [deg] | compensated / raw | compensated / ideal | "
			  "drift between turns compensated / raw |\n"
		   << "|---|---|---|---|---|---|\n";
		for (const auto& st : stages)
		{
			const JsonFigures j((json / ("drives_" + st.id + ".json")).string());
			const auto cell = [&](const std::string& key, const char* f) {
				std::string c = fmt(stageFigure(j, key, "median"), f);
				if (drive_inputs.size() > 1)
					c += " [" + fmt(stageFigure(j, key, "q1"), f) + ", " + fmt(stageFigure(j, key, "q3"), f) + "]";
				return c;
			};
			md << "| " << st.label << " | " << st.runs << " | " << cell("heading_error_rms_deg.compensated", "%.3g")
			   << " | " << cell("ratio.heading_rms_compensated_over_raw", "%.3g") << " | "
			   << cell("ratio.heading_rms_compensated_over_ideal", "%.3g") << " | "
			   << cell("ratio.drift_between_turns_compensated_over_raw", "%.3g") << " |\n";
		}
		if (!stages_on) md << "\nScale-factor and warm-up stages and the simulated drives skipped (--no-stages).\n";
		else if (!have_table) md << "\nNo `ratetable_A.rawlog` in the datasets folder: the scale-factor and warm-up stages are skipped.\n";
		else if (!fs::exists(warm_run)) md << "\nNo `warmup.rawlog` in the datasets folder: no warm-up term in the default calibration.\n";
		md << "\nWhere the remaining error comes from (decomposition by simulator effect): docs/guide/heading-drift.md.\n\n";
		md << "## Bias (chamber runs, tau = 100 s)\n\n"
		   << "| run | raw stability [deg/h] | compensated stability [deg/h] | raw range [deg/h] | compensated range [deg/h] |\n"
		   << "|---|---|---|---|---|\n";
		for (const auto& [label, ev] : {std::pair<const char*, const JsonFigures*>{"A (in-sample: the fitted run)", &evA},
										{"B (held out: another profile)", &evB}})
			md << "| " << label << " | " << fmt(ev->number("raw.stability_dph")) << " | "
			   << fmt(ev->number("compensated.stability_dph")) << " | " << fmt(ev->number("raw.range_dph")) << " | "
			   << fmt(ev->number("compensated.range_dph")) << " |\n";
		md << "\n## Navigation (vehicle drive, " << fmt(drift.number("duration_s") / 60.0, "%.1f") << " min, "
		   << fmt(drift.number("distance_m") / 1000.0, "%.2f") << " km)\n\n"
		   << "| gyro | heading error final [deg] | heading error max [deg] | position error final [m] |\n"
		   << "|---|---|---|---|\n";
		for (const char* g : {"raw", "compensated", "ideal"})
			md << "| " << g << " | " << fmt(drift.number(std::string("heading_error_final_deg.") + g)) << " | "
			   << fmt(drift.number(std::string("heading_error_max_deg.") + g)) << " | "
			   << fmt(drift.number(std::string("position_error_final_m.") + g)) << " |\n";
		md << "\nRequirement (compensated heading drift <= 1/10 of raw and within 2x of the ideal gyro): "
		   << "compensated/raw = " << ratio(hComp, hRaw) << ", compensated/ideal = " << ratio(hComp, hIdeal)
		   << ". See README.md (Navigation) for why the simulated drive misses them where it does.\n";
		if (have_localize)
		{
			const JsonFigures loc((json / "localize.json").string());
			const double lr = loc.number("position_rms_m.raw"), lc = loc.number("position_rms_m.compensated"),
						 li = loc.number("position_rms_m.ideal");
			md << "\n## MRPT localization on the drive (fog-localize)\n\n"
			   << "Calibration of the compensated gyro: " << loc.text("calibration.description") << ".\n\n"
			   << "Particle filter on a simulated map around the route (laser scans), odometry heading from each gyro; "
			   << "position RMS on the open-field (observation-poor) stretches, pooled over the filter seeds: raw " << fmt(lr)
			   << " m, compensated " << fmt(lc) << " m, ideal " << fmt(li) << " m (compensated/raw = " << ratio(lc, lr)
			   << ", target <= 0.5; compensated/ideal = " << ratio(lc, li) << ", target <= 1.5); paired over the seeds, "
			   << "compensated - raw = " << fmt(loc.number("paired_open_rms_difference_m.compensated_minus_raw.mean"), "%+.2f")
			   << " +- " << fmt(loc.number("paired_open_rms_difference_m.compensated_minus_raw.standard_error"), "%.2f")
			   << " m (" << loc.text("paired_open_rms_difference_m.compensated_minus_raw.verdict")
			   << "; 'cannot tell' below 2 standard errors), compensated - ideal = "
			   << fmt(loc.number("paired_open_rms_difference_m.compensated_minus_ideal.mean"), "%+.2f") << " +- "
			   << fmt(loc.number("paired_open_rms_difference_m.compensated_minus_ideal.standard_error"), "%.2f") << " m ("
			   << loc.text("paired_open_rms_difference_m.compensated_minus_ideal.verdict")
			   << "). Can these fields judge the gyro? The ideal gyro gives "
			   << fmt(loc.number("heading_relevance.ideal_to_raw_position_rms"), "%.2f") << "x the raw position RMS: "
			   << loc.text("heading_relevance.verdict") << ". Map, rawlogs, "
			   << "pf-localization .ini files and plots: `localize/`; details: docs/guide/localization.md.\n";
		}
		if (have_paper)
		{
			const JsonFigures paper((json / "paper.json").string());
			md << "\n## The seed paper's tables beside ours (fog-paper)\n\n"
			   << "| model | paper stability | ours in-sample (A) | ours held out (B) | paper range | ours range in-sample | ours range held out |\n"
			   << "|---|---|---|---|---|---|---|\n";
			for (const char* m : {"uncompensated", "M1", "M2", "M3", "M4", "points_1", "points_2", "points_3", "points_4"})
			{
				const std::string k(m);
				md << "| " << k << " | " << fmt(paper.number("paper." + k + ".stability_dph")) << " | "
				   << fmt(paper.number("ours.in_sample." + k + ".stability_dph")) << " | "
				   << fmt(paper.number("ours.held_out." + k + ".stability_dph")) << " | "
				   << fmt(paper.number("paper." + k + ".range_dph")) << " | "
				   << fmt(paper.number("ours.in_sample." + k + ".range_dph")) << " | "
				   << fmt(paper.number("ours.held_out." + k + ".range_dph")) << " |\n";
			}
		}
		md << "\n## Files\n\n- `calibration.yaml`: the calibration (model, fallbacks, ranges, statistics)\n"
		   << "- `json/`: every program's `--json` output\n- `plots/`: PNG plots (chamber_A, chamber_B, drift"
		   << (have_paper ? ", paper" : "") << ")\n- `odometry_compensated.rawlog`: the compensated dead-reckoned "
		   << "trajectory as CObservationOdometry, readable by MRPT's pf-localization\n- `logs/`: each step's output\n";
		md << "\n## Commands (each figure above comes from one of these)\n\n```\n";
		for (const auto& c : run.commands()) md << c << "\n";
		md << "```\n";
		writeTextFileAtomically((out / "summary.md").string(), md.str());

		std::cout << "\nReport: " << (out / "summary.md").string() << "\n";
		for (const auto& st : stages)
		{
			const JsonFigures j((json / ("drives_" + st.id + ".json")).string());
			std::cout << "  heading RMS over " << drive_inputs.size() << " drive(s), " << st.label << ": compensated "
					  << fmt(stageFigure(j, "heading_error_rms_deg.compensated", "median")) << " deg (/raw "
					  << fmt(stageFigure(j, "ratio.heading_rms_compensated_over_raw", "median"), "%.6g") << ", /ideal "
					  << fmt(stageFigure(j, "ratio.heading_rms_compensated_over_ideal", "median"), "%.3g") << ")\n";
		}
		std::cout
				  << "  held-out bias stability (run B, 100 s): raw " << fmt(rawB) << " -> compensated " << fmt(compB)
				  << " deg/h\n"
				  << (have_second_chamber ? "  the same, calibrated on runs A + C:      compensated " +
												fmt(JsonFigures((json / "calibrate_two_runs.json").string())
														.number("validation.compensated.stability_dph")) +
												" deg/h\n"
										  : std::string())
				  << "  final heading error after the drive:    raw " << fmt(hRaw) << " deg, compensated " << fmt(hComp)
				  << " deg, ideal " << fmt(hIdeal) << " deg\n"
				  << "  final position error:                   raw " << fmt(drift.number("position_error_final_m.raw"))
				  << " m, compensated " << fmt(drift.number("position_error_final_m.compensated")) << " m, ideal "
				  << fmt(drift.number("position_error_final_m.ideal")) << " m\n";
		return 0;
	});
}
