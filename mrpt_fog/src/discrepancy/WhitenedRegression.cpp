/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/GoldenSection.h>
#include <mrpt_fog/discrepancy/WhitenedRegression.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mrpt_fog::discrepancy
{
LsFit leastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, bool wantCov)
{
	LsFit f;
	const Eigen::Index p = X.cols();
	Eigen::VectorXd scale(p);
	for (Eigen::Index j = 0; j < p; ++j)
	{
		const double nrm = X.col(j).norm();
		scale(j) = nrm > 0 ? 1.0 / nrm : 1.0;
	}
	const Eigen::MatrixXd Xs = X * scale.asDiagonal();
	Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Xs);
	qr.setThreshold(1e-10);
	f.rank = static_cast<int>(qr.rank());
	const Eigen::VectorXd cs = qr.solve(y);
	f.coef = scale.asDiagonal() * cs;
	f.residual = y - X * f.coef;
	f.rss = f.residual.squaredNorm();
	if (wantCov)
	{
		const Eigen::MatrixXd XtX = Xs.transpose() * Xs;
		const Eigen::MatrixXd inv = XtX.completeOrthogonalDecomposition().pseudoInverse();
		f.cov_unscaled = scale.asDiagonal() * inv * scale.asDiagonal();
	}
	return f;
}

std::vector<std::size_t> whitenableRows(const std::vector<int>& block, const std::vector<unsigned char>& ok, int p)
{
	std::vector<std::size_t> rows;
	const std::size_t n = block.size();
	std::size_t run = 0;  // consecutive ok samples in the same block ending at k
	for (std::size_t k = 0; k < n; ++k)
	{
		if (!ok[k] || block[k] < 0)
		{
			run = 0;
			continue;
		}
		if (k > 0 && run > 0 && block[k - 1] == block[k] && ok[k - 1])
			++run;
		else
			run = 1;
		if (run >= static_cast<std::size_t>(p) + 1) rows.push_back(k);
	}
	return rows;
}

double armaVarianceRatio(const ArNoiseModel& ar)
{
	if (ar.order() != 1) return 1.0;
	const double phi = ar.phi[0], th = ar.theta;
	return (1.0 + th * th - 2.0 * phi * th) / std::max(1e-12, 1.0 - phi * phi);
}

Eigen::MatrixXd whiten(const Eigen::MatrixXd& M, const ArNoiseModel& ar, const std::vector<std::size_t>& rows,
					   const std::vector<int>* block)
{
	const auto n = static_cast<Eigen::Index>(rows.size());
	Eigen::MatrixXd W(n, M.cols());
	const bool exact = block != nullptr && ar.order() == 1;
	const double c = exact ? 1.0 / std::sqrt(armaVarianceRatio(ar)) : 1.0;
	// Whether row i starts a new stretch (no predecessor in the same block), once for all columns.
	std::vector<unsigned char> restart(rows.size());
	for (std::size_t i = 0; i < rows.size(); ++i)
		restart[i] = i == 0 || rows[i - 1] + 1 != rows[i] || (block && (*block)[rows[i] - 1] != (*block)[rows[i]]);
	// Column by column (both matrices are column-major) and without a temporary per row: the
	// operations on each element are those of the row form, in the same order.
	const int order = ar.order();
	for (Eigen::Index col = 0; col < M.cols(); ++col)
	{
		const double* m = M.col(col).data();
		double* w = W.col(col).data();
		for (Eigen::Index i = 0; i < n; ++i)
		{
			const std::size_t k = rows[static_cast<std::size_t>(i)];
			if (exact && restart[static_cast<std::size_t>(i)])
			{
				w[i] = c * m[k];
				continue;
			}
			double r = m[k];
			for (int j = 0; j < order; ++j) r -= ar.phi[static_cast<std::size_t>(j)] * m[k - static_cast<std::size_t>(j) - 1];
			if (ar.theta != 0.0 && !restart[static_cast<std::size_t>(i)]) r += ar.theta * w[i - 1];
			w[i] = r;
		}
	}
	return W;
}

namespace
{
ArNoiseModel fitArma(const std::vector<double>& residual, const std::vector<int>& block,
					 const std::vector<unsigned char>& ok, int max_order, int only_order, int ma_mode);
}

ArNoiseModel fitArNoise(const std::vector<double>& residual, const std::vector<int>& block,
						const std::vector<unsigned char>& ok, int max_order)
{
	return fitArma(residual, block, ok, max_order, -1, -1);
}

ArNoiseModel fitArNoiseFixedOrder(const std::vector<double>& residual, const std::vector<int>& block,
								  const std::vector<unsigned char>& ok, int max_order, int order, bool with_ma)
{
	return fitArma(residual, block, ok, max_order, order, with_ma ? 1 : 0);
}

namespace
{
/** only_order < 0: any order 0..max_order; ma_mode -1: with or without MA, 0: without, 1: with. */
ArNoiseModel fitArma(const std::vector<double>& residual, const std::vector<int>& block,
					 const std::vector<unsigned char>& ok, int max_order, int only_order, int ma_mode)
{
	ArNoiseModel best;
	double bestBic = std::numeric_limits<double>::infinity();
	// the same rows (valid for max_order) for every model, so BICs compare
	const auto rows = whitenableRows(block, ok, max_order);
	if (rows.size() < static_cast<std::size_t>(4 * max_order + 10))
	{
		double s = 0;
		std::size_t m = 0;
		for (std::size_t k = 0; k < residual.size(); ++k)
			if (ok[k])
			{
				s += residual[k] * residual[k];
				++m;
			}
		best.innovation_sd = m ? std::sqrt(s / m) : 0.0;
		return best;
	}
	const auto n = static_cast<Eigen::Index>(rows.size());
	// u = e / (1 - theta B) over the ok samples, restarted at block edges and exclusions
	const auto allRows = whitenableRows(block, ok, 0);
	static const double thetas[] = {0.0, 0.2, 0.4, 0.5, 0.6, 0.65, 0.7, 0.75, 0.8, 0.85, 0.9, 0.93, 0.96, 0.98};
	std::vector<double> u(residual.size(), 0.0);
	for (double theta : thetas)
	{
		if ((ma_mode == 0 && theta > 0) || (ma_mode == 1 && theta == 0)) continue;
		for (std::size_t i = 0; i < allRows.size(); ++i)
		{
			const std::size_t k = allRows[i];
			const bool cont = i > 0 && allRows[i - 1] + 1 == k && block[k - 1] == block[k];
			u[k] = residual[k] + (cont ? theta * u[k - 1] : 0.0);
		}
		Eigen::VectorXd y(n);
		Eigen::MatrixXd L(n, max_order);
		for (Eigen::Index i = 0; i < n; ++i)
		{
			const std::size_t k = rows[static_cast<std::size_t>(i)];
			y(i) = u[k];
			for (int j = 0; j < max_order; ++j) L(i, j) = u[k - static_cast<std::size_t>(j) - 1];
		}
		for (int p = 0; p <= max_order; ++p)
		{
			if (only_order >= 0 && p != only_order) continue;
			Eigen::VectorXd phi = Eigen::VectorXd::Zero(p);
			double rss = y.squaredNorm();
			if (p > 0)
			{
				const auto f = leastSquares(L.leftCols(p), y);
				phi = f.coef;
				rss = f.rss;
			}
			const int params = p + (theta > 0 ? 1 : 0);
			const double bic = static_cast<double>(n) * std::log(std::max(rss, 1e-300) / n) + params * std::log(double(n));
			if (bic < bestBic)
			{
				bestBic = bic;
				best.phi.assign(phi.data(), phi.data() + p);
				best.theta = theta;
				best.innovation_sd = std::sqrt(rss / n);
			}
		}
	}
	return best;
}
}  // namespace

namespace
{
double remlObjective(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const std::vector<std::size_t>& rows,
					 const std::vector<int>& block, double phi, double theta)
{
	ArNoiseModel m;
	m.phi = {phi};
	m.theta = theta;
	const Eigen::MatrixXd Xw = whiten(X, m, rows, &block);
	const Eigen::VectorXd yw = whiten(y, m, rows, &block).col(0);
	std::size_t starts = 0;
	for (std::size_t i = 0; i < rows.size(); ++i)
		if (i == 0 || rows[i - 1] + 1 != rows[i] || block[rows[i] - 1] != block[rows[i]]) ++starts;
	Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(Xw);
	qr.setThreshold(1e-10);
	const auto rank = qr.rank();
	const Eigen::VectorXd b = qr.solve(yw);
	const double rss = (yw - Xw * b).squaredNorm();
	double logdet = 0.0;
	for (Eigen::Index i = 0; i < rank; ++i) logdet += 2.0 * std::log(std::fabs(qr.matrixR()(i, i)));
	const double dof = double(rows.size()) - double(rank);
	// + log det of the noise correlation (the scaled first rows of each stretch)
	return dof * std::log(std::max(rss, 1e-300) / dof) + logdet + double(starts) * std::log(armaVarianceRatio(m));
}

}  // namespace

ArNoiseModel fitNoiseReml(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const std::vector<std::size_t>& rows,
						  const std::vector<int>& block, const ArNoiseModel* start)
{
	double phi = 0, theta = 0;
	double lo = 0.0, hi = 0.999, tlo = 0.0, thi = 0.98;
	if (start && start->order() == 1)
	{
		phi = start->phi[0];
		theta = start->theta;
		lo = std::max(0.0, phi - 0.04);
		hi = std::min(0.999, phi + 0.03);
		tlo = std::max(0.0, theta - 0.1);
		thi = std::min(0.98, theta + 0.1);
	}
	else
	{
		static const double phis[] = {0.0, 0.3, 0.5, 0.7, 0.8, 0.87, 0.92, 0.95, 0.97, 0.98, 0.99, 0.995};
		static const double thetas[] = {0.0, 0.3, 0.5, 0.6, 0.7, 0.8, 0.9, 0.95};
		double best = std::numeric_limits<double>::infinity();
		for (double p : phis)
			for (double t : thetas)
			{
				if (t >= p && t > 0) continue;  // MA root at or above the AR root: no information
				const double v = remlObjective(X, y, rows, block, p, t);
				if (v < best)
				{
					best = v;
					phi = p;
					theta = t;
				}
			}
		lo = std::max(0.0, phi - 0.1);
		hi = std::min(0.999, phi + 0.05);
		tlo = std::max(0.0, theta - 0.15);
		thi = std::min(0.98, theta + 0.15);
	}
	for (int pass = 0; pass < 2; ++pass)
	{
		phi = goldenSectionMinimum([&](double p) { return remlObjective(X, y, rows, block, p, theta); }, lo, hi, 14);
		theta = goldenSectionMinimum([&](double t) { return remlObjective(X, y, rows, block, phi, t); }, tlo, thi, 12);
	}
	ArNoiseModel m;
	m.phi = {phi};
	m.theta = theta;
	const Eigen::MatrixXd Xw = whiten(X, m, rows, &block);
	const Eigen::VectorXd yw = whiten(y, m, rows, &block).col(0);
	const auto f = leastSquares(Xw, yw);
	m.innovation_sd = std::sqrt(f.rss / std::max<double>(1.0, double(rows.size()) - f.rank));
	return m;
}

namespace
{
/** Regularised upper incomplete gamma Q(a, x) (series / continued fraction). */
double gammaQ(double a, double x)
{
	if (x <= 0) return 1.0;
	const double gln = std::lgamma(a);
	if (x < a + 1)
	{
		double ap = a, sum = 1.0 / a, del = sum;
		for (int i = 0; i < 1000; ++i)
		{
			ap += 1;
			del *= x / ap;
			sum += del;
			if (std::fabs(del) < std::fabs(sum) * 1e-15) break;
		}
		return 1.0 - sum * std::exp(-x + a * std::log(x) - gln);
	}
	const double fpmin = 1e-300;
	double b = x + 1 - a, c = 1 / fpmin, d = 1 / b, h = d;
	for (int i = 1; i < 1000; ++i)
	{
		const double an = -i * (i - a);
		b += 2;
		d = an * d + b;
		if (std::fabs(d) < fpmin) d = fpmin;
		c = b + an / c;
		if (std::fabs(c) < fpmin) c = fpmin;
		d = 1 / d;
		const double del = d * c;
		h *= del;
		if (std::fabs(del - 1) < 1e-15) break;
	}
	return std::exp(-x + a * std::log(x) - gln) * h;
}
}  // namespace

double chi2Survival(double x, double dof)
{
	if (!(x > 0)) return 1.0;
	return std::clamp(gammaQ(0.5 * dof, 0.5 * x), 0.0, 1.0);
}

}  // namespace mrpt_fog::discrepancy
