/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/common/IntervalMask.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/BiasFit.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/ModelPreset.h>
#include <mrpt_fog/model/FitFigureStats.h>
#include <mrpt_fog/common/RowSpill.h>

#include <algorithm>
#include <functional>
#include <map>
#include <random>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
double BiasModel::evaluate(const double* values, bool clamp, int* clamped) const
{
	std::vector<double> f(features.termCount());
	const int c = features.features(values, f.data(), clamp);
	if (clamped) *clamped = c;
	double sum = 0;
	for (std::size_t i = 0; i < f.size(); i++) sum += coef_dph[i] * f[i];
	return sum;
}

double BiasModel::evaluate(const double* values, ExtrapolationPolicy policy, int* outside) const
{
	const std::size_t ns = features.signals().size();
	std::vector<double> f(features.termCount());
	const int c = features.features(values, f.data(), policy != ExtrapolationPolicy::Polynomial);
	if (outside)
	{
		int n = 0;
		for (std::size_t s = 0; s < ns; s++)
		{
			const auto& nm = features.normalisation()[s];
			n += values[s] < nm.min || values[s] > nm.max;
		}
		*outside = n;
	}
	double sum = 0;
	for (std::size_t i = 0; i < f.size(); i++) sum += coef_dph[i] * f[i];
	if (policy == ExtrapolationPolicy::Linear && c > 0)
		for (std::size_t s = 0; s < ns; s++)
		{
			const auto& nm = features.normalisation()[s];
			if (values[s] < nm.min) sum += edgeSlope(s, false) * (values[s] - nm.min);
			else if (values[s] > nm.max) sum += edgeSlope(s, true) * (values[s] - nm.max);
		}
	return sum;
}

double BiasModel::edgeSlope(std::size_t s, bool upper) const
{
	const auto& nm = features.normalisation().at(s);
	const double z = ((upper ? nm.max : nm.min) - nm.centre) / nm.scale;
	double slope = 0;
	for (std::size_t i = 0; i < features.termCount(); i++)
	{
		if (features.termSignal(i) != static_cast<int>(s)) continue;
		const int k = features.terms()[i].power;
		slope += coef_dph[i] * k * std::pow(z, k - 1);
	}
	return slope / nm.scale;
}

constexpr EnumName<ExtrapolationPolicy> kExtrapolationPolicies[] = {{ExtrapolationPolicy::Clamp, "clamp"},
																	   {ExtrapolationPolicy::Linear, "linear"},
																	   {ExtrapolationPolicy::Polynomial, "polynomial"}};

const char* toString(ExtrapolationPolicy p) { return nameIn(kExtrapolationPolicies, p, "polynomial"); }

ExtrapolationPolicy extrapolationPolicyFromString(const std::string& text)
{
	if (const auto p = valueIn(kExtrapolationPolicies, text)) return *p;
	throw std::invalid_argument("extrapolation policy '" + text + "': use clamp, linear or polynomial");
}

constexpr EnumName<TermSelection> kTermSelections[] = {{TermSelection::Auto, "auto"}, {TermSelection::None, "none"}};

const char* toString(TermSelection s) { return nameIn(kTermSelections, s, "auto"); }

TermSelection termSelectionFromString(const std::string& text)
{
	if (const auto s = valueIn(kTermSelections, text)) return *s;
	throw std::invalid_argument("selection must be 'auto' or 'none', got '" + text + "'");
}

const BiasModel* Calibration::fallbackFor(const std::string& thermistor) const
{
	for (const auto& f : fallbacks)
		if (f.dropped == thermistor) return &f;
	return nullptr;
}

namespace
{
const std::vector<double> kRidgeGrid = {0.0, 1e-9, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1};

/** One calibration run prepared for the fit: which samples are usable, the bias and the
 * thermistor rates. Memory does not grow with the log (the usable flags are intervals,
 * common/IntervalMask.h, at most one bit per sample for a log whose flags flip very often): the
 * run is read in chunks (obs/FogRun.h: in memory, or spilled to a temporary file), the bias is
 * computed from the chunk when asked (y()), and the causal rates are recomputed in each
 * sequential pass by a RowCursor (the tracker is deterministic: the same numbers as storing
 * them); only the non-causal estimator (savgol, studies) stores its rates. */
struct PreparedRun
{
	const FogRun* run = nullptr;
	std::vector<int> col;  // layout column of each feature-set thermistor
	int axis = 0;
	bool exclude_table = false;
	RateEstimatorSettings est;
	std::vector<LagChannel> lags;  // the feature set's lags (ThermalFeatureSet::lags), by thermistor index
	std::vector<HysteresisChannel> hyst;  // its hysteresis operators (ThermalFeatureSet::hystereses)
	std::vector<std::vector<double>> rate;  // [thermistor][sample] degC/s (non-causal estimator only)
	IntervalMask ok;  // usable sample (intervals: a few words for a clean run of any length)
	std::size_t usable = 0;
	/** Usable samples whose rate window covers less than half its length for some thermistor:
	 * the compensator does not trust those rates (it uses the rate-free start-up model there). */
	std::size_t short_rate_span = 0;
	/** Bias of sample j of chunk c [deg/h]: gyro minus table rate; NaN for a table sample left
	 * out of the fit. */
	double y(const FogSeries& c, std::size_t j) const
	{
		// gyro off (power 0): no gyro sample, whatever the cell holds (fog-sim's chamber writes 0 deg/h
		// there), so that the raw figures do not count it either
		if (!c.power.empty() && c.power[j] == 0.0) return std::numeric_limits<double>::quiet_NaN();
		const double table = c.table_rate_dph.empty() ? 0.0 : c.table_rate_dph[j];
		if (exclude_table && table != 0.0) return std::numeric_limits<double>::quiet_NaN();
		return c.rate_dph[axis][j] - table;
	}
};

/** Sequential access to a prepared run's per-thermistor temperatures and rates: row(c, k0, k)
 * with k ascending (gaps allowed: skipped samples still go through the rate tracker); c is the
 * chunk holding sample k (its first sample is k0), and endChunk() must be called at the end of
 * every chunk (the samples not asked for go through the tracker). */
class RowCursor
{
   public:
	explicit RowCursor(const PreparedRun& r)
		: r_(r),
		  causal_(r.est.kind == RateEstimatorKind::Causal),
		  order2_(causal_ && r.est.poly_order == 2),
		  tracker_(r.col.size(), r.est.window_s),
		  half_(r.col.size(), 0.5 * r.est.window_s),
		  lags_(r.lags),
		  hyst_(r.hyst),
		  x_(r.col.size()),
		  lag_rate_(r.lags.size()),
		  hyst_value_(r.hyst.size())
	{
	}
	/** Temperatures and rates of sample k (k >= the previous k); lagRates() and hysteresis() then
	 * hold its lag rates and hysteresis outputs. */
	void row(const FogSeries& c, std::size_t k0, std::size_t k, double* temp, double* rate)
	{
		const std::size_t nt = r_.col.size();
		pushTo(c, k0, k + 1);
		if (causal_)
		{
			// order 2 (delay-compensated): the same two trackers and formula as the compensator
			for (std::size_t i = 0; i < nt; i++)
				rate[i] = order2_ ? CausalRateTracker::extrapolatedRate(tracker_, half_, i, c.time_s[k - k0]) : tracker_.rate(i);
		}
		else
			for (std::size_t i = 0; i < nt; i++) rate[i] = r_.rate[i][k];
		for (std::size_t i = 0; i < nt; i++) temp[i] = c.temp_C[r_.col[i]][k - k0];
		for (std::size_t i = 0; i < lag_rate_.size(); i++) lag_rate_[i] = lags_.rate_C_per_s(i);
		for (std::size_t i = 0; i < hyst_value_.size(); i++) hyst_value_[i] = hyst_.value(i);
	}
	/** The lag rates of the last row() [degC/s], in PreparedRun::lags order. */
	const double* lagRates() const { return lag_rate_.data(); }
	std::size_t lagCount() const { return lag_rate_.size(); }
	/** The hysteresis outputs of the last row(), in PreparedRun::hyst order. */
	const double* hysteresis() const { return hyst_value_.data(); }
	std::size_t hysteresisCount() const { return hyst_value_.size(); }
	void endChunk(const FogSeries& c, std::size_t k0) { pushTo(c, k0, k0 + c.size()); }
	/** After row(): some thermistor's rate window covers less than half its length (the
	 * compensator's rule for using the rate-free start-up model). */
	bool shortSpan() const
	{
		if (!causal_) return false;
		for (std::size_t i = 0; i < r_.col.size(); i++)
			if (!tracker_.spanAtLeast(i, 0.5 * r_.est.window_s)) return true;
		return false;
	}

   private:
	void pushTo(const FogSeries& c, std::size_t k0, std::size_t end)
	{
		const std::size_t nt = r_.col.size();
		if (!causal_ && lags_.size() == 0 && hyst_.size() == 0)
		{
			next_ = std::max(next_, end);
			return;
		}
		for (; next_ < end; next_++)
		{
			const std::size_t j = next_ - k0;
			for (std::size_t i = 0; i < nt; i++) x_[i] = c.temp_C[r_.col[i]][j];
			if (causal_)
			{
				tracker_.push(c.time_s[j], x_.data());
				if (order2_) half_.push(c.time_s[j], x_.data());
			}
			if (lags_.size()) lags_.push(c.time_s[j], x_.data());
			if (hyst_.size()) hyst_.push(x_.data());
		}
	}
	const PreparedRun& r_;
	bool causal_, order2_;
	CausalRateTracker tracker_, half_;
	LagFilterBank lags_;
	HysteresisFilterBank hyst_;
	std::vector<double> x_, lag_rate_, hyst_value_;
	std::size_t next_ = 0;
};

/** One pass over a prepared run: f(c, k0, j) for every sample (k = k0 + j), then the cursor (if
 * any) is told the chunk ended. */
template <class F>
void forEachSample(const PreparedRun& r, RowCursor* cur, F&& f)
{
	r.run->forEachChunk([&](const FogSeries& c, std::size_t k0) {
		for (std::size_t j = 0; j < c.size(); j++) f(c, k0, j);
		if (cur) cur->endChunk(c, k0);
	});
}

PreparedRun prepare(const FogRun& s, const ThermalFeatureSet& fs, const RateEstimatorSettings& est, GyroAxis axis,
					TableSamples table, double exclusion_s)
{
	PreparedRun r;
	r.run = &s;
	const std::size_t n = s.size(), nt = fs.thermistors().size();
	for (const auto& name : fs.thermistors()) r.col.push_back(s.header().thermistorIndex(name));
	r.axis = static_cast<int>(axis);
	// A table sample is not a bias sample (nor in the raw figures) when excluded.
	r.exclude_table = table == TableSamples::Exclude;
	r.est = est;
	r.lags = fs.lags();
	r.hyst = fs.hystereses();
	if (est.kind != RateEstimatorKind::Causal)
	{
		// The centred estimator needs whole columns (studies only: memory grows with the run).
		FogSeries loaded;
		const FogSeries* whole = s.inMemory();
		if (!whole)
		{
			loaded = s.load();
			whole = &loaded;
		}
		auto e = makeRateEstimator(est);
		r.rate.resize(nt);
		for (std::size_t i = 0; i < nt; i++) r.rate[i] = e->estimate(whole->time_s, whole->temp_C[r.col[i]]);
	}
	// The same multi-channel tracker as the compensator (RowCursor): identical numbers.
	RowCursor cur(r);
	std::vector<double> temp(nt), rate(nt);
	r.ok.assign(n, true);
	// turn-ons: the samples of the first turn_on_exclusion_s after each stay out (FitOptions)
	double excluded_until_s = -std::numeric_limits<double>::infinity();
	double previous_power = 1.0;
	bool first_sample = true;
	forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
		cur.row(c, k0, k0 + j, temp.data(), rate.data());
		if (exclusion_s > 0)
		{
			if (first_sample)
			{
				const std::string meta = s.header().metadataValue("power_on_time_s");
				const double t_on = meta.empty() ? std::numeric_limits<double>::quiet_NaN() : std::strtod(meta.c_str(), nullptr);
				if (std::isfinite(t_on) && t_on <= c.time_s[j]) excluded_until_s = t_on + exclusion_s;
				first_sample = false;
			}
			const double power = c.power.empty() ? 1.0 : c.power[j];
			if (power != 0.0 && previous_power == 0.0) excluded_until_s = c.time_s[j] + exclusion_s;
			previous_power = power;
		}
		bool ok = std::isfinite(r.y(c, j)) && (c.power.empty() || c.power[j] != 0.0) && !(c.time_s[j] < excluded_until_s);
		for (std::size_t i = 0; i < nt && ok; i++) ok = std::isfinite(temp[i]) && std::isfinite(rate[i]);
		r.ok.set(k0 + j, ok);
		r.usable += ok;
		r.short_rate_span += ok && cur.shortSpan();
	});
	return r;
}

void rowSignals(RowCursor& cur, const ThermalFeatureSet& fs, const FogSeries& c, std::size_t k0, std::size_t j,
				std::vector<double>& temp, std::vector<double>& rate, std::vector<double>& values)
{
	cur.row(c, k0, k0 + j, temp.data(), rate.data());
	// the feature set's lags are those the run was prepared with (only differences leave it after)
	if (fs.lags().size() != cur.lagCount()) throw std::logic_error("fit: feature set and prepared run disagree on the lags");
	if (fs.hystereses().size() != cur.hysteresisCount())
		throw std::logic_error("fit: feature set and prepared run disagree on the hysteresis operators");
	fs.signalValues(temp.data(), rate.data(), cur.lagRates(), cur.hysteresis(), values.data());
}

/** Columns (sorted, constant first) of the terms with power <= order[signal]. */
std::vector<int> columnsOf(const ThermalFeatureSet& fs, const std::vector<int>& order)
{
	std::vector<int> cols{0};
	for (std::size_t i = 1; i < fs.termCount(); i++)
		if (fs.terms()[i].power <= order[static_cast<std::size_t>(fs.termSignal(i))]) cols.push_back(static_cast<int>(i));
	return cols;
}

/** One candidate model: the order of each signal (0 = left out), its ridge and held-out error. */
struct Choice
{
	std::vector<int> order;
	double ridge = 0;
	double cv_rms = std::numeric_limits<double>::infinity();
	double cv_se_mse = 0;  // standard error of the cross-validated mean squared error
	std::vector<double> fold_mse;  // per fold (NaN: fold empty), for paired comparisons
	std::vector<double> block_sse;  // per block of every fold (FoldSet::units), for paired comparisons
	double rows = 0;  // held-out rows scored
	std::size_t terms = 1;  // including the constant
	std::vector<std::string> pool;  // thermistors the choice was allowed to use
};

/** The validation folds and, for each, the accumulator of the other folds (its training set). */
struct FoldSet
{
	std::vector<StreamingQr> held_out, training;
	/** Optional: each fold's held-out rows cut into time blocks (StepRule::Significant). */
	std::vector<std::vector<StreamingQr>> units;
};

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

/** A regime segment [t0, t1] of a run and its class (0 cooling, 1 soak, 2 heating). */
struct RegimeSegment
{
	double t0, t1;
	int cls;
};

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

/** The fold of each usable sample of a pass, in time order: regime segment j is fold
 * j mod max_folds. */
class RegimeFoldCursor
{
   public:
	RegimeFoldCursor(const std::vector<RegimeSegment>& merged, std::size_t max_folds) : m_(merged), max_(max_folds) {}
	std::size_t fold(double t)
	{
		while (j_ + 1 < m_.size() && t > m_[j_].t1) j_++;
		return j_ % max_;
	}

   private:
	const std::vector<RegimeSegment>& m_;
	std::size_t max_;
	std::size_t j_ = 0;
};

std::string runName(const std::vector<std::string>& labels, std::size_t i)
{
	return i < labels.size() ? labels[i] : "run " + std::to_string(i + 1);
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

/** The figures of (time, raw, compensated) rows (column 0, 1, 2), read in passes. */
void statsInto(FitFigures& f, const RowSpill& rows, double tau_s)
{
	const auto column = [&](std::size_t col) -> RecordPass {
		return [&rows, col](const RecordVisitor& v) {
			rows.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
				for (std::size_t j = 0; j < n; j++) v(r[3 * j], r[3 * j + col]);
			});
		};
	};
	fitFiguresOfPasses(f, column(2), column(1), tau_s);
}

/** The calibration runs laid end to end on one time axis, a one-window (tau_s) gap between runs:
 * the (time, raw, compensated) rows statsInto() computes the figures on, in a RowSpill (memory
 * independent of the runs' length). */
struct ConcatenatedRuns
{
	RowSpill rows{3};
	double offset_s = 0, t0 = 0;
	void beginRun(const PreparedRun& r) { t0 = r.run->frontTime_s(); }
	/** A sample at time t of the run: its bias (raw) and compensated rate (NaN: none) [deg/h]. */
	void push(double t, double raw, double comp)
	{
		const double row[3] = {offset_s + t - t0, raw, comp};
		rows.push(row);
	}
	void endRun(const PreparedRun& r, double tau_s) { offset_s = offset_s + r.run->backTime_s() - t0 + tau_s; }
	void figuresInto(FitFigures& f, double tau_s) const { statsInto(f, rows, tau_s); }
};
// The stages of fitCalibrationRuns before the fold accumulation, in the order it runs them.

/** The fit's options and runs are valid (throws std::invalid_argument naming the run). */
void checkFitInputs(const std::vector<FogRun>& runs, const FitOptions& opt, const std::vector<std::string>& labels)
{
	if (runs.empty()) throw std::invalid_argument("fit: no calibration runs given");
	opt.rate_estimator.validate();
	if (!(opt.ridge >= 0)) throw std::invalid_argument("fit: ridge must be >= 0");
	if (runs.size() == 1 && opt.folds < 2) throw std::invalid_argument("fit: folds must be >= 2");
	if (opt.blocks_per_fold < 1) throw std::invalid_argument("fit: blocks_per_fold must be >= 1");
	if (!(opt.min_relative_gain >= 0 && opt.min_relative_gain < 1))
		throw std::invalid_argument("fit: min_relative_gain must be in [0, 1)");
	if (!(opt.tau_s > 0)) throw std::invalid_argument("fit: tau_s must be > 0");
	if (!(opt.turn_on_exclusion_s >= 0) || !std::isfinite(opt.turn_on_exclusion_s))
		throw std::invalid_argument("fit: turn_on_exclusion_s must be finite and >= 0 [s]");
	for (std::size_t i = 0; i < runs.size(); i++)
	{
		try
		{
			runs[i].validate();
		}
		catch (const std::exception& e)
		{
			throw std::invalid_argument(runName(labels, i) + ": " + e.what());
		}
		if (runs[i].empty()) throw std::invalid_argument(runName(labels, i) + ": no samples");
		if (i > 0 && !runs[i].header().sameLayout(runs[0].header()))
			throw std::invalid_argument(runName(labels, i) + " has another sensor layout (thermistors or axes) than " +
										runName(labels, 0));
	}
}

/** The preset's feature set, with the physics candidates when `candidates_added`: for every
 * inner thermistor of the preset, the difference to the outer one at the same angle (and its
 * rate when the preset reads rates). */
ThermalFeatureSet calibrationFeatures(const ModelPreset& preset, const FogSeries& first, bool candidates_added,
									   const std::vector<double>& lag_taus_s, std::size_t lag_max_thermistors)
{
	ThermalFeatureSet fs = presetFeatures(preset);
	const bool lags = !lag_taus_s.empty() && (preset.kind == PresetKind::Multipoint || preset.kind == PresetKind::Points) &&
					  fs.thermistors().size() <= lag_max_thermistors;
	if (!candidates_added && !lags) return fs;
	std::vector<ThermalTerm> terms(fs.terms().begin() + 1, fs.terms().end());
	if (lags)  // the lag-rate candidates of every thermistor of the preset (FitOptions::lag_taus_s)
		for (const auto& name : fs.thermistors())
			for (const double tau : lag_taus_s) terms.push_back(ThermalTerm::lagRate(name, tau, 1));
	if (!candidates_added) return ThermalFeatureSet(terms);
	for (const auto& in : first.thermistors)
	{
		if (in.side != CoilSide::Inner ||
			std::find(preset.thermistors.begin(), preset.thermistors.end(), in.name) == preset.thermistors.end())
			continue;
		for (const auto& out : first.thermistors)
			if (out.side == CoilSide::Outer && out.angle_deg == in.angle_deg &&
				std::find(preset.thermistors.begin(), preset.thermistors.end(), out.name) != preset.thermistors.end())
			{
				terms.push_back(ThermalTerm::of(SignalKind::Diff, in.name, out.name, 1));
				if (preset.rate_order > 0) terms.push_back(ThermalTerm::of(SignalKind::DiffRate, in.name, out.name, 1));
			}
	}
	return ThermalFeatureSet(terms);
}

/** The coarsest reading quantum of the feature set's thermistors over the runs [degC] (0 when
 * none is found): one sequential pass per run. */
double readingQuantum_C(const std::vector<FogRun>& runs, const ThermalFeatureSet& fs)
{
	double quantum_C = 0;
	const auto& names = fs.thermistors();
	std::vector<double> q(names.size(), std::numeric_limits<double>::infinity());
	for (const auto& r : runs)  // one sequential pass per run
	{
		std::vector<ReadingQuantum> acc(names.size());
		std::vector<std::size_t> col;
		for (const auto& name : names) col.push_back(static_cast<std::size_t>(r.header().thermistorIndex(name)));
		r.forEachChunk([&](const FogSeries& chunk, std::size_t) {
			for (std::size_t i = 0; i < names.size(); i++)
				for (const double v : chunk.temp_C[col[i]]) acc[i].add(v);
		});
		for (std::size_t i = 0; i < names.size(); i++) q[i] = std::min(q[i], acc[i].quantum_C());
	}
	for (const double qi : q)
		if (std::isfinite(qi)) quantum_C = std::max(quantum_C, qi);
	return quantum_C;
}

/** Every run prepared for the fit; `usable` = their usable samples. */
std::vector<PreparedRun> prepareRuns(const std::vector<FogRun>& runs, const ThermalFeatureSet& fs, const FitOptions& opt,
									 GyroAxis axis, std::size_t& usable)
{
	std::vector<PreparedRun> prep;
	usable = 0;
	for (const auto& r : runs)
	{
		prep.push_back(prepare(r, fs, opt.rate_estimator, axis, opt.table_samples, opt.turn_on_exclusion_s));
		usable += prep.back().usable;
	}
	return prep;
}

/** Burst logs (e.g. 5 s bursts every 5 min): within a burst the rate window never covers half
 * its length, so the compensator could never use a model that reads rates (it would run the
 * rate-free start-up model on every sample). When that holds for most usable samples, the
 * rates are not estimable from this log: the rate signals leave the feature set and the runs
 * are prepared again. Returns whether they did. */
bool leaveOutRatesOfBurstLogs(const std::vector<FogRun>& runs, const FitOptions& opt, GyroAxis axis,
							  ThermalFeatureSet& fs, std::vector<PreparedRun>& prep, std::size_t& usable)
{
	std::size_t short_span = 0;
	for (const auto& r : prep) short_span += r.short_rate_span;
	if (!(2 * short_span > usable)) return false;
	std::vector<bool> keep(fs.signals().size());
	bool any_rate = false;
	for (std::size_t s = 0; s < keep.size(); s++)
	{
		keep[s] = !fs.signals()[s].isRate();
		any_rate |= !keep[s];
	}
	if (!any_rate) return false;
	fs = fs.selectSignals(keep);
	prep = prepareRuns(runs, fs, opt, axis, usable);  // the thermistors may have changed (one read only through its rate)
	return true;
}

/** Each signal's range over the usable samples, and the mean bias (the y reference). */
struct SignalRanges
{
	std::vector<double> lo, hi;
	double y_ref = 0;
};

SignalRanges signalRanges(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, std::size_t usable)
{
	const std::size_t ns = fs.signals().size(), nt = fs.thermistors().size();
	SignalRanges g;
	g.lo.assign(ns, std::numeric_limits<double>::infinity());
	g.hi.assign(ns, -std::numeric_limits<double>::infinity());
	std::vector<double> temp(nt), rate(nt), values(ns);
	double ysum = 0;
	for (const auto& r : prep)
	{
		RowCursor cur(r);
		forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
			if (!r.ok[k0 + j]) return;
			rowSignals(cur, fs, c, k0, j, temp, rate, values);
			for (std::size_t s = 0; s < ns; s++)
			{
				g.lo[s] = std::min(g.lo[s], values[s]);
				g.hi[s] = std::max(g.hi[s], values[s]);
			}
			ysum += r.y(c, j);
		});
	}
	g.y_ref = ysum / static_cast<double>(usable);
	return g;
}

/** A physics candidate without variation (e.g. two identical readings) leaves the feature set. */
void leaveOutConstantDifferences(ThermalFeatureSet& fs, SignalRanges& g)
{
	const std::size_t ns = fs.signals().size();
	std::vector<bool> keep(ns, true);
	bool any = false;
	for (std::size_t s = 0; s < ns; s++)
		if (fs.signals()[s].isDifference() && !(g.hi[s] - g.lo[s] > 1e-9 * (1 + std::abs(g.hi[s]))))
		{
			keep[s] = false;
			any = true;
		}
	if (!any) return;
	fs = fs.selectSignals(keep);
	std::vector<double> lo2, hi2;
	for (std::size_t s = 0; s < ns; s++)
		if (keep[s])
		{
			lo2.push_back(g.lo[s]);
			hi2.push_back(g.hi[s]);
		}
	g.lo = lo2;
	g.hi = hi2;
}

/** Each signal's normalisation from its range: a temperature to [-1, 1] about its centre, a rate
 * or difference scaled by its largest magnitude. Throws when a temperature spans too little for
 * its polynomial order or a signal is constant. */
void setNormalisation(ThermalFeatureSet& fs, const SignalRanges& g, const FitOptions& opt)
{
	const std::size_t ns = fs.signals().size();
	const auto& lo = g.lo;
	const auto& hi = g.hi;
	for (std::size_t s = 0; s < ns; s++)
	{
		const auto& sig = fs.signals()[s];
		int order = 0;
		for (std::size_t i = 0; i < fs.termCount(); i++)
			if (fs.termSignal(i) == static_cast<int>(s)) order = std::max(order, fs.terms()[i].power);
		const double span = hi[s] - lo[s];
		std::ostringstream why;
		if (sig.kind == SignalKind::Temp && span < order * opt.min_temp_span_per_order_C)
		{
			why << sig.name() << " spans only " << span << " degC in the calibration data; an order-" << order
				<< " polynomial needs at least " << order * opt.min_temp_span_per_order_C << " degC ("
				<< opt.min_temp_span_per_order_C << " degC per order): calibrate over a wider range or lower the order";
			throw std::invalid_argument(why.str());
		}
		if (!(span > 0))
			throw std::invalid_argument(sig.name() + " is constant in the calibration data: it cannot be fitted");
		auto& nm = fs.normalisation()[s];
		nm.min = lo[s];
		nm.max = hi[s];
		if (sig.kind == SignalKind::Temp)
		{
			nm.centre = 0.5 * (lo[s] + hi[s]);
			nm.scale = 0.5 * span;
		}
		else if (sig.isHysteresis())  // bounded by construction: its own range, never clamped
		{
			nm.centre = 0.0;
			nm.scale = 1.0;
			nm.min = -1.0;
			nm.max = 1.0;
		}
		else
		{
			nm.centre = 0.0;
			nm.scale = std::max(std::abs(lo[s]), std::abs(hi[s]));
		}
	}
}

/** The mean of each feature over the usable samples (the accumulation reference of the QR
 * factors: their sums then hold centred features). */
std::vector<double> featureMeans(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, std::size_t usable)
{
	const std::size_t nt = fs.thermistors().size();
	std::vector<double> temp(nt), rate(nt), values(fs.signals().size()), f(fs.termCount());
	std::vector<double> fsum(fs.termCount(), 0.0);
	for (const auto& r : prep)
	{
		RowCursor cur(r);
		forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
			if (!r.ok[k0 + j]) return;
			rowSignals(cur, fs, c, k0, j, temp, rate, values);
			fs.features(values.data(), f.data(), false);
			for (std::size_t q = 0; q < f.size(); q++) fsum[q] += f[q];
		});
	}
	std::vector<double> x_ref(fs.termCount());
	for (std::size_t j = 0; j < x_ref.size(); j++) x_ref[j] = fsum[j] / static_cast<double>(usable);
	return x_ref;
}

/** The in-sample figures (cal.in_sample): the calibration runs through the real-time compensator
 * (only when the model can run in real time: the causal rate estimator), else through the fitted
 * feature set directly. The (time, raw, compensated) rows go to a RowSpill (memory independent of
 * the runs' length). */
void addInSampleFigures(Calibration& cal, const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs,
						const FitOptions& opt)
{
	constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
	const std::size_t ns = fs.signals().size(), nt = fs.thermistors().size();
	std::vector<double> temp(nt), rate(nt), values(ns);
	ConcatenatedRuns all;
	for (std::size_t ri = 0; ri < prep.size(); ri++)
	{
		const auto& r = prep[ri];
		all.beginRun(r);
		const auto put = [&](const FogSeries& c, std::size_t k0, std::size_t j, double bias) {
			const double y = r.y(c, j);
			all.push(c.time_s[j], y, r.ok[k0 + j] ? y - bias : kNaN);
		};
		if (opt.rate_estimator.kind == RateEstimatorKind::Causal)
			compensateRun(cal, *r.run,
						  [&](const FogSeries& c, std::size_t k0, std::size_t j0, std::size_t m,
							  const Compensator::Output* out) {
							  for (std::size_t j = 0; j < m; j++) put(c, k0, j0 + j, out[j].bias_dph);
						  });
		else
		{
			RowCursor cur(r);
			std::vector<double> mv(cal.model.features.signals().size());
			forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
				double bias = kNaN;
				if (r.ok[k0 + j])
				{
					rowSignals(cur, fs, c, k0, j, temp, rate, values);
					for (std::size_t s = 0; s < mv.size(); s++)
						for (std::size_t q = 0; q < ns; q++)
							if (fs.signals()[q] == cal.model.features.signals()[s]) mv[s] = values[q];
					bias = cal.model.evaluate(mv.data(), cal.extrapolation);
				}
				put(c, k0, j, bias);
			});
		}
		all.endRun(r, opt.tau_s);
	}
	cal.in_sample.label = "in-sample";
	all.figuresInto(cal.in_sample, opt.tau_s);
}

/** How the calibration samples are split into folds: one per run when several runs are given
 * (or each run's regimes, FitOptions::run_folds), else whole thermal regimes of the run
 * (FoldScheme::Regimes) or interleaved time blocks. */
struct FoldPlan
{
	bool by_run = false, run_regimes = false, by_regime = false;
	/** regimes_of[r]: run r's regime segments (one run: the run's, Regimes scheme; several runs:
	 * RunFolds::RegimesWithinRuns); a run with fewer than 3 is not cut (blocks / one fold). */
	std::vector<std::vector<RegimeSegment>> regimes_of;
	std::size_t regime_segments = 0;
	/** The first fold of each run (several runs): one fold per run, or per regime fold of each run. */
	std::vector<std::size_t> run_fold0;
	std::size_t nfolds = 0;
	double front_s = 0, back_s = 0;  //!< the first run's time span (interleaved blocks)
	std::size_t blocks_per_fold = 1;

	/** The fold of a usable sample at time t of run `run` (passes in time order: the regime cursor). */
	std::size_t foldOf(std::size_t run, double t, RegimeFoldCursor& regime) const
	{
		if (by_run) return run_fold0[run] + (regimes_of[run].empty() || !run_regimes ? 0 : regime.fold(t));
		if (by_regime) return regime.fold(t);
		const double u = (t - front_s) / (back_s - front_s + 1e-300);
		const std::size_t nblocks = nfolds * blocks_per_fold;
		return std::min(nblocks - 1, static_cast<std::size_t>(u * static_cast<double>(nblocks))) % nfolds;
	}
	/** The label of the held-out figures. */
	std::string heldOutLabel(std::size_t runs) const
	{
		return run_regimes ? "held-out (leave-regime-out within " + std::to_string(runs) + " runs, " +
								 std::to_string(nfolds) + " folds)"
			   : by_run    ? "held-out (leave-one-run-out, " + std::to_string(nfolds) + " runs)"
			   : by_regime ? "held-out (leave-regime-out, " + std::to_string(regime_segments) + " regimes in " +
								 std::to_string(nfolds) + " folds)"
						   : "held-out (blocked " + std::to_string(nfolds) + "-fold)";
	}
};

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

/** Pass 2: what the folds accumulate. */
struct FoldAccumulation
{
	FoldSet folds;  //!< every sample, per fold (the fit and its held-out figures)
	FoldSet sel;  //!< what the selection judges (time-bin means, FitOptions::selection_bin_s)
	StreamingQr total;  //!< every fold merged
	/** Resampling units for the stability of the choice: (fold, run block) -> rows. */
	std::map<std::pair<std::size_t, std::size_t>, StreamingQr> units;
};

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

/** The choice of terms (FitOptions::selection): the main model among the preset's thermistor
 * pools (nested over thermistor subsets when automatic), and a fallback model per thermistor. */
class TermSearch
{
public:
	TermSearch(const ThermalFeatureSet& fs, const ModelPreset& preset, const FitOptions& opt)
		: fs_(fs), preset_(preset), opt_(opt), ns_(fs.signals().size()), max_order_(fs.signalOrders()),
		  automatic_(opt.selection == TermSelection::Auto), names_(fs.thermistors()),
		  nested_(automatic_ && (preset.kind == PresetKind::Points || (preset.kind == PresetKind::Multipoint && !opt.linear_base)))
	{
	}

	struct Result
	{
		Choice best;
		std::vector<Choice> fallback_choices;  //!< the best choice without each thermistor of best
	};

	/** The main model (and, with FitOptions::fallbacks, the fallbacks) judged on `sel`; `folds`
	 * where every sample counts (selection none, a fallback without any thermistor). */
	Result select(FoldSet& sel, FoldSet& folds) const
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

	/** The main-model selection alone on other folds (the stability resamples). */
	Choice selectMain(FoldSet& fset, const Choice& best) const
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

private:
	std::vector<bool> allowedFor(const std::vector<std::string>& pool, const std::string& dropped) const
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
	std::vector<Choice> forward(FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) const
	{
		return selectForward(fset, fs_, allowedFor(pool, dropped), max_order_, opt_);
	}
	Choice choose(FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) const
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

	const ThermalFeatureSet& fs_;
	const ModelPreset& preset_;
	const FitOptions& opt_;
	std::size_t ns_;
	std::vector<int> max_order_;
	bool automatic_;
	const std::vector<std::string>& names_;  // the subsets of thermistors are masks over these
	bool nested_;
};

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

/** Gaps between consecutive samples longer than the rate window, over every run. */
std::size_t rateGapCount(const std::vector<FogRun>& runs, double window_s)
{
	std::size_t rate_gaps = 0;
	for (const auto& r : runs)
	{
		bool first_sample = true;
		double prev_t = 0;
		r.forEachChunk([&](const FogSeries& c, std::size_t) {
			for (double t : c.time_s)
			{
				if (!first_sample) rate_gaps += t - prev_t > window_s;
				first_sample = false;
				prev_t = t;
			}
		});
	}
	return rate_gaps;
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

/** Held-out figures: every fold predicted by the chosen model fitted on the other folds. */
void addHeldOutFigures(Calibration& cal, const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs,
					   FoldAccumulation& acc, const FoldPlan& plan, const Choice& best, std::size_t runs, const FitOptions& opt)
{
	constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
	const std::size_t nfolds = plan.nfolds;
	const std::size_t ns = fs.signals().size();
	const std::size_t nt = fs.thermistors().size();
	std::vector<double> temp(nt), rate(nt), values(ns), f(fs.termCount());  // one row
	auto& folds = acc.folds;
	// Held-out figures: every fold predicted by the chosen model fitted on the other folds.
	{
		const auto cols = columnsOf(fs, best.order);
		std::vector<Eigen::VectorXd> coef(nfolds);
		std::vector<bool> has(nfolds, false);
		for (std::size_t fo = 0; fo < nfolds; fo++)
		{
			auto& train = folds.training[fo];
			if (train.count() < cols.size()) continue;
			coef[fo] = solveBiasFit(train, cols, best.ridge).coef_dph;
			has[fo] = true;
		}
		ConcatenatedRuns all;
		for (std::size_t ri = 0; ri < prep.size(); ri++)
		{
			const auto& r = prep[ri];
			all.beginRun(r);
			RowCursor cur(r);
			RegimeFoldCursor regime(plan.regimes_of[ri], opt.max_regime_folds);
			forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
				double comp = kNaN;
				if (r.ok[k0 + j])
				{
					const std::size_t fo = plan.foldOf(ri, c.time_s[j], regime);
					if (has[fo])
					{
						rowSignals(cur, fs, c, k0, j, temp, rate, values);
						fs.features(values.data(), f.data(), false);
						double pred = 0;
						for (std::size_t q = 0; q < cols.size(); q++) pred += coef[fo][static_cast<Eigen::Index>(q)] * f[cols[q]];
						comp = r.y(c, j) - pred;
					}
				}
				all.push(c.time_s[j], r.y(c, j), comp);
			});
			all.endRun(r, opt.tau_s);
		}
		cal.held_out.label = plan.heldOutLabel(runs);
		all.figuresInto(cal.held_out, opt.tau_s);
	}
}

}  // namespace

Calibration fitCalibration(const std::vector<FogSeries>& series, const std::string& preset_text, const FitOptions& opt,
						   const std::vector<std::string>& labels)
{
	std::vector<FogRun> runs;
	for (const auto& s : series) runs.emplace_back(s);
	return fitCalibrationRuns(runs, preset_text, opt, labels);
}

Calibration fitCalibrationRuns(const std::vector<FogRun>& runs, const std::string& preset_text, const FitOptions& opt_in,
						   const std::vector<std::string>& labels)
{
	FitOptions opt = opt_in;  // the rate window may follow the thermistors' quantum (below)
	checkFitInputs(runs, opt, labels);
	const FogSeries& first = runs[0].header();
	const GyroAxis axis = opt.axis ? *opt.axis : first.primaryAxis();
	if (!first.has_axis[static_cast<int>(axis)])
		throw std::invalid_argument(runName(labels, 0) + " has no " + axisLetter(axis) + " axis to calibrate");
	const ModelPreset preset = parseModelPreset(preset_text, first.thermistors);
	// Common orders are defined for the thermistor presets (multipoint, points:K); M1..M4 and
	// term lists (differences among their own signals) keep the per-signal search.
	if (!(preset.kind == PresetKind::Multipoint || preset.kind == PresetKind::Points))
		opt.order_search = OrderSearch::PerSignal;
	const bool candidates_added =
		opt.selection == TermSelection::Auto && opt.physics_candidates && (preset.kind == PresetKind::Multipoint || preset.kind == PresetKind::Points);
	for (const double tau : opt.lag_taus_s)
		if (!(std::isfinite(tau) && tau > 0 && tau <= 1e7))
			throw std::invalid_argument("fit: lag time constant " + std::to_string(tau) + " s must be in (0, 1e7]");
	// lag candidates, like the physics candidates, only for selection auto: none is every preset term
	ThermalFeatureSet fs = calibrationFeatures(preset, first, candidates_added,
											   opt.selection == TermSelection::Auto ? opt.lag_taus_s : std::vector<double>{},
											   opt.lag_max_thermistors);

	// Rate window for the thermistors' reading quantum (FitOptions::window_for_quantum).
	const double quantum_C = readingQuantum_C(runs, fs);
	if (opt.window_for_quantum) opt.rate_estimator.window_s = windowForQuantum_s(opt.rate_estimator.window_s, quantum_C);

	std::size_t usable = 0;
	std::vector<PreparedRun> prep = prepareRuns(runs, fs, opt, axis, usable);
	if (usable == 0) throw std::invalid_argument("fit: no usable sample (every sample has a dropout or no rate yet)");
	const bool rates_unavailable = leaveOutRatesOfBurstLogs(runs, opt, axis, fs, prep, usable);

	// Pass 1: signal ranges -> normalisation; mean bias as y reference.
	SignalRanges ranges = signalRanges(prep, fs, usable);
	const double y_ref = ranges.y_ref;
	if (candidates_added) leaveOutConstantDifferences(fs, ranges);
	setNormalisation(fs, ranges, opt);
	// Feature means (the accumulation reference: the sums then hold centred features).
	const std::vector<double> x_ref = featureMeans(prep, fs, usable);

	// Pass 2: the folds (FoldPlan) and what they accumulate.
	const FoldPlan plan = planFolds(runs, prep, opt);
	FoldAccumulation acc = accumulateFolds(prep, fs, plan, opt, y_ref, x_ref);
	StreamingQr& total = acc.total;

	// The terms, the fallbacks and how stable the choice is.
	const TermSearch terms(fs, preset, opt);
	const TermSearch::Result chosen = terms.select(acc.sel, acc.folds);
	const Choice& best = chosen.best;
	const std::vector<Choice>& fallback_choices = chosen.fallback_choices;
	const SelectionStability stability = selectionStability(terms, acc, best, fs, plan, opt, y_ref, x_ref);

	Calibration cal;
	cal.selection_stability = stability;
	cal.rates_unavailable = rates_unavailable;
	cal.rate_gaps = rateGapCount(runs, opt.rate_estimator.window_s);
	cal.sensor_label = first.sensor_label;
	cal.axis = axis;
	cal.layout = first.thermistors;
	{
		std::vector<FogSeries> headers;
		for (const auto& r : runs) headers.push_back(r.header());
		cal.latitude_deg = commonLatitude_deg(headers);
	}
	cal.preset = preset_text;
	cal.selection = opt.selection;
	cal.rate_estimator = opt.rate_estimator;
	cal.reading_quantum_C = quantum_C;
	cal.extrapolation = opt.extrapolation;
	cal.mean_bias_dph = y_ref;
	for (std::size_t i = 0; i < runs.size(); i++) cal.runs.push_back(runName(labels, i));
	cal.model = makeModel(total, fs, best, "", opt);
	if (opt.fallbacks)
	{
		const auto& used = cal.model.features.thermistors();
		for (std::size_t i = 0; i < used.size() && i < fallback_choices.size(); i++)
			cal.fallbacks.push_back(makeModel(total, fs, fallback_choices[i], used[i], opt));
	}

	addStartupModel(cal, acc, fs, best, opt);

	// In-sample figures, then held-out ones.
	addInSampleFigures(cal, prep, fs, opt);
	addHeldOutFigures(cal, prep, fs, acc, plan, best, runs.size(), opt);
	return cal;
}

FitFigures evaluateCalibration(const Calibration& cal, const FogSeries& series, const std::string& label, double tau_s)
{
	return evaluateCalibration(cal, FogRun(series), label, tau_s);
}

FitFigures evaluateCalibration(const Calibration& cal, const FogRun& run, const std::string& label, double tau_s)
{
	// (time, raw, compensated) rows in a RowSpill (memory independent of the run's length).
	const int axis = static_cast<int>(cal.axis);
	RowSpill rows(3);
	const CompensationCounters counters = compensateRun(
		cal, run, [&](const FogSeries& c, std::size_t, std::size_t j0, std::size_t m, const Compensator::Output* out) {
			for (std::size_t j = j0; j < j0 + m; j++)
			{
				const bool on = c.power.empty() || c.power[j] != 0.0;  // off: no gyro sample, raw or compensated
				double raw = on ? c.rate_dph[axis][j] : std::numeric_limits<double>::quiet_NaN();
				if (!c.table_rate_dph.empty()) raw -= c.table_rate_dph[j];
				const double comp = on ? raw - out[j - j0].bias_dph : std::numeric_limits<double>::quiet_NaN();
				const double row[3] = {c.time_s[j], raw, comp};
				rows.push(row);
			}
		});
	FitFigures f;
	f.label = label;
	statsInto(f, rows, tau_s);
	f.temp_outside_samples = counters.temp_outside_samples;
	f.rate_outside_samples = counters.rate_outside_samples;
	f.max_temp_excursion_C = counters.max_temp_excursion_C;
	f.max_rate_excursion_C_per_s = counters.max_rate_excursion_C_per_s;
	return f;
}

}  // namespace mrpt_fog
