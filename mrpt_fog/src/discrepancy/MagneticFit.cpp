/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/MagneticFit.h>
#include <mrpt_fog/discrepancy/DiscrepancyOptions.h>
#include <mrpt_fog/discrepancy/WhitenedRegression.h>
#include <mrpt_fog/model/Compensator.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrpt_fog::discrepancy
{
namespace
{
/** A sample the fit uses: gyro on, no table rate, a finite field and compensated rate. */
bool usable(const FogSeries& run, std::size_t k, double compensated_dph)
{
	const bool on = run.power.empty() || run.power[k] != 0.0;
	const bool table = !run.table_rate_dph.empty() && run.table_rate_dph[k] != 0.0;
	return on && !table && std::isfinite(run.field_uT[k]) && std::isfinite(compensated_dph);
}
}  // namespace

bool hasFieldVariation(const std::vector<FogSeries>& runs)
{
	for (const auto& run : runs)
	{
		if (run.field_uT.size() != run.size()) continue;
		double first = NAN;
		for (std::size_t k = 0; k < run.size(); k++)
		{
			const double f = run.field_uT[k];
			if (!std::isfinite(f) || !(run.power.empty() || run.power[k] != 0.0)) continue;
			if (std::isnan(first)) first = f;
			else if (f != first) return true;
		}
	}
	return false;
}

MagneticModel fitMagneticSensitivity(const Calibration& cal_in, const std::vector<FogSeries>& runs)
{
	Calibration cal = cal_in;
	cal.magnetic.reset();
	// the samples used, run by run: global index, run, compensated rate
	struct Sample
	{
		std::size_t run, k;
		double y;
	};
	std::vector<Sample> used;
	std::size_t with_field = 0;
	double lo = std::numeric_limits<double>::infinity(), hi = -lo;
	for (std::size_t r = 0; r < runs.size(); r++)
	{
		const FogSeries& run = runs[r];
		if (run.field_uT.size() != run.size()) continue;
		with_field++;
		const CompensatedSeries comp = compensate(cal, run);
		for (std::size_t k = 0; k < run.size(); k++)
			if (usable(run, k, comp.compensated_dph[k]))
			{
				used.push_back({r, k, comp.compensated_dph[k]});
				lo = std::min(lo, run.field_uT[k]);
				hi = std::max(hi, run.field_uT[k]);
			}
	}
	if (with_field == 0)
		throw MagneticFitError(runs.size() == 1 ? "the run has no field column" : "no run has a field column");
	if (used.size() < 10 || !(hi > lo))
		throw MagneticFitError("the applied field does not vary over the powered samples (not separable from the bias)");
	const auto field = [&](const Sample& s) { return runs[s.run].field_uT[s.k]; };
	const auto time = [&](const Sample& s) { return runs[s.run].time_s[s.k]; };
	// the shortest stretch of constant field [s], the spacing of the drift's knots: of the stretches
	// between two changes of the field within a run, else (a run with one change) of those with
	// one change at an end
	double shortest_s = std::numeric_limits<double>::infinity(), shortest_edge_s = shortest_s;
	for (std::size_t i = 1, start = 0; i <= used.size(); i++)
	{
		const bool run_ends = i == used.size() || used[i].run != used[i - 1].run;
		if (!run_ends && field(used[i]) == field(used[i - 1])) continue;
		const bool opened_by_change = start > 0 && used[start - 1].run == used[start].run;
		const double len_s = time(used[i - 1]) - time(used[start]);
		if (opened_by_change && !run_ends) shortest_s = std::min(shortest_s, len_s);
		else if (opened_by_change || !run_ends) shortest_edge_s = std::min(shortest_edge_s, len_s);
		start = i;
	}
	if (!std::isfinite(shortest_s)) shortest_s = shortest_edge_s;
	// per run: first time, knot count (0 = one level)
	std::vector<double> t_first(runs.size(), NAN), t_last(runs.size(), NAN);
	for (const auto& s : used)
	{
		if (std::isnan(t_first[s.run])) t_first[s.run] = time(s);
		t_last[s.run] = time(s);
	}
	std::vector<std::size_t> knots(runs.size(), 0), first_col(runs.size(), 0);
	std::size_t total = 0;
	const bool drift = shortest_s > 0 && std::isfinite(shortest_s);
	for (std::size_t r = 0; r < runs.size(); r++)
		if (!std::isnan(t_first[r]))
			total += drift ? static_cast<std::size_t>(std::ceil((t_last[r] - t_first[r]) / shortest_s)) + 1 : 1;
	const bool hats = drift && total <= kMaxMagneticDriftKnots;
	Eigen::Index p = 1;  // column 0: the field
	for (std::size_t r = 0; r < runs.size(); r++)
	{
		if (std::isnan(t_first[r])) continue;
		knots[r] = hats ? static_cast<std::size_t>(std::ceil((t_last[r] - t_first[r]) / shortest_s)) + 1 : 1;
		knots[r] = std::max<std::size_t>(knots[r], hats ? 2 : 1);
		first_col[r] = static_cast<std::size_t>(p);
		p += static_cast<Eigen::Index>(knots[r]);
	}
	// rows: every sample of the runs with a field column, the unused ones marked not ok
	std::vector<std::size_t> offset(runs.size() + 1, 0);
	for (std::size_t r = 0; r < runs.size(); r++)
		offset[r + 1] = offset[r] + (runs[r].field_uT.size() == runs[r].size() ? runs[r].size() : 0);
	const std::size_t n = offset.back();
	std::vector<int> block(n, 0);
	std::vector<unsigned char> ok(n, 0);
	for (std::size_t r = 0; r < runs.size(); r++)
		std::fill(block.begin() + static_cast<std::ptrdiff_t>(offset[r]), block.begin() + static_cast<std::ptrdiff_t>(offset[r + 1]),
				  static_cast<int>(r));
	Eigen::MatrixXd X = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), p);
	Eigen::VectorXd y = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(n));
	for (const auto& s : used)
	{
		const std::size_t g = offset[s.run] + s.k;
		const auto i = static_cast<Eigen::Index>(g);
		ok[g] = 1;
		X(i, 0) = field(s);
		y(i) = s.y;
		const auto c0 = static_cast<Eigen::Index>(first_col[s.run]);
		if (knots[s.run] == 1)
		{
			X(i, c0) = 1.0;
			continue;
		}
		const std::size_t K = knots[s.run];
		const double u = std::clamp((time(s) - t_first[s.run]) / shortest_s, 0.0, static_cast<double>(K - 1));
		const std::size_t j = std::min(static_cast<std::size_t>(u), K - 2);
		const double w = u - static_cast<double>(j);
		X(i, c0 + static_cast<Eigen::Index>(j)) += 1.0 - w;
		X(i, c0 + static_cast<Eigen::Index>(j) + 1) += w;
	}
	// drift knots no used sample touches (a gap of the gyro or a table segment) are left out
	std::vector<Eigen::Index> keep;
	for (Eigen::Index c = 0; c < p; c++)
		if (c == 0 || X.col(c).cwiseAbs().maxCoeff() > 0) keep.push_back(c);
	if (static_cast<Eigen::Index>(keep.size()) < p)
	{
		Eigen::MatrixXd Xk(X.rows(), static_cast<Eigen::Index>(keep.size()));
		for (std::size_t c = 0; c < keep.size(); c++) Xk.col(static_cast<Eigen::Index>(c)) = X.col(keep[c]);
		X = std::move(Xk);
		p = X.cols();
	}
	const std::vector<std::size_t> rows = whitenableRows(block, ok, 0);
	// the noise model on [1, field] (REML over ~100 columns would cost a minute per run)
	Eigen::MatrixXd X2(static_cast<Eigen::Index>(n), 2);
	for (std::size_t g = 0; g < n; g++) X2(static_cast<Eigen::Index>(g), 0) = ok[g] ? 1.0 : 0.0;
	X2.col(1) = X.col(0);
	const ArNoiseModel ar = fitNoiseReml(X2, y, rows, block);
	const LsFit fit = leastSquares(whiten(X, ar, rows, &block), whiten(y, ar, rows, &block).col(0), true);
	if (fit.rank < p) throw MagneticFitError("the applied field cannot be told apart from a slow drift");
	const double sigma2 = fit.rss / std::max(1.0, static_cast<double>(rows.size()) - static_cast<double>(p));
	const double lrv = longRunVarianceFactor(fit.residual, SelectionOptions{}.lrv_max_lag);
	MagneticModel m;
	m.dph_per_uT = fit.coef(0);
	m.dph_per_uT_std = std::sqrt(std::max(0.0, sigma2 * fit.cov_unscaled(0, 0) * lrv));
	m.field_min_uT = lo;
	m.field_max_uT = hi;
	m.samples = used.size();
	if (!m.valid()) throw MagneticFitError("the field fit gave no finite coefficient");
	return m;
}

MagneticFitter magneticFitter()
{
	return [](const Calibration& cal, const std::vector<FogSeries>& runs, std::string& why_not) -> std::optional<MagneticModel> {
		if (!hasFieldVariation(runs)) return std::nullopt;  // a constant field: nothing to fit, nothing to say
		try
		{
			return fitMagneticSensitivity(cal, runs);
		}
		catch (const MagneticFitError& e)
		{
			why_not = e.what();
			return std::nullopt;
		}
	};
}

}  // namespace mrpt_fog::discrepancy
