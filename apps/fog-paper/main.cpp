/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** fog-paper: the seed paper's Tables 1-3 reproduced on the simulated gyro, beside the paper's.
 *
 * Runs the seed's experiment (chamber run A = the seed profile) on the default simulated device,
 * fits every model of the paper (M1-M4 on a single point, multi-point with 1..4 points, orders
 * 5/3) and reports the 100 s bias stability and range: in-sample on run A (as the paper does)
 * and held out on run B (a different profile). Also draws figures like the seed's Fig. 5
 * (stability and range vs number of points) and Fig. 2 (inner vs outer temperatures).
 *
 *   fog-paper [--json F] [--plots DIR] [--run-a A.rawlog --run-b B.rawlog] [--selection none|auto]
 */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/plot/PlotCanvas.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/SimRandom.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

#include "AppMain.h"
#include "LogInput.h"
#include "CommandLine.h"
#include "Options.h"

using namespace mrpt_fog;

namespace
{
struct Entry
{
	std::string key;  //!< JSON key: uncompensated, M1..M4, points_1..points_4
	std::string preset;  //!< model preset ("" for uncompensated)
	double paper_stability_dph, paper_range_dph;  //!< seed Tables 1-3
};

// The seed's Tables 2 and 3 (Table 1 = uncompensated and points_3). points_1 is the single-point
// M2 model in the paper (same figures in Tables 2 and 3).
const std::vector<Entry>& entries()
{
	static const std::vector<Entry> e = {
		{"uncompensated", "", 0.1148572, 0.5082123}, {"M1", "M1", 0.1041110, 0.4899192},
		{"M2", "M2", 0.0344557, 0.1892430},			 {"M3", "M3", 0.0187308, 0.1298451},
		{"M4", "M4", 0.0402742, 0.1979645},			 {"points_1", "points:1", 0.0344557, 0.18924306},
		{"points_2", "points:2", 0.0087575, 0.08417432}, {"points_3", "points:3", 0.0069472, 0.0713152},
		{"points_4", "points:4", 0.0058415, 0.0638561}};
	return e;
}

struct Figures
{
	double stability_dph = NAN, range_dph = NAN;
};

void putFigures(JsonValue& j, const Figures& f)
{
	j["stability_dph"] = f.stability_dph;
	j["range_dph"] = f.range_dph;
}

void drawFig5(const std::string& path, const std::vector<Figures>& paper, const std::vector<Figures>& in,
			  const std::vector<Figures>& out)
{
	PlotCanvas fig(900, 800);
	const char* names[2] = {"bias stability (100 s) [deg/h]", "full-temperature range [deg/h]"};
	for (int panel = 0; panel < 2; panel++)
	{
		LinePlot& p = fig.addPanel();
		p.title = panel == 0 ? "Bias stability vs number of temperature points (cf. seed Fig. 5)"
							 : "Range vs number of temperature points";
		p.x_axis.label = "number of temperature points";
		p.x_axis.min = 0.8;
		p.x_axis.max = 4.2;
		p.y_axis.label = names[panel];
		p.y_axis.log = true;
		auto series = [&](const std::vector<Figures>& f, const char* label, cv::Scalar c, bool dashed) {
			PlotSeries s;
			s.label = label;
			s.colour = c;
			s.thickness_px = 2;
			s.dashed = dashed;
			for (std::size_t k = 0; k < f.size(); k++)
			{
				s.x.push_back(static_cast<double>(k + 1));
				s.y.push_back(panel == 0 ? f[k].stability_dph : f[k].range_dph);
			}
			p.addSeries(s);
		};
		series(paper, "paper (in-sample)", plot_colour::kBlack, true);
		series(in, "ours, in-sample (run A)", plot_colour::kBlue, false);
		series(out, "ours, held out (run B)", plot_colour::kOrange, false);
	}
	fig.save(path);
}

void drawFig2(const std::string& path, const FogSeries& a)
{
	PlotCanvas fig(1000, 600);
	LinePlot& p = fig.addPanel();
	p.title = "Run A: inner vs outer coil temperatures (cf. seed Fig. 2)";
	p.x_axis.label = "time [h]";
	p.y_axis.label = "temperature [degC]";
	const std::size_t step = std::max<std::size_t>(1, a.size() / 4000);
	for (std::size_t i = 0; i < a.thermistorCount(); i++)
	{
		PlotSeries s;
		s.label = a.thermistors[i].name + " (" + toString(a.thermistors[i].side) + ", " +
				  std::to_string(static_cast<int>(a.thermistors[i].angle_deg)) + " deg)";
		s.colour = plot_colour::cycle(i);
		s.dashed = a.thermistors[i].side == CoilSide::Outer;
		for (std::size_t k = 0; k < a.size(); k += step)
		{
			s.x.push_back(a.time_s[k] / 3600.0);
			s.y.push_back(a.temp_C[i][k]);
		}
		p.addSeries(s);
	}
	// Second axis: inner - outer of the first pair.
	const int in = a.thermistorCount() >= 2 ? 0 : -1;
	if (in >= 0)
	{
		PlotSeries d;
		d.label = a.thermistors[0].name + " - " + a.thermistors[1].name;
		d.colour = plot_colour::kGrey;
		d.right_axis = true;
		for (std::size_t k = 0; k < a.size(); k += step)
		{
			d.x.push_back(a.time_s[k] / 3600.0);
			d.y.push_back(a.temp_C[0][k] - a.temp_C[1][k]);
		}
		p.y2_axis.label = "inner - outer [degC]";
		p.addSeries(d);
	}
	fig.save(path);
}
}  // namespace

int main(int argc, char** argv)
{
	return mrpt_fog::app::runApp("fog-paper", [&]() -> int {
		TCLAP::CmdLine cmd(
			"fog-paper: the seed paper's Tables 1-3 (uncompensated, M1-M4, multi-point with 1-4 points, orders 5/3) "
			"on the simulated gyro, in-sample on run A (seed profile) and held out on run B, beside the paper's.",
			' ', "1.0");
		app::OutputArg json("", "json", "write the tables as JSON", false, "", "F", cmd);
		app::OutputDirArg plots("", "plots", "directory for fig5_points.png and fig2_temperatures.png", false,
										   "", "DIR", cmd);
		app::InputArg run_a("", "run-a", "run A log (default: simulate the seed profile)", false, "",
										   "FILE", cmd);
		app::InputArg run_b("", "run-b", "run B log (default: simulate profile B)", false, "", "FILE",
										   cmd);
		app::CountArg seed(cmd, "seed", "simulation seed (default 20240501)", "seed", 0, UINT64_MAX, sim::kDefaultSeed);
		app::RealArg rate(cmd, "rate-hz", "simulation sample rate (default 10)", "Hz", app::Range::closed(0.01, 1000), 10.0,
						  "F");
		TCLAP::ValueArg<std::string> selection(
			"", "selection", "term selection: none (plain least squares on all terms, the paper's way; default) or auto",
			false, "none", "none|auto", cmd);
		app::LogInput log_input(cmd, "fog-paper");
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-paper")) return *rc;
		const TermSelection term_selection = app::parseChoice(selection, termSelectionFromString);
		if (plots.isSet() && !std::filesystem::is_directory(plots.getValue()))
			throw std::invalid_argument(plots.getValue() + ": --plots directory does not exist");

		const auto t0 = std::chrono::steady_clock::now();
		sim::SimSettings ss;
		ss.seed = seed.getValue();
		ss.rate_hz = rate.getValue();
		const auto dev = sim::FogDevice::defaultDevice();
		FogSeries A, B;
		if (run_a.isSet())
			A = readFogLog(run_a.getValue(), "FOG", log_input.options());
		else
		{
			ss.profile_source = "seed";
			A = sim::simulateChamber(sim::ChamberProfile::preset("seed"), dev, ss);
		}
		if (run_b.isSet())
			B = readFogLog(run_b.getValue(), "FOG", log_input.options());
		else
		{
			ss.profile_source = "B";
			B = sim::simulateChamber(sim::ChamberProfile::preset("B"), dev, ss);
		}

		FitOptions opt;
		opt.selection = term_selection;
		std::vector<Figures> in(entries().size()), out(entries().size());
		for (std::size_t i = 0; i < entries().size(); i++)
		{
			const Entry& e = entries()[i];
			if (e.preset.empty()) continue;
			const Calibration cal = fitCalibration({A}, e.preset, opt, {"run A"});
			in[i] = {cal.in_sample.stability_dph, cal.in_sample.range_dph};
			const FitFigures f = evaluateCalibration(cal, B, "held out: run B");
			out[i] = {f.stability_dph, f.range_dph};
			if (i == 1)
			{
				in[0] = {cal.in_sample.raw_stability_dph, cal.in_sample.raw_range_dph};
				out[0] = {f.raw_stability_dph, f.raw_range_dph};
			}
		}
		const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();

		std::printf("fog-paper: seed Tables 1-3 on the simulated gyro (100 s bias stability / range, deg/h)\n");
		std::printf("run A: %s (%zu samples), run B: %s (%zu samples); fit: orders 5/3, selection %s\n",
					run_a.isSet() ? run_a.getValue().c_str() : "simulated seed profile", A.size(),
					run_b.isSet() ? run_b.getValue().c_str() : "simulated profile B", B.size(),
					toString(term_selection));
		std::printf("%-14s | %-21s | %-21s | %-21s\n", "model", "paper (in-sample)", "ours in-sample (A)",
					"ours held out (B)");
		for (std::size_t i = 0; i < entries().size(); i++)
			std::printf("%-14s | %9.6f  %9.6f | %9.6f  %9.6f | %9.6f  %9.6f\n", entries()[i].key.c_str(),
						entries()[i].paper_stability_dph, entries()[i].paper_range_dph, in[i].stability_dph,
						in[i].range_dph, out[i].stability_dph, out[i].range_dph);
		std::printf("(points_K: multi-point model on the best K-thermistor subset; M1-M4: single point, first inner "
					"thermistor and its outer partner)\ncomputed in %.1f s\n",
					elapsed);

		if (json.isSet())
		{
			JsonValue j = JsonValue::object();
			JsonValue& meta = j["settings"];
			meta["run_a"] = run_a.isSet() ? run_a.getValue() : std::string("simulated:seed");
			meta["run_b"] = run_b.isSet() ? run_b.getValue() : std::string("simulated:B");
			meta["seed"] = static_cast<double>(ss.seed);
			meta["rate_hz"] = ss.rate_hz;
			meta["selection"] = toString(term_selection);
			meta["orders"] = "5/3";
			meta["tau_s"] = 100.0;
			for (std::size_t i = 0; i < entries().size(); i++)
			{
				const Entry& e = entries()[i];
				putFigures(j["paper"][e.key], {e.paper_stability_dph, e.paper_range_dph});
			}
			for (std::size_t i = 0; i < entries().size(); i++) putFigures(j["ours"]["in_sample"][entries()[i].key], in[i]);
			for (std::size_t i = 0; i < entries().size(); i++) putFigures(j["ours"]["held_out"][entries()[i].key], out[i]);
			writeTextFileAtomically(json.getValue(), j.dump());
		}
		if (plots.isSet())
		{
			std::vector<Figures> p5, i5, o5;
			for (std::size_t i = 5; i < 9; i++)
			{
				p5.push_back({entries()[i].paper_stability_dph, entries()[i].paper_range_dph});
				i5.push_back(in[i]);
				o5.push_back(out[i]);
			}
			const std::string dir = plots.getValue();
			drawFig5(dir + "/fig5_points.png", p5, i5, o5);
			drawFig2(dir + "/fig2_temperatures.png", A);
			std::printf("plots: %s/fig5_points.png, %s/fig2_temperatures.png\n", dir.c_str(), dir.c_str());
		}
		return 0;
	});
}
