/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/BiasFit.h>

#include <Eigen/SVD>
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
namespace
{
/** The centred, equilibrated factor of a column subset and its SVD. */
struct CentredSystem
{
	double n = 0;  // rows
	Eigen::VectorXd mean;  // means of the shifted features (non-constant columns)
	Eigen::VectorXd shift;  // x_ref of those columns (unshifted mean = mean + shift)
	Eigen::VectorXd d;  // equilibration: 1 / (norm of the centred column)
	double ybar = 0;  // mean of y - y_ref
	Eigen::MatrixXd S;  // R factor of the centred features (unequilibrated)
	Eigen::VectorXd z;  // Q' y_c on those columns
	double rho2 = 0;  // residual sum of squares of the unpenalised fit
	Eigen::VectorXd sv;  // singular values of S D (descending)
	Eigen::MatrixXd U, V;
	bool zero_variance = false;
};

CentredSystem centre(StreamingQr& acc, const std::vector<int>& cols)
{
	if (acc.count() == 0) throw std::invalid_argument("bias fit: no samples accumulated");
	if (cols.empty() || cols[0] != 0) throw std::invalid_argument("bias fit: the constant (column 0) must come first");
	for (int c : cols)
		if (c < 0 || static_cast<std::size_t>(c) >= acc.terms())
			throw std::invalid_argument("bias fit: column " + std::to_string(c) + " out of range");
	// QR of [1, X_cols, y]: the constant's reflector removes the means, so the trailing block is
	// the factor of the centred features and response.
	const Eigen::MatrixXd Rs = acc.columnsR(cols);
	CentredSystem s;
	s.n = static_cast<double>(acc.count());
	const auto m = static_cast<Eigen::Index>(cols.size() - 1);
	const double r00 = Rs(0, 0);  // +-sqrt(n)
	s.mean.resize(m);
	s.shift.resize(m);
	for (Eigen::Index i = 0; i < m; i++)
	{
		s.shift[i] = acc.xRef()[static_cast<std::size_t>(cols[static_cast<std::size_t>(i) + 1])];
		s.mean[i] = Rs(0, i + 1) / r00;
	}
	s.ybar = Rs(0, m + 1) / r00;
	s.S = Rs.block(1, 1, m, m).triangularView<Eigen::Upper>();
	s.z = Rs.block(1, m + 1, m, 1);
	s.rho2 = Rs(m + 1, m + 1) * Rs(m + 1, m + 1);
	s.d.resize(m);
	for (Eigen::Index i = 0; i < m; i++)
	{
		const double centred = s.S.col(i).norm(), raw = Rs.col(i + 1).norm();
		if (centred > 0 && centred > 1e-7 * raw)
			s.d[i] = 1.0 / centred;
		else
		{
			s.d[i] = 0.0;  // constant feature: no information (counts as rank loss)
			s.zero_variance = true;
		}
	}
	if (m > 0)
	{
		const Eigen::MatrixXd Se = s.S * s.d.asDiagonal();
		Eigen::JacobiSVD<Eigen::MatrixXd, Eigen::NoQRPreconditioner> svd(Se, Eigen::ComputeFullU | Eigen::ComputeFullV);
		s.sv = svd.singularValues();
		s.U = svd.matrixU();
		s.V = svd.matrixV();
	}
	return s;
}

/** Whether singular value i counts in the numerical rank (s > rcond s_max). */
bool kept(const CentredSystem& s, Eigen::Index i, double rcond)
{
	const double smax = s.sv.size() ? s.sv[0] : 0.0;
	return s.sv[i] > 0 && s.sv[i] > rcond * smax;
}

/** Coefficients (full, including the constant with y_ref) for ridge lambda. */
Eigen::VectorXd solveCentred(const CentredSystem& s, double lambda, double rcond, double y_ref,
							 Eigen::VectorXd* shrink_out = nullptr)
{
	const Eigen::Index m = s.mean.size();
	Eigen::VectorXd beta = Eigen::VectorXd::Zero(m + 1);
	if (m > 0)
	{
		Eigen::VectorXd g(m), shrink(m);
		for (Eigen::Index i = 0; i < m; i++)
		{
			const double sv = s.sv[i], e = sv * sv;
			const bool keep = kept(s, i, rcond);
			g[i] = keep ? sv / (e + lambda) : 0.0;
			shrink[i] = keep ? e / (e + lambda) : 0.0;
		}
		const Eigen::VectorXd bt = s.V * g.asDiagonal() * (s.U.transpose() * s.z);
		beta.tail(m) = s.d.asDiagonal() * bt;
		if (shrink_out) *shrink_out = shrink;
	}
	beta[0] = s.ybar - (m > 0 ? (s.mean + s.shift).dot(beta.tail(m)) : 0.0) + y_ref;
	return beta;
}

std::size_t rankOf(const CentredSystem& s, double rcond)
{
	std::size_t r = 1;
	for (Eigen::Index i = 0; i < s.sv.size(); i++) r += kept(s, i, rcond);
	return r;
}

/** Coefficients of the unshifted model expressed for the accumulator's shifted rows. */
Eigen::VectorXd shiftedCoef(const StreamingQr& acc, const std::vector<int>& cols, const Eigen::VectorXd& coef)
{
	Eigen::VectorXd beta = coef;
	beta[0] -= acc.yRef();
	for (std::size_t i = 1; i < cols.size(); i++)
		beta[0] += coef[static_cast<Eigen::Index>(i)] * acc.xRef()[static_cast<std::size_t>(cols[i])];
	return beta;
}
}  // namespace

Eigen::VectorXd shiftedFullCoefficients(const StreamingQr& acc, const std::vector<int>& cols, const Eigen::VectorXd& coef)
{
	if (static_cast<std::size_t>(coef.size()) != cols.size())
		throw std::invalid_argument("shiftedFullCoefficients: coefficient count differs from the column count");
	const Eigen::VectorXd b = shiftedCoef(acc, cols, coef);
	Eigen::VectorXd full = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(acc.terms()));
	for (std::size_t i = 0; i < cols.size(); i++)
	{
		if (cols[i] < 0 || static_cast<std::size_t>(cols[i]) >= acc.terms())
			throw std::invalid_argument("shiftedFullCoefficients: column " + std::to_string(cols[i]) + " out of range");
		full[cols[i]] = b[static_cast<Eigen::Index>(i)];
	}
	return full;
}

double residualSumOfSquares(StreamingQr& acc, const std::vector<int>& cols, const Eigen::VectorXd& coef)
{
	if (static_cast<std::size_t>(coef.size()) != cols.size())
		throw std::invalid_argument("residualSumOfSquares: coefficient count differs from the column count");
	const Eigen::MatrixXd& R = acc.r();
	const Eigen::VectorXd beta = shiftedCoef(acc, cols, coef);
	Eigen::VectorXd w = R.col(static_cast<Eigen::Index>(acc.terms()));  // || R [-b; 1] ||^2
	for (std::size_t i = 0; i < cols.size(); i++)
	{
		if (cols[i] < 0 || static_cast<std::size_t>(cols[i]) >= acc.terms())
			throw std::invalid_argument("residualSumOfSquares: column " + std::to_string(cols[i]) + " out of range");
		w -= beta[static_cast<Eigen::Index>(i)] * R.col(cols[i]);
	}
	return w.squaredNorm();
}

LinearFit solveBiasFit(StreamingQr& acc, const std::vector<int>& cols, double ridge, double rcond)
{
	if (!(ridge >= 0) || !std::isfinite(ridge)) throw std::invalid_argument("bias fit: ridge must be >= 0");
	const CentredSystem s = centre(acc, cols);
	LinearFit fit;
	fit.columns = cols;
	fit.ridge = ridge;
	fit.samples = acc.count();
	Eigen::VectorXd shrink;
	fit.coef_dph = solveCentred(s, ridge, rcond, acc.yRef(), &shrink);
	const Eigen::Index m = s.mean.size();
	fit.numerical_rank = rankOf(s, rcond);
	if (s.zero_variance)
	{
		std::size_t zeros = 0;
		for (Eigen::Index i = 0; i < m; i++) zeros += s.d[i] == 0.0;
		fit.numerical_rank = std::min(fit.numerical_rank, cols.size() - zeros);
	}
	if (m > 0)
	{
		const double smin = s.sv[m - 1], smax = s.sv[0];
		fit.condition_number = (smin > 0 && !s.zero_variance) ? (smax / smin) * (smax / smin)
															   : std::numeric_limits<double>::infinity();
		fit.effective_dof = 1.0 + shrink.sum();
	}
	else
	{
		fit.condition_number = 1.0;
		fit.effective_dof = 1.0;
	}
	// In-sample residual from the factor: || z - S b ||^2 + rho^2 (the centred residual); its
	// mean is ybar - mean'b - b0_shifted, which is 0 up to round-off (the constant is free).
	const Eigen::VectorXd b = fit.coef_dph.tail(m);
	const double sse = (m > 0 ? (s.z - s.S * b).squaredNorm() : 0.0) + s.rho2;
	fit.rms_dph = std::sqrt(sse / s.n);
	fit.residual_mean_dph = s.ybar - s.mean.dot(b) - shiftedCoef(acc, cols, fit.coef_dph)[0];
	const double dof_left = s.n - fit.effective_dof;
	const double sigma2 = dof_left > 0 ? sse / dof_left : std::numeric_limits<double>::quiet_NaN();
	// Covariance: Cov(b_rest) = sigma^2 D V diag(e/(e+l)^2) V' D (e = s^2); b0 = ybar - mean'b_rest.
	fit.covariance.setZero(m + 1, m + 1);
	if (m > 0)
	{
		Eigen::VectorXd w(m);
		for (Eigen::Index i = 0; i < m; i++)
		{
			const double e = s.sv[i] * s.sv[i];
			w[i] = kept(s, i, rcond) ? e / ((e + ridge) * (e + ridge)) : 0.0;
		}
		const Eigen::MatrixXd DV = s.d.asDiagonal() * s.V;
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

std::vector<StreamingQr> trainingSets(std::vector<StreamingQr>& folds)
{
	std::vector<StreamingQr> train;
	for (std::size_t f = 0; f < folds.size(); f++)
	{
		train.emplace_back(folds[f].terms(), folds[f].yRef(), folds[f].xRef());
		for (std::size_t g = 0; g < folds.size(); g++)
			if (g != f) train.back().merge(folds[g]);
	}
	return train;
}

std::vector<std::vector<double>> crossValidatedFoldSse(std::vector<StreamingQr>& folds, std::vector<StreamingQr>& train,
													   const std::vector<int>& cols, const std::vector<double>& ridges,
													   double rcond)
{
	if (train.size() != folds.size()) throw std::invalid_argument("crossValidatedFoldSse: one training set per fold needed");
	const double nan = std::numeric_limits<double>::quiet_NaN();
	std::vector<std::vector<double>> sse(ridges.size(), std::vector<double>(folds.size(), nan));
	for (std::size_t f = 0; f < folds.size(); f++)
	{
		if (folds[f].count() == 0 || train[f].count() == 0) continue;
		const CentredSystem s = centre(train[f], cols);
		const bool deficient = rankOf(s, rcond) < cols.size() || s.zero_variance;
		for (std::size_t r = 0; r < ridges.size(); r++)
		{
			if (ridges[r] == 0 && deficient)
			{
				sse[r][f] = std::numeric_limits<double>::infinity();
				continue;
			}
			sse[r][f] = residualSumOfSquares(folds[f], cols, solveCentred(s, ridges[r], rcond, train[f].yRef()));
		}
	}
	return sse;
}

std::vector<std::vector<std::vector<double>>> crossValidatedBlockSse(std::vector<StreamingQr>& train,
																	 std::vector<std::vector<StreamingQr>>& units,
																	 const std::vector<int>& cols, const std::vector<double>& ridges,
																	 double rcond)
{
	if (train.size() != units.size()) throw std::invalid_argument("crossValidatedBlockSse: one training set per fold needed");
	const double nan = std::numeric_limits<double>::quiet_NaN();
	std::vector<std::vector<std::vector<double>>> sse(ridges.size());
	for (auto& r : sse)
		for (const auto& u : units) r.emplace_back(u.size(), nan);
	for (std::size_t f = 0; f < units.size(); f++)
	{
		if (units[f].empty() || train[f].count() == 0) continue;
		const CentredSystem s = centre(train[f], cols);
		const bool deficient = rankOf(s, rcond) < cols.size() || s.zero_variance;
		for (std::size_t r = 0; r < ridges.size(); r++)
		{
			if (ridges[r] == 0 && deficient)
			{
				std::fill(sse[r][f].begin(), sse[r][f].end(), std::numeric_limits<double>::infinity());
				continue;
			}
			const Eigen::VectorXd coef = solveCentred(s, ridges[r], rcond, train[f].yRef());
			for (std::size_t u = 0; u < units[f].size(); u++) sse[r][f][u] = residualSumOfSquares(units[f][u], cols, coef);
		}
	}
	return sse;
}

std::vector<double> crossValidatedRms(std::vector<StreamingQr>& folds, std::vector<StreamingQr>& train,
									  const std::vector<int>& cols, const std::vector<double>& ridges, double rcond)
{
	if (train.size() != folds.size()) throw std::invalid_argument("crossValidatedRms: one training set per fold needed");
	const std::vector<std::vector<double>> sse = crossValidatedFoldSse(folds, train, cols, ridges, rcond);
	double rows = 0;
	for (std::size_t f = 0; f < folds.size(); f++)
		if (folds[f].count() != 0 && train[f].count() != 0) rows += static_cast<double>(folds[f].count());
	std::vector<double> out(ridges.size(), std::numeric_limits<double>::infinity());
	if (rows <= 0) return out;
	for (std::size_t r = 0; r < ridges.size(); r++)
	{
		double total = 0;
		bool deficient = false;  // rank-deficient without a ridge in some fold: no figure
		for (std::size_t f = 0; f < folds.size(); f++)
			if (folds[f].count() != 0 && train[f].count() != 0)
			{
				deficient = deficient || sse[r][f] == std::numeric_limits<double>::infinity();
				total += sse[r][f];
			}
		if (!deficient) out[r] = std::sqrt(total / rows);
	}
	return out;
}

std::vector<double> crossValidatedRms(std::vector<StreamingQr>& folds, const std::vector<int>& cols,
									  const std::vector<double>& ridges, double rcond)
{
	auto train = trainingSets(folds);
	return crossValidatedRms(folds, train, cols, ridges, rcond);
}

}  // namespace mrpt_fog
