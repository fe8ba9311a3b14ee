/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/** Hidden-effect trials on the third generator (tests/support/ShellCoilGenerator.h), analysed as
 * fog-discrepancy does at its defaults: a run sampled faster than 1 Hz is read as 1 s block means
 * (io/BlockMeanReader.h, the reader's own accumulator), then analyseDiscrepancy with the analysis
 * timescale chosen from the data; base model M2:Tin@2/1 as a bias-only calibration
 * (fog-calibrate --scale-factor off: a hidden scale factor is then missing from it). Trial with
 * seed s: run 1 = generator seed 2s, run 2 (confirmation) = 2s + 1.
 *  - named: the first named effect, or a member of its alias group, is one of the candidate ids
 *    that name the hidden effect right (shellCoilAcceptedIds);
 *  - null trial: false naming when anything is named.
 * Each cell prints a "SHELL ..." line (grep SHELL).
 */
#include <mrpt_fog/discrepancy/DiscrepancyAnalysis.h>
#include <mrpt_fog/io/BlockMeanReader.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "ShellCoilGenerator.h"

namespace shell_trials
{
using namespace mrpt_fog::discrepancy;

constexpr const char* kBaseModel = "M2:Tin@2/1";

/** The rows fog-discrepancy analyses: 1 s block means of a faster run (as it reads a file). */
inline mrpt_fog::FogSeries asRead(const mrpt_fog::FogSeries& run)
{
	mrpt_fog::FogSeries layout = run;
	layout.resize(0);
	if (!run.table_rate_dph.empty()) layout.table_rate_dph = {NAN};
	if (!run.field_uT.empty()) layout.field_uT = {NAN};
	if (!run.power.empty()) layout.power = {NAN};
	mrpt_fog::BlockMeanOptions bo;  // the reader's defaults: 1 s blocks, 65536 rows
	mrpt_fog::BlockMeanAccumulator acc(layout, bo);
	mrpt_fog::FogSample x;
	x.temp_C.resize(run.thermistorCount());
	for (std::size_t k = 0; k < run.size(); ++k)
	{
		x.time_s = run.time_s[k];
		for (int a = 0; a < 3; ++a) x.rate_dph[a] = run.rate_dph[a].empty() ? NAN : run.rate_dph[a][k];
		for (std::size_t i = 0; i < run.thermistorCount(); ++i) x.temp_C[i] = run.temp_C[i][k];
		x.table_rate_dph = run.table_rate_dph.empty() ? NAN : run.table_rate_dph[k];
		x.field_uT = run.field_uT.empty() ? NAN : run.field_uT[k];
		x.power = run.power.empty() ? NAN : run.power[k];
		acc.add(x);
	}
	mrpt_fog::BlockMeanInfo info;
	return acc.finish(info);
}

inline DiscrepancyOptions trialOptions()
{
	DiscrepancyOptions o;
	o.scale_factor = ScaleFactorFitting::Off;
	return o;
}

struct Outcome
{
	bool named_ok = false, false_naming = false;
	std::vector<std::string> named_ids;  //!< the named ids with their alias groups, as the verdict
	double block_s = 0;
	std::string summary;
};

inline bool namesRight(const DiscrepancyReport& rep, const std::string& hidden)
{
	if (rep.selection.named.empty()) return false;
	const auto& first = rep.selection.named.front();
	for (const auto& id : fogtest::shellCoilAcceptedIds(hidden))
		if (std::find(first.alias_group.begin(), first.alias_group.end(), id) != first.alias_group.end()) return true;
	return false;
}

inline Outcome scoreReport(const DiscrepancyReport& rep, const std::string& hidden, double ratio, std::uint64_t seed,
						   double dt_s)
{
	Outcome out;
	out.block_s = rep.timescale.block_s;
	if (hidden.empty())
		out.false_naming = !rep.selection.named.empty();
	else
		out.named_ok = namesRight(rep, hidden);
	for (const auto& ne : rep.selection.named) out.named_ids.push_back(ne.id);
	char buf[300];
	std::snprintf(buf, sizeof buf, "seed %llu dt %gs %s x%g (block %.3g s, corner %.3g s): %s",
				  static_cast<unsigned long long>(seed), dt_s, hidden.empty() ? "null" : hidden.c_str(), ratio,
				  rep.timescale.block_s, rep.timescale.white_corner_s, rep.verdict().c_str());
	out.summary = buf;
	for (const auto& rj : rep.rejected) out.summary += "; not named " + rj.id + " (" + rj.reason.substr(0, 110) + ")";
	for (const auto& ne : rep.selection.not_confirmed) out.summary += "; not confirmed " + ne.id;
	return out;
}

inline Outcome runShellTrial(const std::string& hidden, double ratio, std::uint64_t seed, double dt_s)
{
	fogtest::ShellCoilOptions o1, o2;
	o1.dt_s = o2.dt_s = dt_s;
	o1.seed = 2 * seed;
	o2.seed = 2 * seed + 1;
	if (!hidden.empty()) o1.hidden[hidden] = o2.hidden[hidden] = ratio;
	const auto r1 = asRead(fogtest::makeShellCoilRun(o1).series);
	const auto r2 = asRead(fogtest::makeShellCoilRun(o2).series);
	const auto rep = analyseDiscrepancy({r1, r2}, {"run1", "run2"}, kBaseModel, trialOptions());
	const auto out = scoreReport(rep, hidden, ratio, seed, dt_s);
	std::printf("  trial: %s\n", out.summary.c_str());
	std::fflush(stdout);
	return out;
}

struct Tally
{
	int trials = 0, named = 0, false_naming = 0;
	std::vector<std::string> misses;
};

inline Tally runShellCell(const std::string& hidden, double ratio, std::uint64_t first_seed, int count, double dt_s)
{
	Tally t;
	for (int i = 0; i < count; ++i)
	{
		const auto o = runShellTrial(hidden, ratio, first_seed + static_cast<std::uint64_t>(i), dt_s);
		++t.trials;
		t.named += o.named_ok;
		t.false_naming += o.false_naming;
		if ((!hidden.empty() && !o.named_ok) || o.false_naming) t.misses.push_back(o.summary);
	}
	std::printf("SHELL dt %gs %s x%g seeds %llu..%llu: named %d/%d, false naming %d\n", dt_s,
				hidden.empty() ? "null" : hidden.c_str(), ratio, static_cast<unsigned long long>(first_seed),
				static_cast<unsigned long long>(first_seed + count - 1), t.named, t.trials, t.false_naming);
	for (const auto& m : t.misses) std::printf("  miss: %s\n", m.c_str());
	std::fflush(stdout);
	return t;
}

}  // namespace shell_trials
