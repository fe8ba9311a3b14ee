/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file GeneralizationBench.h
 * Test support: the generalization bench. Each device of an ensemble (drawn with
 * DeviceEnsemble.h from fog-sim's physics, or with the independent SectorCoilGenerator.h) is
 * calibrated on the seed's chamber profile and evaluated on other profiles it never saw
 * (evaluationProfiles()); the figure is the held-out 100 s bias stability divided by that
 * device's noise floor on the same profile (the 100 s stability of the same device and profile
 * with every thermal error off). A ratio of 1 is the best any model can do.
 */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/ErrorEffects.h>

#include <cstdint>
#include <string>
#include <vector>

namespace fogtest
{
struct BenchProfile
{
	std::string name;
	mrpt_fog::sim::ChamberProfile profile;
	bool out_of_range = false;  //!< colder and hotter than the calibration profile
};

/** The seed profile (25 -> -40 -> 60 C at 1 C/min, 2 h soaks): what every device is fitted on. */
mrpt_fog::sim::ChamberProfile calibrationProfile();
/** B (other rates, a step, a swept sine), heat_first (heating before cooling, 0.5 and 2 C/min,
 * 1 h soaks), sine_soaks (a 40 min sine, short soaks, 0.7 / 1.5 C/min), cold_start (unpowered
 * equilibrium, power on, 3 h), and out_of_range (-55 .. 75 C, beyond the calibrated -40 .. 60). */
std::vector<BenchProfile> evaluationProfiles();

/** A model as the bench fits it. */
struct BenchPreset
{
	std::string label;
	std::string preset;
	mrpt_fog::FitOptions options;
	bool fixed = true;  //!< false for presets that select terms (the default)
	/** Diagnostic only: fitted on each evaluation run itself (in-sample there), the best that
	 * model family and selection can do on that profile; not a held-out figure. */
	bool fit_on_evaluation = false;
	/** Fitted on the seed run alone (no second calibration run, no warm-up term) even when the
	 * case has them: one and several calibration runs compared on the same simulated runs. */
	bool seed_run_only = false;
	bool no_warmup = false;  //!< without the warm-up term even when the case has a turn-on run
};
/** The default (`multipoint`, default options) and fixed presets (selection none). */
std::vector<BenchPreset> benchPresets();

enum class Generator
{
	FogSim,
	SectorCoil
};
const char* toString(Generator g);

/** Time after a turn-on left out of the bias fit in a calibration run that holds one [s]:
 * fog-calibrate's suggestion (kSuggestedTurnOnExclusion_s). */
constexpr double kBenchTurnOnExclusion_s = mrpt_fog::kSuggestedTurnOnExclusion_s;

struct BenchCase
{
	Generator generator = Generator::FogSim;
	std::uint64_t seed = 0;
	double rate_cap_hz = 1e9;  //!< the drawn sample rate, at most this (the quick subset caps it)
	/** Diagnostics (fog-sim devices only): the simulator effects of the calibration and
	 * evaluation runs (default: all), and thermistors without reading noise or quantisation. */
	mrpt_fog::sim::EffectSet effects = mrpt_fog::sim::defaultEffects();
	bool ideal_thermistors = false;
	/** A second calibration run (two runs: the fit's selection leaves out whole runs): the name of
	 * a profile of secondCalibrationProfiles() (not evaluated: none is an evaluation profile), or
	 * of an evaluation profile (then that profile's evaluation run is the second calibration run
	 * and is not evaluated). Empty: the seed run alone. */
	std::string second_calibration;
	/** A turn-on run (cal_turn_on, fog-sim devices) fits the warm-up term (fitWarmup) on top of
	 * each bias calibration, as fog-calibrate --warmup-run does. */
	bool warmup_calibration = false;
	/** The calibration run's profile: empty = the seed profile; otherwise the name of a profile of
	 * secondCalibrationProfiles() (e.g. cal_single: one run that starts with a turn-on). A
	 * calibration run holding a turn-on keeps the first kBenchTurnOnExclusion_s after it out of
	 * the bias fit and fits the warm-up term on itself (fitWarmup), as fog-calibrate does. */
	std::string calibration_profile;
	/** FitOptions::turn_on_exclusion_s for such a run (0: the turn-on joins the bias fit, no warm-up term). */
	double turn_on_exclusion_s = kBenchTurnOnExclusion_s;
};


/** Calibration runs a user with a chamber could add to the seed run, none of them an
 * evaluation profile: cal_sine (a 30 min sine of +-20 C about 5 C, then 2 and 3 C/min ramps to
 * -35 and 55 C with 45 min soaks) and cal_turn_on (a turn-on from unpowered equilibrium at
 * 10 C, 3 h: the cold start's history at another ambient); cal_single, the three in one
 * chamber run: a turn-on from unpowered equilibrium at 25 C, 2 h, the seed profile, then
 * cal_sine's sine and ramps (12.8 h). */
std::vector<BenchProfile> secondCalibrationProfiles();

struct CaseResult
{
	Generator generator = Generator::FogSim;
	std::uint64_t seed = 0;
	double rate_hz = 0;
	int thermistors = 0;
	std::string profile, preset;
	bool out_of_range = false;
	bool ok = false;
	std::string error;  //!< why the fit or evaluation failed
	double stability_dph = 0, raw_stability_dph = 0, noise_floor_dph = 0;
	double ratio = 0;  //!< stability / noise floor
	double raw_over_comp = 0;
	std::string model_terms;  //!< chosen terms (count and names, for reports)
};

/** Runs one device through every preset and evaluation profile. */
std::vector<CaseResult> runBenchCase(const BenchCase& c, const std::vector<BenchPreset>& presets,
									 const std::vector<BenchProfile>& profiles);

struct PresetSummary
{
	std::string preset;
	std::size_t cases = 0, failures = 0;
	double median_ratio = 0, p90_ratio = 0;  //!< in-range profiles
	double oor_median_raw_over_comp = 0;  //!< out-of-range profile: raw / compensated stability
	double oor_median_ratio = 0;
};
/** Median and 90th percentile per preset (failed fits count as +inf). */
std::vector<PresetSummary> summarise(const std::vector<CaseResult>& results, const std::vector<BenchPreset>& presets);

/** Quantile q in [0, 1] (linear interpolation), of a copy. */
double quantile(std::vector<double> v, double q);

}  // namespace fogtest
