/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The choice of terms: forward selection by held-out error, parsimony, thermistor subsets, stability, the fitted models. */
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
namespace
{
/** A difference signal's first power, T(a)-T(b) or d/dt (T(a)-T(b)), is a linear combination of
 * the first powers of T(a) and T(b) (of their rates): when both are in the model it adds a
 * column in their span, which only a ridge can fit and which changes nothing but the ridge's
 * shrinkage. Such a step is not a candidate (its higher powers are; none are offered today). */
bool differenceInSpan(const ThermalFeatureSet& fs, std::size_t g, const std::vector<int>& order)
{
	const ThermalSignal& d = fs.signals()[g];
	if (!d.isDifference()) return false;
	const SignalKind part = d.kind == SignalKind::Diff ? SignalKind::Temp : SignalKind::Rate;
	bool has_a = false, has_b = false;
	for (std::size_t s = 0; s < fs.signals().size(); s++)
	{
		const ThermalSignal& x = fs.signals()[s];
		if (x.kind != part || order[s] < 1) continue;
		has_a |= x.a == d.a;
		has_b |= x.a == d.b;
	}
	return has_a && has_b;
}

/** Forward stepwise selection by CV error, among `allowed` signals, each up to max_order: a step
 * adds a signal at order 1 or raises an included signal's order by one (with orders off, a step
 * adds a whole signal at its preset order). A step must lower the held-out RMS by min_gain.
 * Returns the path (the empty model first). */
/** The paired difference of two candidates' block SSEs (a - b), summed, and its standard error
 * (blocks treated as independent: sqrt(blocks x variance of the per-block differences)).
 * {0, 0} without blocks. */
std::pair<double, double> pairedBlockDifference(const Choice& a, const Choice& b)
{
	double sum = 0, sum2 = 0;
	std::size_t n = 0;
	for (std::size_t u = 0; u < a.block_sse.size() && u < b.block_sse.size(); u++)
		if (std::isfinite(a.block_sse[u]) && std::isfinite(b.block_sse[u]))
		{
			const double d = a.block_sse[u] - b.block_sse[u];
			sum += d;
			sum2 += d * d;
			n++;
		}
	if (n < 2) return {sum, 0.0};
	const double mean = sum / static_cast<double>(n);
	const double var = std::max(0.0, (sum2 - static_cast<double>(n) * mean * mean) / static_cast<double>(n - 1));
	return {sum, std::sqrt(static_cast<double>(n) * var)};
}

/** Whether `step` improves on `cur` enough to be taken (StepRule). */
bool stepGains(const Choice& cur, const Choice& step, const FitOptions& opt)
{
	if (!(step.cv_rms < cur.cv_rms)) return false;
	if (opt.step_rule == StepRule::Significant && !cur.block_sse.empty() && !step.block_sse.empty())
	{
		const auto [diff, se] = pairedBlockDifference(cur, step);
		return diff > opt.step_z * se;
	}
	return step.cv_rms < cur.cv_rms * (1.0 - opt.min_relative_gain);
}

std::vector<Choice> selectForward(FoldSet& folds, const ThermalFeatureSet& fs, const std::vector<bool>& allowed,
								  const std::vector<int>& max_order, const FitOptions& opt)
{
	const bool orders = opt.select_orders, linear_base = opt.linear_base;
	const std::size_t ns = fs.signals().size();
	if (opt.order_search == OrderSearch::Common)
	{
		// Every (temperature order, rate order) pair, applied to all allowed thermistors alike.
		int max_t = 0, max_r = 0;
		for (std::size_t g = 0; g < ns; g++)
		{
			if (!allowed[g] || fs.signals()[g].isDifference() || fs.signals()[g].isLag()) continue;
			(fs.signals()[g].isRate() ? max_r : max_t) = std::max(fs.signals()[g].isRate() ? max_r : max_t, max_order[g]);
		}
		std::vector<Choice> all;
		for (int kt = std::min(1, max_t); kt <= max_t; kt++)
			for (int kr = std::min(1, max_r); kr <= max_r; kr++)
			{
				std::vector<int> order(ns, 0);
				for (std::size_t g = 0; g < ns; g++)
					if (allowed[g] && !fs.signals()[g].isDifference() && !fs.signals()[g].isLag())
						order[g] = std::min(max_order[g], fs.signals()[g].isRate() ? kr : kt);
				all.push_back(scoreOrders(folds, fs, order, kRidgeGrid));
			}
		return all;
	}
	std::vector<int> start(ns, 0);
	if (linear_base)  // every allowed thermistor's T and dT/dt at order 1 (Shupe is linear in the rates)
		for (std::size_t g = 0; g < ns; g++)
			if (allowed[g] && !fs.signals()[g].isDifference() && (!fs.signals()[g].isLag() || opt.lag_in_base) &&
				max_order[g] >= 1)
				start[g] = 1;
	std::vector<Choice> path{scoreOrders(folds, fs, start, linear_base ? kRidgeGrid : std::vector<double>{0.0})};
	while (true)
	{
		const Choice& cur = path.back();
		Choice step;
		for (std::size_t g = 0; g < ns; g++)
		{
			if (!allowed[g] || cur.order[g] >= max_order[g]) continue;
			if (!orders && cur.order[g] > 0) continue;
			if (cur.order[g] == 0 && differenceInSpan(fs, g, cur.order)) continue;
			// any higher order of the signal (a cubic can help where a quadratic alone does not)
			for (int k = orders ? cur.order[g] + 1 : max_order[g]; k <= max_order[g]; k++)
			{
				auto order = cur.order;
				order[g] = k;
				Choice c = scoreOrders(folds, fs, order, kRidgeGrid);
				if (c.cv_rms < step.cv_rms) step = c;
			}
		}
		if (!stepGains(cur, step, opt)) break;
		path.push_back(step);
	}
	return path;
}

/** Standard error of the paired difference of two candidates' per-fold MSEs (the folds both
 * scored): how far apart their CV errors may be by chance when the same folds judge both. The
 * spread of one candidate's fold MSEs (cv_se_mse) mostly measures how unlike the folds are
 * (a soak against a 2 C/min ramp), which both candidates share; the paired spread does not. */
double pairedSeMse(const Choice& a, const Choice& b)
{
	if (!a.block_sse.empty() && !b.block_sse.empty() && a.rows > 0)  // per block (StepRule::Significant)
		return pairedBlockDifference(a, b).second / a.rows;
	std::vector<double> d;
	for (std::size_t f = 0; f < a.fold_mse.size() && f < b.fold_mse.size(); f++)
		if (std::isfinite(a.fold_mse[f]) && std::isfinite(b.fold_mse[f])) d.push_back(a.fold_mse[f] - b.fold_mse[f]);
	if (d.size() < 2) return 0.0;
	double m = 0, v = 0;
	for (double x : d) m += x;
	m /= static_cast<double>(d.size());
	for (double x : d) v += (x - m) * (x - m);
	return std::sqrt(v / static_cast<double>(d.size() - 1) / static_cast<double>(d.size()));
}

/** Parsimony: among the candidates, the one with the fewest terms whose CV MSE is within one
 * standard error of the best (ties: lower CV error). paired: the standard error of the
 * difference to the best over the same folds (pairedSeMse), else the best's own (cv_se_mse). */
Choice oneStandardError(const std::vector<const Choice*>& cands, bool paired)
{
	const Choice* best = nullptr;
	for (const Choice* c : cands)
		if (!best || c->cv_rms < best->cv_rms) best = c;
	const double best_mse = best->cv_rms * best->cv_rms;
	const Choice* pick = best;
	for (const Choice* c : cands)
	{
		const double se = paired ? pairedSeMse(*c, *best) : best->cv_se_mse;
		if (c->cv_rms * c->cv_rms <= best_mse + se &&
			(c->terms < pick->terms || (c->terms == pick->terms && c->cv_rms < pick->cv_rms)))
			pick = c;
	}
	return *pick;
}

/** Nested search over thermistor subsets (selection "auto" of multipoint / points:K): the
 * forward path of every subset of the preset's thermistors (memoised over subset masks, 2^n - 1
 * paths for n thermistors). best(mask) is the lowest-CV candidate of mask and all its subsets,
 * so with the same folds more thermistors never give a larger cross-validated error; with
 * parsimony the final pick is the simplest candidate within one standard error of that best,
 * among mask and its subsets. */
class NestedSelection
{
   public:
	static constexpr std::size_t kMaxThermistors = 8;
	NestedSelection(const std::vector<std::string>& thermistors,
					std::function<std::vector<Choice>(const std::vector<std::string>&)> forward)
		: names_(thermistors), forward_(std::move(forward))
	{
		if (names_.size() > kMaxThermistors)
			throw std::invalid_argument("fit: selection auto searches every thermistor subset and supports up to " +
										std::to_string(kMaxThermistors) + " thermistors, got " +
										std::to_string(names_.size()) +
										": name fewer (multipoint:A,B,..), or use --selection none");
	}
	std::size_t fullMask() const { return (std::size_t{1} << names_.size()) - 1; }
	std::size_t bit(const std::string& name) const
	{
		for (std::size_t i = 0; i < names_.size(); i++)
			if (names_[i] == name) return std::size_t{1} << i;
		return 0;
	}
	const std::vector<Choice>& path(std::size_t mask)
	{
		auto it = memo_.find(mask);
		if (it != memo_.end()) return it->second;
		std::vector<std::string> pool;
		for (std::size_t i = 0; i < names_.size(); i++)
			if (mask & (std::size_t{1} << i)) pool.push_back(names_[i]);
		auto p = forward_(pool);
		for (auto& c : p) c.pool = pool;
		return memo_.emplace(mask, std::move(p)).first->second;
	}
	/** Every candidate of `mask` and its non-empty subsets. */
	std::vector<const Choice*> candidates(std::size_t mask)
	{
		std::vector<const Choice*> out;
		for (std::size_t sub = mask; sub > 0; sub = (sub - 1) & mask)
			for (const Choice& c : path(sub)) out.push_back(&c);
		return out;
	}
	Choice best(std::size_t mask, bool parsimony, bool paired = false)
	{
		const auto c = candidates(mask);
		if (parsimony) return oneStandardError(c, paired);
		const Choice* b = c.front();
		for (const Choice* x : c)
			if (x->cv_rms < b->cv_rms) b = x;
		return *b;
	}

   private:
	std::vector<std::string> names_;
	std::function<std::vector<Choice>(const std::vector<std::string>&)> forward_;
	std::map<std::size_t, std::vector<Choice>> memo_;
};
}  // namespace

/** Columns (sorted, constant first) of the terms with power <= order[signal]. */
std::vector<int> columnsOf(const ThermalFeatureSet& fs, const std::vector<int>& order)
{
	std::vector<int> cols{0};
	for (std::size_t i = 1; i < fs.termCount(); i++)
		if (fs.terms()[i].power <= order[static_cast<std::size_t>(fs.termSignal(i))]) cols.push_back(static_cast<int>(i));
	return cols;
}

/** Best ridge for an order vector; the choice with its CV RMS and the standard error of its CV
 * MSE (spread of the per-fold MSEs / sqrt(folds)). */
Choice scoreOrders(FoldSet& folds, const ThermalFeatureSet& fs, const std::vector<int>& order,
				   const std::vector<double>& ridges)
{
	Choice c;
	c.order = order;
	const auto cols = columnsOf(fs, order);
	c.terms = cols.size();
	std::vector<std::vector<double>> sse;
	std::vector<std::vector<std::vector<double>>> block;
	if (folds.units.empty())
		sse = crossValidatedFoldSse(folds.held_out, folds.training, cols, ridges);
	else
	{
		// The fold's SSE is the sum of its blocks' (the blocks partition its rows).
		block = crossValidatedBlockSse(folds.training, folds.units, cols, ridges);
		sse.assign(ridges.size(), std::vector<double>(folds.units.size(), std::numeric_limits<double>::quiet_NaN()));
		for (std::size_t r = 0; r < ridges.size(); r++)
			for (std::size_t f = 0; f < folds.units.size(); f++)
			{
				if (folds.held_out[f].count() == 0 || folds.training[f].count() == 0 || folds.units[f].empty()) continue;
				double t = 0;
				for (double x : block[r][f]) t += x;
				sse[r][f] = t;
			}
	}
	for (std::size_t r = 0; r < ridges.size(); r++)
	{
		double total = 0, rows = 0;
		std::vector<double> mse;
		bool bad = false;
		for (std::size_t f = 0; f < sse[r].size(); f++)
		{
			if (std::isnan(sse[r][f])) continue;
			if (!std::isfinite(sse[r][f])) bad = true;
			const double n = static_cast<double>(folds.held_out[f].count());
			total += sse[r][f];
			rows += n;
			mse.push_back(sse[r][f] / n);
		}
		if (bad || rows <= 0) continue;
		const double rms = std::sqrt(total / rows);
		if (rms < c.cv_rms * (1 - 1e-9))
		{
			c.cv_rms = rms;
			c.ridge = ridges[r];
			double m = 0, v = 0;
			for (double x : mse) m += x;
			m /= static_cast<double>(mse.size());
			for (double x : mse) v += (x - m) * (x - m);
			c.cv_se_mse = mse.size() > 1 ? std::sqrt(v / static_cast<double>(mse.size() - 1) / static_cast<double>(mse.size())) : 0.0;
			c.rows = rows;
			c.block_sse.clear();
			if (!block.empty())
				for (std::size_t f = 0; f < block[r].size(); f++)
					for (double x : block[r][f]) c.block_sse.push_back(x);
			c.fold_mse.clear();
			for (std::size_t f = 0; f < sse[r].size(); f++)
				c.fold_mse.push_back(std::isnan(sse[r][f]) ? std::numeric_limits<double>::quiet_NaN()
														   : sse[r][f] / static_cast<double>(folds.held_out[f].count()));
		}
	}
	return c;
}

BiasModel makeModel(StreamingQr& total, const ThermalFeatureSet& fs, const Choice& c, const std::string& dropped,
					const FitOptions& opt)
{
	const auto cols = columnsOf(fs, c.order);
	const double need = opt.min_samples_per_term * static_cast<double>(cols.size());
	if (static_cast<double>(total.count()) < need)
		throw std::invalid_argument("too few samples: " + std::to_string(total.count()) + " usable for " +
									std::to_string(cols.size()) + " terms (need at least " +
									std::to_string(static_cast<std::size_t>(need)) + ")");
	const LinearFit fit = solveBiasFit(total, cols, c.ridge);
	if (c.ridge == 0 && fit.numerical_rank < cols.size())
		throw std::invalid_argument("rank deficient: only " + std::to_string(fit.numerical_rank) + " of " +
									std::to_string(cols.size()) + " terms are independent on this data (condition " +
									"number " + std::to_string(fit.condition_number) +
									"); use fewer terms, --selection auto, or a ridge");
	BiasModel m;
	m.dropped = dropped;
	m.features = fs.selectOrders(c.order);
	m.coef_dph.assign(fit.coef_dph.data(), fit.coef_dph.data() + fit.coef_dph.size());
	m.covariance = fit.covariance;
	m.ridge = c.ridge;
	m.condition_number = fit.condition_number;
	m.numerical_rank = fit.numerical_rank;
	m.effective_dof = fit.effective_dof;
	m.samples = fit.samples;
	m.rms_in_sample_dph = fit.rms_dph;
	m.rms_held_out_dph = c.cv_rms;
	return m;
}

TermSearch::Result TermSearch::select(FoldSet& sel, FoldSet& folds) const
{
	const auto& fs = fs_;
	const auto& preset = preset_;
	const auto& opt = opt_;
	const auto& names = names_;
	const bool nested = nested_, automatic = automatic_;
	const std::size_t ns = ns_;
	const auto forward = [&](FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) {
		return this->forward(fset, pool, dropped);
	};
	const auto choose = [&](FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) {
		return this->choose(fset, pool, dropped);
	};
	Result res;
	Choice& best = res.best;
	std::vector<Choice>& fallback_choices = res.fallback_choices;
	if (nested)
	{
		NestedSelection search(names, [&](const std::vector<std::string>& pool) { return forward(sel, pool, ""); });
		std::size_t base = search.fullMask();
		if (preset.kind == PresetKind::Points)
		{
			// points:K = the best choice among all K-thermistor subsets (each with its subsets).
			const auto K = static_cast<std::size_t>(preset.points_k);
			bool first_set = true;
			for (std::size_t mask = 1; mask <= search.fullMask(); mask++)
			{
				if (static_cast<std::size_t>(__builtin_popcountll(mask)) != K) continue;
				const Choice c = search.best(mask, false);
				if (first_set || c.cv_rms < best.cv_rms)
				{
					best = c;
					base = mask;
					first_set = false;
				}
			}
		}
		best = search.best(base, opt.parsimony, opt.paired_se);
		if (opt.fallbacks)
		{
			const ThermalFeatureSet chosen = fs.selectOrders(best.order);
			for (const auto& name : chosen.thermistors())
			{
				const std::size_t without = base & ~search.bit(name);
				fallback_choices.push_back(without ? search.best(without, opt.parsimony, opt.paired_se)
												   : scoreOrders(folds, fs, std::vector<int>(ns, 0), {0.0}));
			}
		}
	}
	else
	{
		// Candidate pools: the preset's thermistors, or every K-subset for points:K (selection none).
		std::vector<std::vector<std::string>> pools;
		if (preset.kind == PresetKind::Points)
		{
			const std::size_t n = names.size(), K = static_cast<std::size_t>(preset.points_k);
			std::vector<bool> pick(n, false);
			std::fill(pick.begin(), pick.begin() + static_cast<long>(K), true);
			do
			{
				std::vector<std::string> sub;
				for (std::size_t i = 0; i < n; i++)
					if (pick[i]) sub.push_back(names[i]);
				pools.push_back(sub);
			} while (std::prev_permutation(pick.begin(), pick.end()) && pools.size() < 256);
		}
		else
			pools.push_back(names);
		bool first_pool = true;
		for (const auto& pool : pools)
		{
			const Choice c = choose(automatic ? sel : folds, pool, "");
			if (first_pool || c.cv_rms < best.cv_rms)
			{
				best = c;
				first_pool = false;
			}
		}
		if (opt.fallbacks)
		{
			const ThermalFeatureSet chosen = fs.selectOrders(best.order);
			for (const auto& name : chosen.thermistors()) fallback_choices.push_back(choose(automatic ? sel : folds, best.pool, name));
		}
	}
	return res;
}

Choice TermSearch::selectMain(FoldSet& fset, const Choice& best) const
{
	const auto& opt = opt_;
	const auto& preset = preset_;
	if (nested_)
	{
		NestedSelection search(names_, [&](const std::vector<std::string>& pool) { return forward(fset, pool, ""); });
		std::size_t base = search.fullMask();
		if (preset.kind == PresetKind::Points)
		{
			double lowest = std::numeric_limits<double>::infinity();
			for (std::size_t mask = 1; mask <= search.fullMask(); mask++)
			{
				if (static_cast<std::size_t>(__builtin_popcountll(mask)) != static_cast<std::size_t>(preset.points_k))
					continue;
				const Choice c = search.best(mask, false);
				if (c.cv_rms < lowest)
				{
					lowest = c.cv_rms;
					base = mask;
				}
			}
		}
		return search.best(base, opt.parsimony, opt.paired_se);
	}
	return choose(fset, best.pool, "");
}

std::vector<bool> TermSearch::allowedFor(const std::vector<std::string>& pool, const std::string& dropped) const
{
	std::vector<bool> allowed(ns_);
	for (std::size_t s = 0; s < ns_; s++)
	{
		const auto& sig = fs_.signals()[s];
		const auto in = [&](const std::string& n) { return std::find(pool.begin(), pool.end(), n) != pool.end(); };
		allowed[s] = in(sig.a) && (!sig.isDifference() || in(sig.b)) && !sig.references(dropped);
	}
	return allowed;
}

std::vector<Choice> TermSearch::forward(FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) const
{
	return selectForward(fset, fs_, allowedFor(pool, dropped), max_order_, opt_);
}

Choice TermSearch::choose(FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) const
{
	const auto& opt = opt_;
	Choice c;
	if (automatic_)
	{
		const auto path = forward(fset, pool, dropped);
		std::vector<const Choice*> cands;
		for (const auto& x : path) cands.push_back(&x);
		c = opt.parsimony ? oneStandardError(cands, opt.paired_se) : *std::min_element(path.begin(), path.end(), [](const Choice& a, const Choice& b) {
			return a.cv_rms < b.cv_rms;
		});
	}
	else
	{
		auto order = max_order_;
		const auto allowed = allowedFor(pool, dropped);
		for (std::size_t s = 0; s < ns_; s++)
			if (!allowed[s]) order[s] = 0;
		c = scoreOrders(fset, fs_, order, {opt.ridge});
	}
	c.pool = pool;
	return c;
}

/** Stability of the choice: the main-model selection rerun on wild (sign-flip) block-bootstrap
 * resamples of the calibration data (every unit kept in its fold, its residual sign-flipped
 * with probability 1/2). Empty unless automatic selection with resamples asked for. */
SelectionStability selectionStability(const TermSearch& terms, FoldAccumulation& acc, const Choice& best,
									  const ThermalFeatureSet& fs, const FoldPlan& plan, const FitOptions& opt, double y_ref,
									  const std::vector<double>& x_ref)
{
	SelectionStability stability;
	const bool resample = opt.selection == TermSelection::Auto && opt.stability_resamples > 0;
	const bool significance = opt.selection == TermSelection::Auto && opt.step_rule == StepRule::Significant;
	if (!resample || acc.units.empty()) return stability;
	const std::size_t nfolds = plan.nfolds;
	auto& units = acc.units;
	auto& total = acc.total;
	auto& folds = acc.folds;
	const auto selectMain = [&](FoldSet& fset) -> Choice { return terms.selectMain(fset, best); };
	const auto termsOf = [&](const Choice& c) {
		std::string s;
		for (const auto& n : fs.selectOrders(c.order).termNames())
			if (n != "1") s += (s.empty() ? "" : " + ") + n;
		return s.empty() ? std::string("1") : s;
	};
	std::vector<const StreamingQr*> unit_list;
	std::vector<std::size_t> unit_fold;
	for (const auto& [key, acc] : units)
	{
		unit_list.push_back(&acc);
		unit_fold.push_back(key.first);
	}
	// Wild (sign-flip) block bootstrap: the rows (the thermal history) stay, the residual of
	// the chosen model changes sign block by block: another noise realisation of the same
	// calibration run, which is what "the same choice with another noise seed" asks about.
	// (A bootstrap that redraws the blocks themselves also changes which temperatures are
	// seen, a much larger change: it called every fit unstable.)
	const LinearFit chosen_fit = solveBiasFit(total, columnsOf(fs, best.order), best.ridge);
	const Eigen::VectorXd beta = shiftedFullCoefficients(total, chosen_fit.columns, chosen_fit.coef_dph);
	std::mt19937_64 rng(opt.stability_seed);
	std::bernoulli_distribution flip(0.5);
	std::map<std::string, std::size_t> model_count, term_count;
	std::map<std::string, std::vector<int>> model_order;
	for (std::size_t b = 0; b < opt.stability_resamples; b++)
	{
		FoldSet fr;
		fr.held_out.assign(nfolds, StreamingQr(fs.termCount(), y_ref, x_ref));
		if (significance) fr.units.assign(nfolds, {});
		for (std::size_t u = 0; u < unit_list.size(); u++)
		{
			if (!flip(rng))
			{
				fr.held_out[unit_fold[u]].merge(*unit_list[u]);
				if (significance) fr.units[unit_fold[u]].push_back(*unit_list[u]);
				continue;
			}
			StreamingQr flipped = *unit_list[u];
			flipped.flipResiduals(beta);
			fr.held_out[unit_fold[u]].merge(flipped);
			if (significance) fr.units[unit_fold[u]].push_back(flipped);
		}
		fr.training = trainingSets(fr.held_out);
		const Choice c = selectMain(fr);
		const std::string key = termsOf(c);
		model_count[key]++;
		model_order[key] = c.order;
		for (const auto& n : fs.selectOrders(c.order).termNames())
			if (n != "1") term_count[n]++;
	}
	const double nb = static_cast<double>(opt.stability_resamples);
	stability.resamples = opt.stability_resamples;
	const std::string chosen = termsOf(best);
	stability.chosen_share = model_count.count(chosen) ? static_cast<double>(model_count[chosen]) / nb : 0.0;
	stability.stable = stability.chosen_share >= opt.stable_share;
	for (const auto& [key, n] : model_count)
	{
		if (key == chosen) continue;
		SelectionStability::Alternative a;
		a.terms = key;
		a.share = static_cast<double>(n) / nb;
		a.held_out_rms_dph = scoreOrders(folds, fs, model_order[key], kRidgeGrid).cv_rms;  // on the real folds
		stability.alternatives.push_back(a);
	}
	const Choice chosen_score = scoreOrders(folds, fs, best.order, kRidgeGrid);
	stability.chosen_held_out_rms_dph = chosen_score.cv_rms;
	stability.held_out_se_mse = chosen_score.cv_se_mse;
	stability.alternatives_equivalent = !stability.alternatives.empty();
	for (const auto& a : stability.alternatives)
		stability.alternatives_equivalent &= std::abs(a.held_out_rms_dph * a.held_out_rms_dph -
													  chosen_score.cv_rms * chosen_score.cv_rms) <= chosen_score.cv_se_mse;
	std::sort(stability.alternatives.begin(), stability.alternatives.end(),
			  [](const auto& a, const auto& b) { return a.share > b.share; });
	for (const auto& [term, n] : term_count) stability.term_share.push_back({term, static_cast<double>(n) / nb});
	return stability;
}

/** Rate-free start-up model (FitOptions::startup_model): the main model's orders with every rate
 * signal left out, refitted (ridge by the same held-out error) on the same samples. Lag rates
 * stay: they need no rate window (LagFilter.h), and a log that starts on a ramp needs them. */
void addStartupModel(Calibration& cal, FoldAccumulation& acc, const ThermalFeatureSet& fs, const Choice& best,
					 const FitOptions& opt)
{
	const std::size_t ns = fs.signals().size();
	auto& total = acc.total;
	auto& folds = acc.folds;
	if (opt.startup_model)
	{
		std::vector<int> order = best.order;
		bool reads_rates = false;
		for (std::size_t s = 0; s < ns; s++)
		{
			const SignalKind kind = fs.signals()[s].kind;
			if ((kind == SignalKind::Rate || kind == SignalKind::DiffRate) && order[s] > 0)
			{
				order[s] = 0;
				reads_rates = true;
			}
		}
		if (reads_rates)
		{
			try
			{
				cal.startup = makeModel(total, fs, scoreOrders(folds, fs, order, kRidgeGrid), "", opt);
			}
			catch (const std::invalid_argument&)
			{
				// cannot be fitted on these data (too few samples for its terms): the start-up is
				// then compensated as without one (documented in Calibration::startup)
			}
		}
	}
}

}  // namespace mrpt_fog::calibration_fit
