/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The fit's figures: in-sample, held-out, and a calibration evaluated on a run. */
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
}  // namespace

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

}  // namespace mrpt_fog::calibration_fit

namespace mrpt_fog
{
using calibration_fit::statsInto;

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
