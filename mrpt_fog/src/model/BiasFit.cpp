/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/BiasFit.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
NormalEquations::NormalEquations(std::size_t n, double y_ref, const std::vector<double>& x_ref) : n_(n), y_ref_(y_ref)
{
	if (!x_ref.empty() && x_ref.size() != n) throw std::invalid_argument("NormalEquations: x_ref size differs from the term count");
	x_ref_ = x_ref.empty() ? std::vector<double>(n, 0.0) : x_ref;
	if (n > 0) x_ref_[0] = 0.0;
	for (double v : x_ref_)
		if (!std::isfinite(v)) throw std::invalid_argument("NormalEquations: x_ref is not finite");
	xtx_.setZero(n, n);
	xty_.setZero(n);
	block_.resize(n, kBlock);
	block_y_.resize(kBlock);
}

void NormalEquations::add(const double* f, double y)
{
	for (std::size_t j = 0; j < n_; j++)
	{
		if (!std::isfinite(f[j]))
			throw std::invalid_argument("NormalEquations::add: feature " + std::to_string(j) + " is not finite");
		block_(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(in_block_)) = f[j] - x_ref_[j];
	}
	if (!std::isfinite(y)) throw std::invalid_argument("NormalEquations::add: response is not finite");
	block_y_[static_cast<Eigen::Index>(in_block_)] = y - y_ref_;
	if (++in_block_ == kBlock) flush();
}

void NormalEquations::flush()
{
	if (in_block_ == 0) return;
	const auto m = static_cast<Eigen::Index>(in_block_);
	const auto B = block_.leftCols(m);
	const auto yb = block_y_.head(m);
	xtx_.selfadjointView<Eigen::Lower>().rankUpdate(B);
	xty_.noalias() += B * yb;
	yty_ += yb.squaredNorm();
	count_ += in_block_;
	in_block_ = 0;
	symmetric_ = false;
}

void NormalEquations::merge(const NormalEquations& o_in)
{
	NormalEquations o = o_in;
	o.flush();
	flush();
	if (o.n_ != n_ || o.y_ref_ != y_ref_ || o.x_ref_ != x_ref_)
		throw std::invalid_argument("NormalEquations::merge: different size or reference");
	xtx_ += o.xtx_;  // the lower triangle is authoritative; the upper is rebuilt on access
	xty_ += o.xty_;
	yty_ += o.yty_;
	count_ += o.count_;
	symmetric_ = false;
}

const Eigen::MatrixXd& NormalEquations::xtx()
{
	flush();
	if (!symmetric_)
	{
		xtx_.triangularView<Eigen::StrictlyUpper>() = xtx_.transpose();
		symmetric_ = true;
	}
	return xtx_;
}
const Eigen::VectorXd& NormalEquations::xty()
{
	flush();
	return xty_;
}
double NormalEquations::yty()
{
	flush();
	return yty_;
}

namespace
{
/** The centred, equilibrated system of a column subset and its eigen-decomposition. */
struct CentredSystem
{
	double n = 0;  // rows
	Eigen::VectorXd mean;  // means of the shifted features (non-constant columns)
	Eigen::VectorXd shift;  // x_ref of those columns (unshifted mean = mean + shift)
	Eigen::VectorXd d;  // equilibration 1/sqrt(var * n)
	double ybar = 0;  // mean of y - y_ref
	Eigen::VectorXd c;  // equilibrated centred X'y
	Eigen::VectorXd evals;
	Eigen::MatrixXd evecs;
	bool zero_variance = false;
};

CentredSystem centre(NormalEquations& ne, const std::vector<int>& cols)
{
	if (ne.count() == 0 && ne.terms() > 0) ne.flush();
	if (ne.count() == 0) throw std::invalid_argument("bias fit: no samples accumulated");
	if (cols.empty() || cols[0] != 0) throw std::invalid_argument("bias fit: the constant (column 0) must come first");
	for (int c : cols)
		if (c < 0 || static_cast<std::size_t>(c) >= ne.terms())
			throw std::invalid_argument("bias fit: column " + std::to_string(c) + " out of range");
	const Eigen::MatrixXd& G = ne.xtx();
	const Eigen::VectorXd& b = ne.xty();
	CentredSystem s;
	s.n = static_cast<double>(ne.count());
	const auto m = static_cast<Eigen::Index>(cols.size() - 1);
	s.mean.resize(m);
	s.shift.resize(m);
	for (Eigen::Index i = 0; i < m; i++) s.shift[i] = ne.xRef()[static_cast<std::size_t>(cols[i + 1])];
	Eigen::MatrixXd C(m, m);
	Eigen::VectorXd c(m);
	s.ybar = b[0] / s.n;
	for (Eigen::Index i = 0; i < m; i++) s.mean[i] = G(cols[i + 1], 0) / s.n;
	for (Eigen::Index i = 0; i < m; i++)
	{
		for (Eigen::Index j = 0; j < m; j++) C(i, j) = G(cols[i + 1], cols[j + 1]) - s.n * s.mean[i] * s.mean[j];
		c[i] = b[cols[i + 1]] - s.n * s.mean[i] * s.ybar;
	}
	s.d.resize(m);
	for (Eigen::Index i = 0; i < m; i++)
	{
		const double v = C(i, i);
		if (v > 0 && v > 1e-14 * G(cols[i + 1], cols[i + 1]))
			s.d[i] = 1.0 / std::sqrt(v);
		else
		{
			s.d[i] = 0.0;  // constant feature: no information (counts as rank loss)
			s.zero_variance = true;
		}
	}
	const Eigen::MatrixXd A = s.d.asDiagonal() * C * s.d.asDiagonal();
	s.c = s.d.asDiagonal() * c;
	if (m > 0)
	{
		Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(A);
		s.evals = es.eigenvalues();
		s.evecs = es.eigenvectors();
	}
	return s;
}

/** Coefficients (full, including constant with y_ref) for ridge lambda. */
Eigen::VectorXd solveCentred(const CentredSystem& s, double lambda, double rank_tol, double y_ref,
							 Eigen::VectorXd* shrink_out = nullptr)
{
	const Eigen::Index m = s.mean.size();
	Eigen::VectorXd beta = Eigen::VectorXd::Zero(m + 1);
	if (m > 0)
	{
		const double emax = std::max(s.evals.maxCoeff(), 0.0);
		Eigen::VectorXd inv(m), shrink(m);
		for (Eigen::Index i = 0; i < m; i++)
		{
			const double e = s.evals[i];
			const bool keep = e > rank_tol * emax;
			inv[i] = keep ? 1.0 / (e + lambda) : 0.0;
			shrink[i] = keep ? e / (e + lambda) : 0.0;
		}
		const Eigen::VectorXd bt = s.evecs * inv.asDiagonal() * (s.evecs.transpose() * s.c);
		beta.tail(m) = s.d.asDiagonal() * bt;
		if (shrink_out) *shrink_out = shrink;
	}
	beta[0] = s.ybar - (m > 0 ? (s.mean + s.shift).dot(beta.tail(m)) : 0.0) + y_ref;
	return beta;
}

std::size_t rankOf(const CentredSystem& s, double rank_tol)
{
	std::size_t r = 1;
	if (s.evals.size() == 0) return r;
	const double emax = s.evals.maxCoeff();
	for (Eigen::Index i = 0; i < s.evals.size(); i++)
		if (s.evals[i] > rank_tol * emax) r++;
	return r;
}
}  // namespace

namespace
{
/** Coefficients of the unshifted model expressed for the accumulator's shifted rows. */
Eigen::VectorXd shiftedCoef(const NormalEquations& ne, const std::vector<int>& cols, const Eigen::VectorXd& coef)
{
	Eigen::VectorXd beta = coef;
	beta[0] -= ne.yRef();
	for (std::size_t i = 1; i < cols.size(); i++)
		beta[0] += coef[static_cast<Eigen::Index>(i)] * ne.xRef()[static_cast<std::size_t>(cols[i])];
	return beta;
}
}  // namespace

double residualSumOfSquares(NormalEquations& ne, const std::vector<int>& cols, const Eigen::VectorXd& coef)
{
	const Eigen::MatrixXd& G = ne.xtx();
	const Eigen::VectorXd& b = ne.xty();
	const auto m = static_cast<Eigen::Index>(cols.size());
	const Eigen::VectorXd beta = shiftedCoef(ne, cols, coef);
	double bXty = 0, bGb = 0;
	for (Eigen::Index i = 0; i < m; i++)
	{
		bXty += beta[i] * b[cols[i]];
		for (Eigen::Index j = 0; j < m; j++) bGb += beta[i] * G(cols[i], cols[j]) * beta[j];
	}
	return std::max(0.0, ne.yty() - 2 * bXty + bGb);
}

LinearFit solveBiasFit(NormalEquations& ne, const std::vector<int>& cols, double ridge, double rank_tol)
{
	if (!(ridge >= 0) || !std::isfinite(ridge)) throw std::invalid_argument("bias fit: ridge must be >= 0");
	const CentredSystem s = centre(ne, cols);
	LinearFit fit;
	fit.columns = cols;
	fit.ridge = ridge;
	fit.samples = ne.count();
	Eigen::VectorXd shrink;
	fit.coef_dph = solveCentred(s, ridge, rank_tol, ne.yRef(), &shrink);
	const Eigen::Index m = s.mean.size();
	fit.numerical_rank = rankOf(s, rank_tol) - (s.zero_variance ? 1 : 0) * 0;
	if (s.zero_variance)
	{
		std::size_t zeros = 0;
		for (Eigen::Index i = 0; i < m; i++) zeros += s.d[i] == 0.0;
		fit.numerical_rank = std::min(fit.numerical_rank, cols.size() - zeros);
	}
	if (m > 0)
	{
		const double emin = s.evals.minCoeff(), emax = s.evals.maxCoeff();
		fit.condition_number = (emin > 0 && !s.zero_variance) ? emax / emin : std::numeric_limits<double>::infinity();
		fit.effective_dof = 1.0 + shrink.sum();
	}
	else
	{
		fit.condition_number = 1.0;
		fit.effective_dof = 1.0;
	}
	const double sse = residualSumOfSquares(ne, cols, fit.coef_dph);
	fit.rms_dph = std::sqrt(sse / s.n);
	const double dof_left = s.n - fit.effective_dof;
	const double sigma2 = dof_left > 0 ? sse / dof_left : std::numeric_limits<double>::quiet_NaN();
	// Residual mean: y - X b summed = X'y[0] - (X'X b)[0] (constant column).
	{
		const Eigen::MatrixXd& G = ne.xtx();
		double sum = ne.xty()[0];
		const Eigen::VectorXd beta = shiftedCoef(ne, cols, fit.coef_dph);
		for (Eigen::Index i = 0; i <= m; i++) sum -= G(0, cols[i]) * beta[i];
		fit.residual_mean_dph = sum / s.n;
	}
	// Covariance: Cov(b_rest) = sigma^2 D V diag(e/(e+l)^2) V' D; b0 = ybar - mean'b_rest.
	fit.covariance.setZero(m + 1, m + 1);
	if (m > 0)
	{
		const double emax = s.evals.maxCoeff();
		Eigen::VectorXd w(m);
		for (Eigen::Index i = 0; i < m; i++)
		{
			const double e = s.evals[i];
			w[i] = e > rank_tol * emax ? e / ((e + ridge) * (e + ridge)) : 0.0;
		}
		const Eigen::MatrixXd DV = s.d.asDiagonal() * s.evecs;
		const Eigen::MatrixXd cov_rest = sigma2 * DV * w.asDiagonal() * DV.transpose();
		fit.covariance.bottomRightCorner(m, m) = cov_rest;
		const Eigen::VectorXd mean_abs = s.mean + s.shift;
		const Eigen::VectorXd cm = cov_rest * mean_abs;
		fit.covariance.block(1, 0, m, 1) = -cm;
		fit.covariance.block(0, 1, 1, m) = -cm.transpose();
		fit.covariance(0, 0) = sigma2 / s.n + mean_abs.dot(cm);
	}
	else
		fit.covariance(0, 0) = sigma2 / s.n;
	return fit;
}

std::vector<double> crossValidatedRms(std::vector<NormalEquations>& folds, const std::vector<int>& cols,
									  const std::vector<double>& ridges, double rank_tol)
{
	std::vector<double> sse(ridges.size(), 0.0);
	std::vector<bool> bad(ridges.size(), false);
	double rows = 0;
	for (std::size_t f = 0; f < folds.size(); f++)
	{
		if (folds[f].count() == 0) folds[f].flush();
		if (folds[f].count() == 0) continue;
		NormalEquations train(folds[f].terms(), folds[f].yRef(), folds[f].xRef());
		for (std::size_t g = 0; g < folds.size(); g++)
			if (g != f) train.merge(folds[g]);
		if (train.count() == 0) continue;
		const CentredSystem s = centre(train, cols);
		const bool deficient = rankOf(s, rank_tol) < cols.size() || s.zero_variance;
		for (std::size_t r = 0; r < ridges.size(); r++)
		{
			if (ridges[r] == 0 && deficient)
			{
				bad[r] = true;
				continue;
			}
			const Eigen::VectorXd beta = solveCentred(s, ridges[r], rank_tol, train.yRef());
			sse[r] += residualSumOfSquares(folds[f], cols, beta);
		}
		rows += static_cast<double>(folds[f].count());
	}
	std::vector<double> out(ridges.size(), std::numeric_limits<double>::infinity());
	if (rows <= 0) return out;
	for (std::size_t r = 0; r < ridges.size(); r++)
		if (!bad[r]) out[r] = std::sqrt(sse[r] / rows);
	return out;
}

}  // namespace mrpt_fog
