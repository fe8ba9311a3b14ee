/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The validation folds of the fit and what each accumulates. */
#include <mrpt_fog/model/CalibrationFitStages.h>
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/FitFigureStats.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::calibration_fit
{
/** Regime folds of one run: each sample's regime (cooling, soak, heating by the mean rate of the
 * thermistors against regime_rate_C_per_min), contiguous runs shorter than min_regime_s merged
 * into the previous one; regime segment j is fold j mod max_folds (RegimeFoldCursor). Returns the
 * merged segments (memory: the segments, not the samples). */
std::vector<RegimeSegment> regimeSegments(const PreparedRun& r, double threshold_C_per_min, double min_regime_s,
										  double window_s)
{
	// The regime is a property of the run, not of the model: the rate of the mean of ALL the
	// run's thermistors (finite readings), whatever thermistors the preset uses.
	// The mean temperature's rate, sample by sample (CausalRateEstimator's numbers, no columns).
	CausalRateTracker tracker(1, window_s);
	const double thr = threshold_C_per_min / 60.0;
	// Segments: [start time, class]; short ones take the class of the one before. Each finished
	// segment is merged at once (the merge only looks at the last merged segment).
	std::vector<RegimeSegment> merged;
	const auto merge = [&](const RegimeSegment& s) {
		if (!merged.empty() && (s.t1 - s.t0 < min_regime_s || merged.back().cls == s.cls))
			merged.back().t1 = s.t1;
		else if (merged.empty() || s.t1 - s.t0 >= min_regime_s)
			merged.push_back(s);
	};
	bool has_seg = false;
	RegimeSegment seg{0, 0, 0};
	forEachSample(r, nullptr, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
		double sum = 0, mean_C = std::numeric_limits<double>::quiet_NaN();
		int cnt = 0;
		for (const auto& col : c.temp_C)
			if (std::isfinite(col[j]))
			{
				sum += col[j];
				cnt++;
			}
		if (cnt == static_cast<int>(c.temp_C.size()) && cnt > 0) mean_C = sum / cnt;
		tracker.push(c.time_s[j], &mean_C);
		const double m = std::isnan(mean_C) ? std::numeric_limits<double>::quiet_NaN() : tracker.rate(0);
		if (!r.ok[k0 + j] || !std::isfinite(m)) return;
		const int cls = m > thr ? 2 : (m < -thr ? 0 : 1);
		const double t = c.time_s[j];
		if (!has_seg || seg.cls != cls)
		{
			if (has_seg) merge(seg);
			seg = {t, t, cls};
			has_seg = true;
		}
		seg.t1 = t;
	});
	if (has_seg) merge(seg);
	if (merged.size() >= 2 && merged.front().t1 - merged.front().t0 < min_regime_s)
	{
		merged[1].t0 = merged.front().t0;
		merged.erase(merged.begin());
	}
	return merged;
}

FoldPlan planFolds(const std::vector<FogRun>& runs, const std::vector<PreparedRun>& prep, const FitOptions& opt)
{
	FoldPlan p;
	p.by_run = runs.size() >= 2;
	p.run_regimes = p.by_run && opt.run_folds == RunFolds::RegimesWithinRuns;
	// regimes_of[r]: run r's regime segments (one run: the run's, Regimes scheme; several runs:
	// RunFolds::RegimesWithinRuns); a run with fewer than 3 is not cut (blocks / one fold).
	p.regimes_of.assign(runs.size(), {});
	if ((!p.by_run && opt.fold_scheme == FoldScheme::Regimes) || p.run_regimes)
		for (std::size_t ri = 0; ri < runs.size(); ri++)
		{
			p.regimes_of[ri] = regimeSegments(prep[ri], opt.regime_rate_C_per_min, opt.min_regime_s, opt.rate_estimator.window_s);
			if (p.regimes_of[ri].size() < 3)
				p.regimes_of[ri].clear();  // a single soak or ramp: blocks instead (one run) or the whole run
			p.regime_segments += p.regimes_of[ri].size();
		}
	p.by_regime = !p.by_run && !p.regimes_of[0].empty();
	// The first fold of each run (several runs): one fold per run, or per regime fold of each run.
	p.run_fold0.assign(runs.size() + 1, 0);
	for (std::size_t ri = 0; ri < runs.size(); ri++)
		p.run_fold0[ri + 1] = p.run_fold0[ri] + (p.regimes_of[ri].empty() || !p.run_regimes ? 1 : std::min(p.regimes_of[ri].size(), opt.max_regime_folds));
	p.nfolds =
		p.by_run ? p.run_fold0[runs.size()] : (p.by_regime ? std::min(p.regime_segments, opt.max_regime_folds) : opt.folds);
	p.front_s = runs[0].frontTime_s();
	p.back_s = runs[0].backTime_s();
	p.blocks_per_fold = opt.blocks_per_fold;
	return p;
}

/** Pass 2: a streaming QR factor per fold, the selection's time-bin means and the resampling
 * units (kStabilityBlocks contiguous time blocks per run, split by fold: a block is never in two
 * folds), in one pass over the runs. */
FoldAccumulation accumulateFolds(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, const FoldPlan& plan,
								 const FitOptions& opt, double y_ref, const std::vector<double>& x_ref)
{
	const std::size_t nfolds = plan.nfolds;
	const std::size_t ns = fs.signals().size();
	const std::size_t nt = fs.thermistors().size();
	std::vector<double> temp(nt), rate(nt), values(ns), f(fs.termCount());  // one row
	FoldAccumulation acc{FoldSet{}, FoldSet{}, StreamingQr(fs.termCount(), y_ref, x_ref), {}};
	FoldSet& folds = acc.folds;
	folds.held_out.assign(nfolds, StreamingQr(fs.termCount(), y_ref, x_ref));
	const bool resample = opt.selection == TermSelection::Auto && opt.stability_resamples > 0;
	const bool significance = opt.selection == TermSelection::Auto && opt.step_rule == StepRule::Significant;
	const bool need_units = resample || significance;
	constexpr std::size_t kStabilityBlocks = 40;
	auto& units = acc.units;
	// Selection judges candidates on time-bin means (FitOptions::selection_bin_s): the rows of
	// `sel` are the means of features and bias over bins of that length (never across a fold or
	// run boundary), so the gyro's white noise, which grows with the sample rate, does not drown
	// the differences between thermal models. The fit itself uses every sample (`folds`).
	const bool binned = opt.selection_bin_s > 0;
	FoldSet& sel = acc.sel;
	sel.held_out.assign(nfolds, StreamingQr(fs.termCount(), y_ref, x_ref));
	std::vector<double> bin_f(fs.termCount()), bin_mean(fs.termCount());
	for (std::size_t ri = 0; ri < prep.size(); ri++)
	{
		const auto& r = prep[ri];
		const double t_front = r.run->frontTime_s(), t_back = r.run->backTime_s();
		RowCursor cur(r);
		RegimeFoldCursor regime(plan.regimes_of[ri], opt.max_regime_folds);
		double bin_t0 = 0, bin_y = 0;
		std::size_t bin_n = 0, bin_fold = 0, bin_block = 0;
		const auto flush = [&]() {
			if (bin_n == 0) return;
			const double inv = 1.0 / static_cast<double>(bin_n);
			for (std::size_t q = 0; q < bin_f.size(); q++) bin_mean[q] = bin_f[q] * inv;
			sel.held_out[bin_fold].add(bin_mean.data(), bin_y * inv);
			if (need_units)
			{
				auto it = units.find({bin_fold, bin_block});
				if (it == units.end())
					it = units.emplace(std::make_pair(bin_fold, bin_block), StreamingQr(fs.termCount(), y_ref, x_ref)).first;
				it->second.add(bin_mean.data(), bin_y * inv);
			}
			std::fill(bin_f.begin(), bin_f.end(), 0.0);
			bin_y = 0;
			bin_n = 0;
		};
		forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
			if (!r.ok[k0 + j]) return;
			rowSignals(cur, fs, c, k0, j, temp, rate, values);
			fs.features(values.data(), f.data(), false);
			const double t = c.time_s[j];
			const std::size_t fold = plan.foldOf(ri, t, regime);
			const double y = r.y(c, j);
			folds.held_out[fold].add(f.data(), y);
			if (!binned && !need_units) return;
			const double u = std::clamp((t - t_front) / (t_back - t_front + 1e-300), 0.0, 1.0);
			const std::size_t block =
				ri * kStabilityBlocks + std::min(kStabilityBlocks - 1, static_cast<std::size_t>(u * kStabilityBlocks));
			if (!binned)  // per sample: `sel` is `folds` (copied below); only the stability units
			{
				auto it = units.find({fold, block});
				if (it == units.end())
					it = units.emplace(std::make_pair(fold, block), StreamingQr(fs.termCount(), y_ref, x_ref)).first;
				it->second.add(f.data(), y);
				return;
			}
			if (bin_n > 0 && (fold != bin_fold || block != bin_block || !(t - bin_t0 < opt.selection_bin_s))) flush();
			if (bin_n == 0)
			{
				bin_t0 = t;
				bin_fold = fold;
				bin_block = block;
			}
			for (std::size_t q = 0; q < bin_f.size(); q++) bin_f[q] += f[q];
			bin_y += y;
			bin_n++;
		});
		flush();
	}
	StreamingQr& total = acc.total;
	for (auto& fo : folds.held_out) total.merge(fo);
	folds.training = trainingSets(folds.held_out);
	if (!binned) sel.held_out = folds.held_out;
	sel.training = trainingSets(sel.held_out);
	if (significance)
	{
		sel.units.assign(nfolds, {});
		for (const auto& [key, unit] : units) sel.units[key.first].push_back(unit);
	}
	return acc;
}

}  // namespace mrpt_fog::calibration_fit
