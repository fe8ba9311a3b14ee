/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CalibrationFitStages.h
 * The stages of fitCalibrationRuns() (Calibration.h), shared by the files that hold them:
 * run preparation (CalibrationRunPreparation.cpp), folds (CalibrationFolds.cpp), term selection
 * (CalibrationTermSelection.cpp) and figures (CalibrationFigures.cpp). Internal: not installed.
 */

#include <mrpt_fog/common/IntervalMask.h>
#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/model/BiasFit.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/ModelPreset.h>

#include <cstddef>
#include <limits>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog::calibration_fit
{
/** The ridges tried for every candidate (relative to the unit diagonal). */
inline const std::vector<double> kRidgeGrid = {0.0, 1e-9, 1e-7, 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 1e-1};

// ---- run preparation (CalibrationRunPreparation.cpp)

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
					TableSamples table, double exclusion_s);
/** The signal values of sample k0 + j (the cursor advanced to it). */
void rowSignals(RowCursor& cur, const ThermalFeatureSet& fs, const FogSeries& c, std::size_t k0, std::size_t j,
				std::vector<double>& temp, std::vector<double>& rate, std::vector<double>& values);
std::string runName(const std::vector<std::string>& labels, std::size_t i);
/** The fit's options and runs are valid (throws std::invalid_argument naming the run). */
void checkFitInputs(const std::vector<FogRun>& runs, const FitOptions& opt, const std::vector<std::string>& labels);
/** The preset's feature set, with the physics candidates when `candidates_added` and the lag
 * candidates of lag_taus_s. */
ThermalFeatureSet calibrationFeatures(const ModelPreset& preset, const FogSeries& first, bool candidates_added,
									   const std::vector<double>& lag_taus_s, std::size_t lag_max_thermistors);
/** The coarsest reading quantum of the feature set's thermistors over the runs [degC]. */
double readingQuantum_C(const std::vector<FogRun>& runs, const ThermalFeatureSet& fs);
/** Every run prepared for the fit; `usable` = their usable samples. */
std::vector<PreparedRun> prepareRuns(const std::vector<FogRun>& runs, const ThermalFeatureSet& fs, const FitOptions& opt,
									 GyroAxis axis, std::size_t& usable);
/** Burst logs: the rate signals leave the feature set when most samples have a short rate span. */
bool leaveOutRatesOfBurstLogs(const std::vector<FogRun>& runs, const FitOptions& opt, GyroAxis axis,
							  ThermalFeatureSet& fs, std::vector<PreparedRun>& prep, std::size_t& usable);
/** Each signal's range over the usable samples, and the mean bias (the y reference). */
struct SignalRanges
{
	std::vector<double> lo, hi;
	double y_ref = 0;
};
SignalRanges signalRanges(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, std::size_t usable);
/** A physics candidate without variation (e.g. two identical readings) leaves the feature set. */
void leaveOutConstantDifferences(ThermalFeatureSet& fs, SignalRanges& g);
/** Each signal's normalisation from its range (throws when a signal spans too little). */
void setNormalisation(ThermalFeatureSet& fs, const SignalRanges& g, const FitOptions& opt);
/** The mean of each feature over the usable samples. */
std::vector<double> featureMeans(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, std::size_t usable);
/** Gaps between consecutive samples longer than the rate window, over every run. */
std::size_t rateGapCount(const std::vector<FogRun>& runs, double window_s);

// ---- folds (CalibrationFolds.cpp)

/** A regime segment [t0, t1] of a run and its class (0 cooling, 1 soak, 2 heating). */
struct RegimeSegment
{
	double t0, t1;
	int cls;
};

std::vector<RegimeSegment> regimeSegments(const PreparedRun& r, double threshold_C_per_min, double min_regime_s,
										  double window_s);

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

FoldPlan planFolds(const std::vector<FogRun>& runs, const std::vector<PreparedRun>& prep, const FitOptions& opt);

// ---- term selection (CalibrationTermSelection.cpp)

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

/** Pass 2: what the folds accumulate. */
struct FoldAccumulation
{
	FoldSet folds;  //!< every sample, per fold (the fit and its held-out figures)
	FoldSet sel;  //!< what the selection judges (time-bin means, FitOptions::selection_bin_s)
	StreamingQr total;  //!< every fold merged
	/** Resampling units for the stability of the choice: (fold, run block) -> rows. */
	std::map<std::pair<std::size_t, std::size_t>, StreamingQr> units;
};

/** Pass 2: a streaming QR factor per fold, the selection's time-bin means and the resampling units. */
FoldAccumulation accumulateFolds(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, const FoldPlan& plan,
								 const FitOptions& opt, double y_ref, const std::vector<double>& x_ref);

/** Columns (sorted, constant first) of the terms with power <= order[signal]. */
std::vector<int> columnsOf(const ThermalFeatureSet& fs, const std::vector<int>& order);
/** Best ridge for an order vector, with its CV RMS. */
Choice scoreOrders(FoldSet& folds, const ThermalFeatureSet& fs, const std::vector<int>& order,
				   const std::vector<double>& ridges);

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
	Result select(FoldSet& sel, FoldSet& folds) const;
	/** The main-model selection alone on other folds (the stability resamples). */
	Choice selectMain(FoldSet& fset, const Choice& best) const;

private:
	std::vector<bool> allowedFor(const std::vector<std::string>& pool, const std::string& dropped) const;
	std::vector<Choice> forward(FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) const;
	Choice choose(FoldSet& fset, const std::vector<std::string>& pool, const std::string& dropped) const;

	const ThermalFeatureSet& fs_;
	const ModelPreset& preset_;
	const FitOptions& opt_;
	std::size_t ns_;
	std::vector<int> max_order_;
	bool automatic_;
	const std::vector<std::string>& names_;  // the subsets of thermistors are masks over these
	bool nested_;
};

/** Stability of the choice (wild block-bootstrap resamples). */
SelectionStability selectionStability(const TermSearch& terms, FoldAccumulation& acc, const Choice& best,
									  const ThermalFeatureSet& fs, const FoldPlan& plan, const FitOptions& opt, double y_ref,
									  const std::vector<double>& x_ref);
/** The bias model of a choice fitted on every fold (throws when too few samples or rank deficient). */
BiasModel makeModel(StreamingQr& total, const ThermalFeatureSet& fs, const Choice& c, const std::string& dropped,
					const FitOptions& opt);
/** Rate-free start-up model (FitOptions::startup_model). */
void addStartupModel(Calibration& cal, FoldAccumulation& acc, const ThermalFeatureSet& fs, const Choice& best,
					 const FitOptions& opt);

// ---- figures (CalibrationFigures.cpp)

/** The figures of (time, raw, compensated) rows (column 0, 1, 2), read in passes. */
void statsInto(FitFigures& f, const RowSpill& rows, double tau_s);
/** The in-sample figures (cal.in_sample). */
void addInSampleFigures(Calibration& cal, const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs,
						const FitOptions& opt);
/** Held-out figures: every fold predicted by the chosen model fitted on the other folds. */
void addHeldOutFigures(Calibration& cal, const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs,
					   FoldAccumulation& acc, const FoldPlan& plan, const Choice& best, std::size_t runs, const FitOptions& opt);

}  // namespace mrpt_fog::calibration_fit
