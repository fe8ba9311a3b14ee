/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/** Shared loops of the proof trials (default suite: 10 seeds; long suite: 100). Each loop
 * prints one table line "TRIALS <what> named <k>/<n> ..." so that the success table can be
 * regenerated with:  ./build-disc/tests/test_discrepancy --gtest_filter='*ProofTrials*' | grep TRIALS
 */
#include "support/DiscrepancyTrials.h"
#include "support/SimEffectTrial.h"
#include "TrialSubset.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace trial_suite
{
using namespace mrpt_fog::discrepancy;

using trial_subset::trialSeeds;

struct Tally
{
	int trials = 0, named = 0, clean = 0, gap_ok = 0, false_naming = 0;
	std::vector<std::string> misses;

	Tally& operator+=(const Tally& o)
	{
		trials += o.trials;
		named += o.named;
		clean += o.clean;
		gap_ok += o.gap_ok;
		false_naming += o.false_naming;
		misses.insert(misses.end(), o.misses.begin(), o.misses.end());
		return *this;
	}
};

/** Runs `seeds` trials (FOG_TRIAL_SEEDS subset aware), seed = first_seed + i, through
 * `trial(seed)` and tallies them; misses are the trials not named or without the gap target. */
template <class Trial>
Tally tallySeeds(int seeds, std::uint64_t first_seed, Trial trial)
{
	seeds = trialSeeds(seeds);
	Tally t;
	for (int s = 0; s < seeds; ++s)
	{
		const auto o = trial(first_seed + static_cast<std::uint64_t>(s));
		++t.trials;
		t.named += o.named_ok;
		t.clean += o.clean;
		t.gap_ok += o.gap_ok;
		t.false_naming += o.false_naming;
		if (!o.named_ok || !o.gap_ok) t.misses.push_back(o.summary);
	}
	return t;
}

inline Tally runSeeds(TrialSpec spec, int seeds, std::uint64_t first_seed)
{
	return tallySeeds(seeds, first_seed, [&](std::uint64_t seed) {
		spec.seed = seed;
		return runTrial(spec);
	});
}

inline void print(const std::string& what, const Tally& t)
{
	std::printf("TRIALS %-45s named %3d/%-3d clean %3d/%-3d gap_ok %3d/%-3d false %d%s\n", what.c_str(), t.named, t.trials,
				t.clean, t.trials, t.gap_ok, t.trials, t.false_naming,
				trialSeeds(10) < 10 ? "  (FOG_TRIAL_SEEDS subset: not the success table)" : "");
	for (const auto& m : t.misses) std::printf("  miss: %s\n", m.c_str());
	std::fflush(stdout);
}

/** The cells `what @1` and `what @3` (tally = cell(ratio)), each printed; returns their sum. */
template <class Cell>
Tally ratios1And3(const std::string& what, Cell cell)
{
	Tally all;
	// The sanitizer run's subset (TrialSubset.h): ratio 3 only, the same code with the effect scaled.
	const std::vector<double> ratios = trial_subset::subsetRun() ? std::vector<double>{3.0} : std::vector<double>{1.0, 3.0};
	for (double ratio : ratios)
	{
		const Tally t = cell(ratio);
		print(what + " @" + std::to_string(int(ratio)), t);
		all += t;
	}
	return all;
}

/** A trial with the given hidden effects at the given ratios (strongest first). */
inline TrialSpec hiddenSpec(std::vector<std::string> hidden, std::vector<double> ratios)
{
	TrialSpec s;
	s.hidden = std::move(hidden);
	s.ratios = std::move(ratios);
	return s;
}

inline const std::vector<std::string>& biasEffects()
{
	static const std::vector<std::string> ids{"shupe_rate", "radial_gradient", "gradient_rate", "thermistor_lag",
											  "hysteresis", "warmup", "scale_factor_temp", "magnetic",
											  "temp_poly_order"};
	return ids;
}

/** No hidden effect, with confounders mixed in (thermistor noise + quantisation every 3rd
 * trial, 5 outliers every 5th, a data gap every 7th). */
inline Tally nullTrials(int seeds, std::uint64_t first_seed)
{
	seeds = trialSeeds(seeds);
	Tally t;
	for (int s = 0; s < seeds; ++s)
	{
		TrialSpec spec;
		spec.seed = first_seed + static_cast<std::uint64_t>(s);
		if (s % 3 == 0)
		{
			spec.thermistor_noise_C = 0.01;
			spec.thermistor_quantum_C = 0.01;
		}
		if (s % 5 == 0) spec.outliers = 5;
		if (s % 7 == 0) spec.gap = true;
		const auto o = runTrial(spec);
		++t.trials;
		t.false_naming += o.false_naming;
		t.named += o.named_ok;
		t.clean += o.clean;
		t.gap_ok += o.gap_ok;
		if (o.false_naming) t.misses.push_back(o.summary);
	}
	return t;
}

/** Trials on the real simulator (SimEffectTrial.h): `seeds` seeds from first_seed. With an
 * empty spec.hidden these are null trials (false naming counted). */
inline Tally runSimSeeds(SimTrialSpec spec, int seeds, std::uint64_t first_seed)
{
	return tallySeeds(seeds, first_seed, [&](std::uint64_t seed) {
		spec.seed = seed;
		return runSimEffectTrial(spec);
	});
}

/** Confounder scenarios (ratio 3 unless stated), each over `seeds` seeds. */
inline std::vector<std::pair<std::string, TrialSpec>> confounderScenarios()
{
	std::vector<std::pair<std::string, TrialSpec>> v;
	TrialSpec a = hiddenSpec({"shupe_rate"}, {3});
	a.static_coef_error = 0.02;
	v.push_back({"shupe_rate@3 + 2% coefficient error (run 2)", a});
	TrialSpec b = hiddenSpec({"radial_gradient"}, {3});
	b.thermistor_noise_C = 0.01;
	b.thermistor_quantum_C = 0.01;
	v.push_back({"radial_gradient@3 + thermistor noise/quant", b});
	TrialSpec c = hiddenSpec({"hysteresis"}, {3});
	c.gap = true;
	v.push_back({"hysteresis@3 + data gap", c});
	TrialSpec d = hiddenSpec({"magnetic"}, {3});
	d.outliers = 5;
	v.push_back({"magnetic@3 + 5 outliers", d});
	v.push_back({"two hidden: shupe_rate@3 + magnetic@1.5", hiddenSpec({"shupe_rate", "magnetic"}, {3, 1.5})});
	v.push_back({"two hidden: radial_gradient@3 + warmup@1.5", hiddenSpec({"radial_gradient", "warmup"}, {3, 1.5})});
	return v;
}
}  // namespace trial_suite
