/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** fog-discrepancy: where a model of the gyro and measured chamber data disagree, which
 * physical effect is missing, and how much the gap shrinks once it is added.
 *
 *   fog-discrepancy --measured A.rawlog [--measured B.rawlog] --model multipoint --json out.json --plots dir
 *   fog-discrepancy --measured A.csv [--measured B.csv] --sim SIM.yaml --json out.json
 */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/report/CalibrationAugmentOutput.h>
#include <mrpt_fog/report/DiscrepancyOutput.h>
#include <mrpt_fog/report/SimDiscrepancyOutput.h>
#include <mrpt_fog/io/BlockMeanReader.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/CalibrationYaml.h>

#include <cstdio>
#include <filesystem>
#include <iostream>

#include "LogInput.h"
#include "AppMain.h"
#include "CommandLine.h"
#include "Options.h"
#include "Progress.h"
#include "ThermistorScreeningReport.h"

using namespace mrpt_fog;

int main(int argc, char** argv)
{
	return app::runApp("fog-discrepancy", [&]() {
		TCLAP::CmdLine cmd(
			"Locate where a gyro model and measured chamber runs disagree, name the missing physical effect "
			"(with alias groups where the run cannot separate candidates), add it, refit and show the gap "
			"before/after. The first --measured run is analysed; a second one confirms.",
			' ', "0.1");
		app::InputMultiArg measured("", "measured", "measured run (.rawlog, .csv, .csv.gz); give 1 or 2",
											  true, "FILE", cmd);
		app::InputArg model("", "model",
										   "bias model to test, built as fog-compensate runs it: a preset (multipoint, "
										   "M1..M4[:...], points:K, terms:...) fitted on the first run with fog-calibrate's "
										   "defaults, or a calibration YAML as is (its terms, normalisation, rate estimator, "
										   "extrapolation); coefficients refitted on the measured run. static:P[:NAME]: a "
										   "polynomial in one thermistor / their mean (synthetic proof trials)",
										   false, "", "PRESET|CAL.yaml");
		app::InputArg sim("", "sim", "simulator configuration to test (device, effects, free parameters, optional profile; see docs/discrepancy-sim.md); its free parameters are calibrated to the measured run. Without a profile (in SIM.yaml or the run metadata sim.profile) the simulator is driven from the log alone: power, table rate and field columns, chamber air reconstructed from the thermistors; a thermistor misfit above 0.1 C RMS is reported as the first disagreement and no bias effect is named on top of it; the share of the bias residual that follows air changes faster than the reconstruction resolves is reported ('Unresolved thermal content') and taken out before effects are named: give the profile to attribute it", false, "",
										 "SIM.yaml");
		cmd.xorAdd(model, sim);
		app::OutputArg json("", "json", "write the figures as JSON", false, "", "FILE", cmd);
		app::OutputDirArg plots("", "plots", "write residual PNGs into this directory", false, "", "DIR", cmd);
		app::OutputArg write_cal(
			"", "write-cal",
			"write the calibration under test plus the named, confirmed effects the compensator can run (thermal "
			"terms), refitted on the first run, and show the gap before/after on the second run through the "
			"compensator (--model only)",
			false, "", "OUT.yaml", cmd);
		app::RealArg alpha(cmd, "alpha", "family-wise significance level (Holm)", "1", app::Range::open(0, 0.5), 0.005, "P");
		TCLAP::ValueArg<std::string> scale_factor(
			"", "scale-factor",
			"with a preset: auto (default, as fog-calibrate) fits the scale factor versus temperature from the "
			"first run's table segments into the model under test; off tests a bias-only calibration "
			"(fog-calibrate --scale-factor off)",
			false, "auto", "auto|off", cmd);
		TCLAP::ValueArg<std::string> label("", "fog-label", "FOG sensor label in a rawlog with several", false, "",
										   "LABEL", cmd);
		TCLAP::SwitchArg no_screen("", "no-screening",
								   "do not screen thermistor readings (stuck / spike / out of range -> dropout) before "
								   "the analysis (fog-compensate's screening)",
								   cmd);
		app::RealArg block_s(
			cmd, "block-s",
			"analyse block means of at least this many seconds (default 1): a run sampled faster is reduced while it "
			"is read to blocks of K = floor(S / sample period) consecutive samples (a block never mixes power "
			"states, table rates or fields, nor bridges a gap); thermal effects vary over minutes, so blocks of "
			"seconds keep them and average only the white part of the gyro noise: the residual RMS is that of "
			"the block means. A run sampled at 1/S or slower is analysed sample by sample. 0: no reduction "
			"(memory about 1.4 KB per sample)",
			"s", app::Range::closed(0, 3600), 1.0, "S");
		app::CountArg max_rows(
			cmd, "max-rows",
			"at most this many rows per run (default 65536, 18 h of 1 s blocks): beyond it adjacent blocks are "
			"merged in pairs (2 S, 4 S, ...), which bounds memory (about 1.4 KB per row) and time; blocks stop "
			"growing at 16 s (the compensator's rate window is 60 s), so beyond 12 days the rows grow",
			"rows", 1000, 100000000, 65536);
		TCLAP::SwitchArg quiet("q", "quiet", "No progress line on stderr while the runs are read", cmd);
		app::LogInput log_input(cmd, "fog-discrepancy");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-discrepancy")) return *rc;

		if (measured.getValue().size() > 2)
			throw std::runtime_error("--measured given " + std::to_string(measured.getValue().size()) +
									 " times: at most two runs (the first is analysed, the second confirms)");
		if (scale_factor.getValue() != "auto" && scale_factor.getValue() != "off")
			throw std::runtime_error("--scale-factor: '" + scale_factor.getValue() + "' is not auto or off");
		if (plots.isSet())
		{
			std::error_code ec;
			std::filesystem::create_directories(plots.getValue(), ec);  // like fog-evaluate
			if (!std::filesystem::is_directory(plots.getValue()))
				throw std::runtime_error("--plots " + plots.getValue() + ": cannot create the directory" +
										 (ec ? ": " + ec.message() : std::string()));
		}


		std::vector<FogSeries> runs;
		std::vector<std::string> labels;
		double analysed_quantum_C = 0;  // the first run's raw thermistor quantum, when reduced
		for (const auto& f : measured.getValue())
		{
			// read as a stream: screened sample by sample (as fog-compensate), then reduced to
			// block means with bounded rows (io/BlockMeanReader.h)
			BlockMeanOptions bopt;
			bopt.min_block_s = block_s.getValue();
			bopt.max_rows = max_rows.get<std::size_t>();
			// the simulator path puts each row on the profile's time grid: rows at their block's
			// first sample (the log's own grid); the means lag that time by half a block
			if (sim.isSet()) bopt.row_time = BlockMeanOptions::RowTime::FirstSample;
			BlockMeanInfo binfo;
			app::StreamScreening screening(!no_screen.getValue());
			app::Progress progress("fog-discrepancy: reading " + f, quiet.getValue());
			runs.push_back(readFogLogBlockMeans(
				f, label.getValue(), bopt, binfo, screening.hook(),
				[&](std::uint64_t n, std::uint64_t done, std::uint64_t total) { progress.update(n, done, total); },
				log_input.options()));
			progress.finish();
			const ThermistorScreening sc = screening.result(FogRun(runs.back()));
			if (sc.rejected_readings > 0) std::cout << f << ":\n" << app::screeningText(sc, true);
			if (runs.size() == 1 && binfo.reduced()) analysed_quantum_C = binfo.thermistor_step_p05_C;
			if (binfo.reduced())
			{
				char buf[300];
				std::snprintf(buf, sizeof buf,
							  "%s: %zu samples (%.4g Hz) analysed as %zu block means of about %zu samples (%.4g s)\n",
							  f.c_str(), binfo.samples, binfo.native_period_s > 0 ? 1.0 / binfo.native_period_s : 0.0,
							  binfo.rows, binfo.samples_per_block, binfo.block_s);
				std::cout << buf;
			}
			labels.push_back(std::filesystem::path(f).filename().string());
		}
		discrepancy::DiscrepancyOptions opt;
		opt.selection.alpha = alpha.getValue();
		opt.thermistor_quantum_C = analysed_quantum_C;
		opt.scale_factor = scale_factor.getValue() == "off" ? discrepancy::ScaleFactorFitting::Off
															 : discrepancy::ScaleFactorFitting::Auto;
		discrepancy::DiscrepancyReport rep;
		JsonValue doc;
		std::string text;
		if (sim.isSet())
		{
			const auto cfg = discrepancy::readSimulatorConfig(sim.getValue());
			discrepancy::SimDiscrepancyOptions sopt;
			sopt.base = opt;
			sopt.heat.alpha = alpha.getValue();
			discrepancy::SimDiscrepancyReport srep;
			try
			{
				srep = discrepancy::analyseSimulatorDiscrepancy(runs, labels, cfg, sopt);
			}
			catch (const std::invalid_argument& e)
			{
				throw std::runtime_error(measured.getValue().front() + ": " + e.what());
			}
			rep = srep.report;
			doc = discrepancy::simDiscrepancyJson(srep);
			text = discrepancy::simDiscrepancyText(srep);
		}
		else
		{
			try
			{
				rep = discrepancy::analyseDiscrepancy(runs, labels, model.getValue(), opt);
			}
			catch (const std::invalid_argument& e)
			{
				throw std::runtime_error(measured.getValue().front() + ": " + e.what());
			}
			doc = discrepancy::discrepancyJson(rep);
			text = discrepancy::discrepancyText(rep);
		}
		if (write_cal.isSet())
		{
			if (sim.isSet()) throw std::runtime_error("--write-cal needs --model (a bias-model preset or calibration)");
			discrepancy::AugmentedCalibration aug;
			try
			{
				aug = discrepancy::augmentCalibration(model.getValue(), rep.selection.named, runs[0],
													  runs.size() == 2 ? &runs[1] : nullptr,
													  runs.size() == 2 ? labels[1] : std::string(), opt.scale_factor);
			}
			catch (const std::invalid_argument& e)
			{
				throw std::runtime_error(measured.getValue().front() + ": --write-cal: " + e.what());
			}
			saveCalibrationYaml(aug.augmented, write_cal.getValue());
			text += discrepancy::augmentedCalibrationText(aug, write_cal.getValue());
			doc["write_cal"] = discrepancy::augmentedCalibrationJson(aug, write_cal.getValue());
		}
		std::cout << text;
		if (plots.isSet())
		{
			const std::filesystem::path dir(plots.getValue());
			discrepancy::saveGapPlot(rep.gap, (dir / "discrepancy_residual.png").string(), "fog-discrepancy");
			std::cout << "Wrote " << (dir / "discrepancy_residual.png").string() << "\n";
			if (rep.has_confirm)
			{
				discrepancy::saveGapPlot(rep.gap_confirm, (dir / "discrepancy_residual_confirm.png").string(),
										 "fog-discrepancy (confirmation)");
				std::cout << "Wrote " << (dir / "discrepancy_residual_confirm.png").string() << "\n";
			}
		}
		if (json.isSet())
		{
			doc["input_notices"] = log_input.json();
			writeTextFileAtomically(json.getValue(), doc.dump());
			std::cout << "Wrote " << json.getValue() << "\n";
		}
		return 0;
	});
}
