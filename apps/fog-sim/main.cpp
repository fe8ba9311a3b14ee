/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** fog-sim: simulates a FOG with coil thermistors in a thermal chamber (or a vehicle) and writes
 * the run as a rawlog or CSV (by extension), with the simulator configuration and seed in the
 * metadata. Same arguments -> the same bytes.
 *
 *   fog-sim --profile seed -o chamber_A.rawlog
 *   fog-sim --profile my_profile.yaml --device my_gyro.yaml --effect -shupe_rate -o run.csv
 *   fog-sim --profile drive -o drive.rawlog          (vehicle scenario: FOG, FOG_IDEAL, ODOMETRY,
 *                                                     GROUND_TRUTH)
 */
#include <mrpt/3rdparty/tclap/CmdLine.h>
#include <mrpt_fog/common/OutputSafety.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/DriveRun.h>
#include <mrpt_fog/sim/EffectRegistry.h>
#include <mrpt_fog/sim/SimRandom.h>
#include <mrpt_fog/sim/TriadRun.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <iostream>

#include "AppMain.h"
#include "CommandLine.h"
#include "Options.h"
#include "StreamedRun.h"

using namespace mrpt_fog;
using namespace mrpt_fog::sim;

namespace
{
const char* const kHelp = R"(
EXAMPLES
  fog-sim --profile seed -o chamber_A.rawlog --seed 20240501
  fog-sim --profile B -o chamber_B.csv.gz --seed 20240502 --rate-hz 10
  fog-sim --profile calibration --triad -o triad_cal.rawlog
  fog-sim --profile drive --cabin drive_cabin_hot -o drive.rawlog --json drive.json
)";
}  // namespace

namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
	return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

ChamberProfile loadProfile(const std::string& arg)
{
	if (endsWith(arg, ".yaml") || endsWith(arg, ".yml")) return ChamberProfile::fromFile(arg);
	return ChamberProfile::preset(arg);
}

// Cuts a profile's output to the first max_s seconds (for short test runs).
FogSeries truncated(const FogSeries& s, double max_s)
{
	FogSeries out = s;
	std::size_t n = 0;
	while (n < s.size() && s.time_s[n] <= max_s + 1e-9) n++;
	out.resize(n);
	return out;
}
}  // namespace

int main(int argc, char** argv)
{
	return mrpt_fog::app::runApp("fog-sim", [&]() -> int {
		TCLAP::CmdLine cmd(
			"fog-sim: physics simulation of a fiber-optic gyro with coil thermistors (thermal chamber or vehicle drive). "
			"Built-in profiles: seed, calibration (one run that calibrates bias, rate terms and warm-up), B, warmup, rich, ratetable, drive_cabin(_mild, _hot), and drive (vehicle scenario, "
			"cabin chosen by --cabin).",
			' ', "1.0");
		app::InputArg profile("p", "profile", "built-in profile name or a profile YAML file", true, "",
											 "NAME|FILE.yaml", cmd);
		app::OutputArg out("o", "output", "output file: .rawlog, .csv or .csv.gz", true, "", "OUT", cmd);
		app::CountArg seed(cmd, "seed", "run seed (default 20240501)", "seed", 0, UINT64_MAX, kDefaultSeed);
		std::string effect_help =
			"error source selection (repeatable): ID = only the listed ids, -ID removes, +ID adds, all, none. Ids:";
		for (const auto& d : sim::effectDescriptors()) effect_help += std::string(" ") + d.id;
		TCLAP::MultiArg<std::string> effect("", "effect", effect_help, false, "ID", cmd);
		app::InputArg device("", "device", "device YAML (overlay on the default device)", false, "",
											"FILE.yaml", cmd);
		app::RealArg rate(cmd, "rate-hz", "output sample rate (default 10)", "Hz", app::Range::closed(1e-4, 1000), 10.0,
						  "F");
		app::RealArg duration(cmd, "duration-s", "keep only the first F seconds of the run (default: all of it)", "s",
							  app::Range::aboveUpTo(0, 1e9), NAN, "F");
		app::InputArg cabin("", "cabin",
										   "cabin profile of the vehicle scenario (--profile drive): a preset "
										   "(drive_cabin: winter cold start, the default; drive_cabin_mild; "
										   "drive_cabin_hot) or a profile YAML file; a {type: power, on: false} "
										   "segment switches the gyro off until {type: power, on: true}: those rows "
										   "have power 0 and no rate (an empty cell; fog-drift navigates each "
										   "powered span alone, docs/guide/heading-drift.md)",
										   false, "drive_cabin", "NAME|FILE.yaml", cmd);
		TCLAP::SwitchArg triad("", "triad",
							   "a three-axis FOG (x, y, z coils sharing one thermal network and the thermistors; per-axis "
							   "error sensitivities and noise: docs/reference/simulator.md, Three-axis FOG). The vehicle: z up; the "
							   "chamber: --up-axis up (the table turns about it), the other two horizontal",
							   cmd);
		TCLAP::ValueArg<std::string> up_axis("", "up-axis",
											 "with --triad in the chamber: the vertical axis, about which the table "
											 "turns (a rate-table run calibrates that axis' scale factor)",
											 false, "z", "x|y|z", cmd);
		app::OutputArg json("", "json", "write figures as JSON", false, "", "F", cmd);
		if (const auto rc = app::parseCommandLine(cmd, argc, argv, "fog-sim", kHelp)) return *rc;

		const std::string ext = fileExtension(out.getValue());
		if (ext != ".rawlog" && ext != ".csv" && ext != ".csv.gz")
			throw std::invalid_argument(out.getValue() + ": output must end in .rawlog, .csv or .csv.gz");
		SimSettings settings;
		settings.seed = seed.getValue();
		settings.rate_hz = rate.getValue();
		settings.effects = effectsFromSelection(effect.getValue());
		settings.profile_source = profile.getValue();
		if (cabin.isSet()) settings.profile_source += " (cabin " + cabin.getValue() + ")";
		settings.validate();
		const FogDevice dev = device.isSet() ? FogDevice::fromFile(device.getValue()) : FogDevice::defaultDevice();
		const bool vehicle = profile.getValue() == "drive";
		if (cabin.isSet() && !vehicle) throw std::invalid_argument("--cabin: only with --profile drive");
		const ChamberProfile prof = vehicle ? loadProfile(cabin.getValue()) : loadProfile(profile.getValue());
		if (up_axis.isSet() && (!triad.getValue() || vehicle))
			throw std::invalid_argument("--up-axis: only with --triad in the chamber (the vehicle's triad is z up)");
		const std::string up_text = up_axis.getValue();
		if (up_text != "x" && up_text != "y" && up_text != "z")
			throw std::invalid_argument("--up-axis: '" + up_text + "' is not x, y or z");
		const GyroAxis up = static_cast<GyroAxis>(up_text[0] - 'x');

		const auto t0 = std::chrono::steady_clock::now();
		app::SimRunSummary sum;
		double sim_s = 0;
		double transient_C = NAN;  // vehicle: the coil's thermal transient
		if (!triad.getValue())
		{
			// A single-axis run is simulated and written sample by sample.
			std::vector<std::pair<std::string, std::string>> extra;
			if (duration.isSet()) extra.emplace_back("sim.duration_s", std::to_string(duration.getValue()));
			const double max_s = duration.isSet() ? duration.getValue() : INFINITY;
			sum = vehicle ? app::writeDriveStreamed(out.getValue(), prof, dev, settings, max_s, extra)
						  : app::writeChamberStreamed(out.getValue(), prof, dev, settings, max_s, extra);
			transient_C = sum.coil_transient_C;
			sim_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
		}
		else
		{
			FogSeries fog;
			std::vector<mrpt::obs::CObservation::Ptr> others;
			std::vector<double> ideal_rate;  // vehicle: FOG_IDEAL, to report the thermal error alone
			if (vehicle)
			{
				DriveOutput d = triad.getValue() ? simulateTriadDrive(prof, dev, settings) : simulateDrive(prof, dev, settings);
				fog = std::move(d.fog);
				ideal_rate = d.fog_ideal.rate_dph[2];
				transient_C = d.coil_transient_C;
				if (duration.isSet())
				{
					fog = truncated(fog, duration.getValue());
					const auto end = mrpt::Clock::fromDouble(fog.epoch_s + duration.getValue() + 1e-6);
					others.clear();
					for (auto& o : d.others)
						if (o->timestamp <= end) others.push_back(o);
				}
				else
					others = std::move(d.others);
			}
			else
			{
				fog = triad.getValue() ? simulateTriadChamber(prof, dev, settings, up) : simulateChamber(prof, dev, settings);
				if (duration.isSet()) fog = truncated(fog, duration.getValue());
			}
			sim_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
			if (fog.size() < 2) throw std::invalid_argument("run has fewer than 2 samples (check --duration-s)");
			if (duration.isSet()) fog.setMetadata("sim.duration_s", std::to_string(duration.getValue()));

			if (ext == ".rawlog")
				writeFogRawlog(out.getValue(), fog, others);
			else
			{
				if (vehicle) std::cerr << "fog-sim: note: CSV holds the FOG stream only; odometry and truth need .rawlog\n";
				writeFogCsv(out.getValue(), fog);
			}

			// Summary: the uncompensated figures of the seed (100 s stability and range).
			sum.samples = fog.size();
			sum.last_time_s = fog.time_s.back();
			sum.thermistors = fog.thermistors;
			std::vector<double> t_on, r_on;
			for (std::size_t k = 0; k < fog.size(); k++)
				if (fog.power.empty() || fog.power[k] != 0)
				{
					t_on.push_back(fog.time_s[k]);
					// bias only: the vehicle's FOG_IDEAL (motion, Earth rate, noise) or a chamber's table rate removed
					const double table = fog.table_rate_dph.empty() ? 0.0 : fog.table_rate_dph[k];
					r_on.push_back(fog.rate_dph[vehicle ? 2 : static_cast<std::size_t>(up)][k] - (vehicle ? ideal_rate[k] : table));
				}
			if (t_on.size() > 2 && t_on.back() - t_on.front() >= 200.0)
			{
				sum.has_stats = true;
				sum.stats = biasStats(t_on, r_on, 100.0);
			}
			for (std::size_t i = 0; i < fog.thermistorCount(); i++)
			{
				const auto& c = fog.temp_C[i];
				const auto [mn, mx] = std::minmax_element(c.begin(), c.end());
				sum.min_C.push_back(*mn);
				sum.max_C.push_back(*mx);
			}
		}
		std::printf("fog-sim: %s, profile %s, seed %llu, %zu samples (%.2f h at %g Hz) -> %s\n", vehicle ? "vehicle" : "chamber",
					profile.getValue().c_str(), static_cast<unsigned long long>(settings.seed), sum.samples,
					sum.last_time_s / 3600.0, settings.rate_hz, out.getValue().c_str());
		std::printf("  effects: %s\n", effectsToString(settings.effects).c_str());
		JsonValue j = JsonValue::object();
		j["profile"] = profile.getValue();
		j["scenario"] = vehicle ? "vehicle" : "chamber";
		j["seed"] = static_cast<double>(settings.seed);
		j["rate_hz"] = settings.rate_hz;
		j["samples"] = static_cast<unsigned long>(sum.samples);
		j["duration_s"] = sum.last_time_s;
		j["effects"] = effectsToString(settings.effects);
		j["simulation_time_s"] = sim_s;
		if (sum.has_stats)
		{
			const BiasStats& st = sum.stats;
			std::printf("  %s: 100 s bias stability %.4f deg/h, range %.4f deg/h, mean %.4f deg/h\n",
						vehicle ? "thermal error (FOG - FOG_IDEAL)" : (triad.getValue() ? "uncompensated up axis (powered samples, table rate removed)" : "uncompensated (powered samples, table rate removed)"), st.stability_dph,
						st.range_dph, st.mean_dph);
			const char* key = vehicle ? "thermal_error" : "uncompensated";
			j[key]["stability_dph"] = st.stability_dph;
			j[key]["range_dph"] = st.range_dph;
			j[key]["mean_dph"] = st.mean_dph;
			j[key]["tau_s"] = 100.0;
		}
		for (std::size_t i = 0; i < sum.thermistors.size(); i++)
		{
			const ThermistorInfo& th = sum.thermistors[i];
			std::printf("  %s (%s %g deg): %.2f .. %.2f C\n", th.name.c_str(), toString(th.side), th.angle_deg,
						sum.min_C[i], sum.max_C[i]);
			j["thermistors"][th.name]["min_C"] = sum.min_C[i];
			j["thermistors"][th.name]["max_C"] = sum.max_C[i];
		}
		if (vehicle)
		{
			std::printf("  coil thermal transient: %.2f C\n", transient_C);
			j["coil_transient_C"] = transient_C;
		}
		std::printf("  simulated in %.3f s\n", sim_s);
		if (json.isSet()) writeTextFileAtomically(json.getValue(), j.dump());
		return 0;
	});
}
