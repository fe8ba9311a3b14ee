/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/** bench_generalization: the generalization bench (tests/generalization/support).
 * Every device of the ensemble is calibrated on the seed chamber profile and evaluated on
 * profiles it never saw; per preset, the median and 90th percentile of held-out 100 s stability
 * divided by the device's noise floor.
 *
 *   bench_generalization [--seeds tuning|heldout|final|fresh|all|N[,N..]] [--sector-coil N] [--rate-cap HZ] [--cases]
 *                        [--extrapolation clamp|linear|polynomial] [--preset TEXT] [--extra PRESET]...
 *                        [--effects SEL] [--ideal-thermistors] [--oracle] [--rate-window S]
 *                        [--cal2 PROFILE] [--warmup-cal] [--cal-profile NAME] [--turn-on-exclusion S]
 *
 * Seeds 1..16 are the tuning devices, 17..24 were kept out of every tuning decision, 25..32
 * ("final") out of everything until the start-up model and quantum window were decided, 33..40
 * ("fresh") until the selection rules were decided (all: 1..24).
 * --sector-coil N adds sector-coil devices 1..N (the independent generator). --cases prints every
 * device x profile x preset line; --extrapolation overrides every preset's policy; --preset
 * keeps the presets whose label contains TEXT (--exclude TEXT drops them; may be repeated); --extra adds a fixed preset
 * (selection none), e.g. --extra M2@5/1. Not a Google Benchmark: a figure-of-merit table.
 *
 * Diagnostics (what the held-out error above the noise floor is made of; fog-sim devices):
 * --effects SEL simulates calibration and evaluation runs with the effects selected as fog-sim
 * does (comma-separated, e.g. -hysteresis,-warmup); --ideal-thermistors removes the thermistors'
 * reading noise and quantisation; --oracle adds, for every preset, the same preset fitted on each
 * evaluation run itself (in-sample: what that model can do at best on that profile);
 * --rate-window S sets every preset's causal rate window [s] (default 60); --savgol uses the
 * non-causal, delay-free Savitzky-Golay rate estimator instead (evaluated offline: no
 * compensator can run it), to measure what the causal estimator's delay costs;
 * --causal-order 1|2 sets the causal estimator's order (default 2; 1 = the delayed slope used
 * before the diagnosis); --also-order1 adds every preset again with the order-1 estimator
 * (label " o1") and --also-window S with a rate window of S seconds (label " wS"), on the same
 * simulated runs.
 * Calibration on more than the seed run: --cal2 PROFILE adds a second calibration run (two runs:
 * the selection leaves out whole runs): cal_sine (not an evaluation profile: every profile stays
 * evaluated), or an evaluation profile's name (its run joins the calibration and that profile
 * is not evaluated; FOG_BENCH_CAL2=PROFILE is the same); --warmup-cal adds the turn-on run
 * cal_turn_on (10 C ambient) and fits the warm-up term on it (fitWarmup, as fog-calibrate
 * --warmup-run; fog-sim devices); --also-seed-run-only adds every preset again fitted on the seed
 * run alone (label " 1run"), --also-no-warmup without the warm-up term (label " nowarm"), on the
 * same simulated runs. Environment: FOG_BENCH_SCORING / _GAIN / _COMMON /
 * _BINS / _PARSIMONY / _VARIANTS add selection variants (GeneralizationBench.cpp); FOG_BENCH_LAGS=1
 * (or a list of time constants, e.g. 100,400) adds the lag-rate variants: "auto no lags" (the
 * default before them), "auto lag steps", "auto lag base" (the default's rule) and "auto lag all".
 * One calibration run: --cal-profile NAME calibrates on that profile of secondCalibrationProfiles()
 * instead of the seed profile, e.g. cal_single (fog-sim's `calibration` profile: a turn-on, the
 * seed ramps, a sine and fast ramps in one run); a turn-on in it keeps the first
 * --turn-on-exclusion S seconds (default 3600) out of the bias fit and fits the warm-up term on
 * the same run (0: the turn-on in the bias fit, no term).
 * Seeds 41..56 and 57..72 were each run once as fresh sets, 73..104 once for the one-run
 * calibration and 105..120 once after the quantum-window change (docs/validation/generalization.md); 121 on
 * are unused. */
#include "DeviceEnsemble.h"
#include "GeneralizationBench.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

int main(int argc, char** argv)
{
	std::string which = "all";
	int sector_coil = 8;
	double cap = 1e9;
	bool cases = false;
	std::string policy, only;
	std::vector<std::string> excluded;
	std::vector<std::string> extra;
	mrpt_fog::sim::EffectSet effects = mrpt_fog::sim::defaultEffects();
	bool ideal = false, oracle = false;
	double rate_window_s = 0;
	bool savgol = false;
	int causal_order = 0;
	std::vector<double> also_windows_s;
	std::string second_calibration;
	if (const char* name = std::getenv("FOG_BENCH_CAL2")) second_calibration = name;  // the older spelling of --cal2
	bool warmup_calibration = false, also_seed_run_only = false, also_no_warmup = false;
	std::string calibration_profile;  // empty: the seed profile
	double turn_on_exclusion_s = fogtest::kBenchTurnOnExclusion_s;
	for (int i = 1; i < argc; i++)
	{
		const std::string a = argv[i];
		if (a == "--seeds" && i + 1 < argc) which = argv[++i];
		else if (a == "--sector-coil" && i + 1 < argc) sector_coil = std::atoi(argv[++i]);
		else if (a == "--rate-cap" && i + 1 < argc) cap = std::atof(argv[++i]);
		else if (a == "--cases") cases = true;
		else if (a == "--extrapolation" && i + 1 < argc) policy = argv[++i];
		else if (a == "--preset" && i + 1 < argc) only = argv[++i];
		else if (a == "--exclude" && i + 1 < argc) excluded.push_back(argv[++i]);
		else if (a == "--extra" && i + 1 < argc) extra.push_back(argv[++i]);
		else if (a == "--effects" && i + 1 < argc)
		{
			std::vector<std::string> sel;
			std::string item;
			for (const char* p = argv[++i];; p++)
			{
				if (*p == ',' || *p == 0)
				{
					if (!item.empty()) sel.push_back(item);
					item.clear();
					if (*p == 0) break;
				}
				else
					item += *p;
			}
			effects = mrpt_fog::sim::effectsFromSelection(sel);
		}
		else if (a == "--ideal-thermistors") ideal = true;
		else if (a == "--cal2" && i + 1 < argc) second_calibration = argv[++i];
		else if (a == "--warmup-cal") warmup_calibration = true;
		else if (a == "--cal-profile" && i + 1 < argc) calibration_profile = argv[++i];
		else if (a == "--turn-on-exclusion" && i + 1 < argc) turn_on_exclusion_s = std::atof(argv[++i]);
		else if (a == "--also-seed-run-only") also_seed_run_only = true;
		else if (a == "--also-no-warmup") also_no_warmup = true;
		else if (a == "--oracle") oracle = true;
		else if (a == "--rate-window" && i + 1 < argc) rate_window_s = std::atof(argv[++i]);
		else if (a == "--savgol") savgol = true;
		else if (a == "--causal-order" && i + 1 < argc) causal_order = std::atoi(argv[++i]);
		else if (a == "--also-order1") also_windows_s.push_back(-1);
		else if (a == "--also-window" && i + 1 < argc) also_windows_s.push_back(std::atof(argv[++i]));
		else
		{
			std::fprintf(stderr, "bench_generalization: unknown argument '%s' (see the file comment)\n", a.c_str());
			return 2;
		}
	}
	std::vector<fogtest::BenchCase> list;
	std::vector<std::uint64_t> seeds;
	if (which == "tuning" || which == "all") seeds = fogtest::tuningSeeds();
	if (which == "heldout" || which == "all")
		for (auto s : fogtest::heldOutSeeds()) seeds.push_back(s);
	if (which == "final")
		for (auto s : fogtest::finalSeeds()) seeds.push_back(s);
	if (which == "fresh")
		for (auto s : fogtest::freshSeeds()) seeds.push_back(s);
	if (!which.empty() && which.find_first_not_of("0123456789,") == std::string::npos)  // e.g. 18 or 18,20
		for (std::size_t i = 0; i < which.size();)
		{
			std::size_t j = which.find(',', i);
			if (j == std::string::npos) j = which.size();
			if (j > i) seeds.push_back(std::strtoull(which.substr(i, j - i).c_str(), nullptr, 10));
			i = j + 1;
		}
	if (seeds.empty())
	{
		std::fprintf(stderr, "bench_generalization: --seeds must be tuning, heldout, final, fresh, all or seed numbers (17,18)\n");
		return 2;
	}
	for (auto s : seeds)
		list.push_back({fogtest::Generator::FogSim, s, cap, effects, ideal, second_calibration, warmup_calibration, calibration_profile,
						turn_on_exclusion_s});
	for (int s = 1; s <= sector_coil; s++)
		list.push_back({fogtest::Generator::SectorCoil, static_cast<std::uint64_t>(s), cap, mrpt_fog::sim::defaultEffects(),
						false, second_calibration, false, calibration_profile, turn_on_exclusion_s});
	auto presets = fogtest::benchPresets();
	for (const auto& e : extra)
	{
		mrpt_fog::FitOptions none;
		none.selection = mrpt_fog::TermSelection::None;
		presets.push_back({e + " none", e, none, true});
	}
	if (!policy.empty())
		for (auto& p : presets) p.options.extrapolation = mrpt_fog::extrapolationPolicyFromString(policy);
	if (!excluded.empty())
	{
		std::vector<fogtest::BenchPreset> keep;
		for (const auto& p : presets)
		{
			bool drop = false;
			for (const auto& x : excluded) drop |= p.label.find(x) != std::string::npos;
			if (!drop) keep.push_back(p);
		}
		presets = keep;
	}
	if (!only.empty())
	{
		std::vector<fogtest::BenchPreset> keep;
		for (const auto& p : presets)
			if (p.label.find(only) != std::string::npos) keep.push_back(p);
		presets = keep;
	}
	if (rate_window_s > 0)
		for (auto& p : presets) p.options.rate_estimator.window_s = rate_window_s;
	if (savgol)
		for (auto& p : presets)
		{
			p.options.rate_estimator.kind = mrpt_fog::RateEstimatorKind::SavitzkyGolay;
			p.options.rate_estimator.poly_order = 1;  // a centred line: no delay
		}
	if (causal_order > 0)
		for (auto& p : presets) p.options.rate_estimator.poly_order = causal_order;
	if (!also_windows_s.empty())  // the same presets again, each with another rate estimator (same simulated runs)
	{
		const std::size_t n = presets.size();
		for (double w : also_windows_s)
			for (std::size_t i = 0; i < n; i++)
			{
				fogtest::BenchPreset o = presets[i];
				if (w < 0)
				{
					o.label += " o1";
					o.options.rate_estimator.poly_order = 1;
				}
				else
				{
					o.label += " w" + std::to_string(static_cast<int>(w));
					o.options.rate_estimator.window_s = w;
				}
				presets.push_back(o);
			}
	}
	if (also_no_warmup)  // the same presets without the warm-up term (label " nowarm"), same simulated runs
	{
		const std::size_t n = presets.size();
		for (std::size_t i = 0; i < n; i++)
		{
			fogtest::BenchPreset o = presets[i];
			o.label += " nowarm";
			o.no_warmup = true;
			presets.push_back(o);
		}
	}
	if (also_seed_run_only)  // the same presets fitted on the seed run alone (label " 1run"), same simulated runs
	{
		const std::size_t n = presets.size();
		for (std::size_t i = 0; i < n; i++)
		{
			// one run: no warm-up term, and the run folds of several runs do not apply
			if (presets[i].no_warmup || presets[i].options.run_folds != mrpt_fog::RunFolds::Runs) continue;
			fogtest::BenchPreset o = presets[i];
			o.label += " 1run";
			o.seed_run_only = true;
			presets.push_back(o);
		}
	}
	if (oracle)
	{
		const std::size_t n = presets.size();
		for (std::size_t i = 0; i < n; i++)
		{
			fogtest::BenchPreset o = presets[i];
			o.label = "oracle " + o.label;
			o.fit_on_evaluation = true;
			presets.push_back(o);
		}
	}
	const auto profiles = fogtest::evaluationProfiles();
	std::vector<fogtest::CaseResult> all;
	for (const auto& c : list)
	{
		const auto r = fogtest::runBenchCase(c, presets, profiles);
		all.insert(all.end(), r.begin(), r.end());
		std::fprintf(stderr, "%s seed %llu done (%.1f Hz, %d thermistors)%s%s\n", fogtest::toString(c.generator),
					 static_cast<unsigned long long>(c.seed), r.empty() ? 0.0 : r[0].rate_hz,
					 r.empty() ? 0 : r[0].thermistors, c.generator == fogtest::Generator::FogSim ? ": " : "",
					 c.generator == fogtest::Generator::FogSim ? fogtest::drawDevice(c.seed).summary.c_str() : "");
	}
	if (cases)
		for (const auto& r : all)
			std::printf("%-8s %3llu %6.1fHz %dT %-12s %-22s ratio %7.2f raw/comp %6.2f %s %s\n", fogtest::toString(r.generator),
						static_cast<unsigned long long>(r.seed), r.rate_hz, r.thermistors, r.profile.c_str(),
						r.preset.c_str(), r.ratio, r.raw_over_comp, r.model_terms.c_str(), r.error.c_str());
	std::printf("seeds %s, %d sector-coil devices; ratio = held-out 100 s stability / noise floor\n", which.c_str(), sector_coil);
	std::printf("%-24s %6s %5s %8s %8s %14s\n", "preset", "cases", "fail", "median", "p90", "oor raw/comp");
	for (const auto& s : fogtest::summarise(all, presets))
		std::printf("%-24s %6zu %5zu %8.2f %8.2f %14.2f\n", s.preset.c_str(), s.cases, s.failures, s.median_ratio,
					s.p90_ratio, s.oor_median_raw_over_comp);
	// Per profile: median ratio of each preset.
	std::printf("\nmedian ratio per evaluation profile\n%-24s", "preset");
	for (const auto& pr : profiles) std::printf(" %12s", pr.name.c_str());
	std::printf("\n");
	for (const auto& bp : presets)
	{
		std::printf("%-24s", bp.label.c_str());
		for (const auto& pr : profiles)
		{
			std::vector<double> v;
			for (const auto& r : all)
				if (r.preset == bp.label && r.profile == pr.name) v.push_back(r.ok ? r.ratio : 1e9);
			std::printf(" %12.2f", fogtest::quantile(v, 0.5));
		}
		std::printf("\n");
	}
	return 0;
}
