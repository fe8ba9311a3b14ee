/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file DiscrepancyTrials.h
 * Randomised proof trials of the model-gap workflow: a run (and a confirmation run with
 * another seed) is generated with known hidden effect(s) that the base model lacks; the
 * selector must name them. Used by the unit tests (10 seeds per cell), the long suite (100)
 * and printed as the success table (effect x ratio: named / trials).
 *
 * A trial counts as "named" when the strongest hidden effect is the first named id, or is in
 * the first named effect's alias group when `accept_alias` (profiles that truly cannot
 * separate); with two hidden effects both must be named (first or alias), strongest first.
 * "Gap ok" when the residual RMS on the confirmation run falls by at least half of the hidden
 * effects' share: (before - after) >= 0.5 (before - oracle), oracle = base model plus the TRUE
 * effect shapes fitted on the first run.
 */

#include <mrpt_fog/discrepancy/EffectSelector.h>
#include "support/SyntheticChamberRun.h"

#include <cstdint>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct TrialSpec
{
	std::vector<std::string> hidden;  //!< ids, strongest first (empty = no hidden effect)
	std::vector<double> ratios;  //!< effect-to-noise ratio per hidden id
	std::uint64_t seed = 1;
	SyntheticProfile profile = SyntheticProfile::AllConditions;
	std::string base_preset = "static:3";
	double dt_s = 20.0;
	// confounders
	double static_coef_error = 0.0;  //!< run-to-run error of the static cubic (confirmation run)
	double thermistor_noise_C = 0.002;
	double thermistor_quantum_C = 0.0;
	bool gap = false;
	std::size_t outliers = 0;
	bool accept_alias = true;
};

struct TrialOutcome
{
	std::vector<NamedEffect> named;
	bool named_ok = false;  //!< hidden effect(s) named as required
	bool clean = false;  //!< named_ok and the first named id is exactly the strongest hidden one
	bool false_naming = false;  //!< no hidden effect but something named
	double rms_before_dph = 0, rms_after_dph = 0, rms_oracle_dph = 0;  //!< confirmation run
	bool gap_ok = false;
	std::string summary;  //!< one line
};

TrialOutcome runTrial(const TrialSpec& spec, const SelectionOptions& opt = {});

/** Scores a selection (already confirmed on run 2) against the truth: the hidden ids
 * (strongest first) and each one's TRUE bias contribution on run 1 and run 2 (oracle columns;
 * may be empty when unknown). summary = "named=... rms2 before/after/oracle=...". */
TrialOutcome scoreTrial(const std::vector<std::string>& hidden, bool accept_alias, const SelectionResult& sel,
						const RunSignals& sig1, const BaseDesign& base1, const RunSignals& sig2, const BaseDesign& base2,
						const std::vector<std::vector<double>>& truth1, const std::vector<std::vector<double>>& truth2);

/* The same on the real simulator, with the effect scaled to a ratio: SimEffectTrial.h. */

}  // namespace mrpt_fog::discrepancy
