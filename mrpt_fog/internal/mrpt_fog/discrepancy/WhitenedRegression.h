/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file WhitenedRegression.h
 * Least squares that holds up on autocorrelated gyro noise. Gyro bias noise is strongly
 * autocorrelated (bias instability, rate random walk), so ordinary least-squares F-tests see
 * thousands of "independent" samples where there are a few hundred: they would name an effect
 * in nearly every run. Here the residual is pre-whitened by an ARMA(p,1) model (p and the MA
 * coefficient chosen by BIC, lags never crossing a block edge). The MA term matters: a
 * Gauss-Markov bias (AR(1) near 1) plus white noise is ARMA(1,1), and pure low-order AR fits
 * under-whiten its low frequencies, which inflated null chi-squares 2-3x in our trials. What
 * autocorrelation survives the whitening is measured by a Bartlett long-run variance factor
 * that inflates the test variance.
 */

#include <mrpt_fog/discrepancy/SelectionResult.h>
#include <mrpt_fog/metrics/LongRunVariance.h>

#include <Eigen/Dense>
#include <cstddef>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Least-squares fit with column equilibration and a rank-revealing QR (rank-deficient
 * designs give a minimum-norm-like solution instead of garbage). */
struct LsFit
{
	Eigen::VectorXd coef;
	Eigen::VectorXd residual;
	double rss = 0.0;
	int rank = 0;
	/** (X'X)^-1 (pseudo-inverse), for standard errors: var(coef_j) = sigma^2 * cov(j, j). */
	Eigen::MatrixXd cov_unscaled;
};
LsFit leastSquares(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, bool wantCov = false);

/** Fits ARMA(p,1), p = 0..max_order and theta on a grid chosen by BIC, to a residual series (values at samples
 * whose `ok` is 0 are ignored; lags never cross a block edge). */
ArNoiseModel fitArNoise(const std::vector<double>& residual, const std::vector<int>& block,
						const std::vector<unsigned char>& ok, int max_order = 5);
/** The same with the AR order fixed (0..max_order) and the MA term on (`with_ma`) or off: models
 * compared by likelihood ratio must share the noise-model structure, or the ratio rewards a
 * change of ARMA order instead of the candidate. */
ArNoiseModel fitArNoiseFixedOrder(const std::vector<double>& residual, const std::vector<int>& block,
								  const std::vector<unsigned char>& ok, int max_order, int order, bool with_ma);

/** ARMA(1,1) noise model of y - X b by restricted maximum likelihood (REML): minimises
 * (n - k) ln(RSS_w / (n - k)) + ln det(Xw' Xw) over (phi, theta), Xw, yw whitened on `rows`.
 * Unlike fitting the OLS residual, REML accounts for what the regressors absorb: OLS residuals
 * of slow regressors (temperature polynomials) lack low-frequency power, which biased phi low
 * and made null chi-squares of slow candidates ~1.2-1.35x too large in our trials.
 * `start` (optional) restricts the search to a neighbourhood of a previous estimate. */
ArNoiseModel fitNoiseReml(const Eigen::MatrixXd& X, const Eigen::VectorXd& y, const std::vector<std::size_t>& rows,
						  const std::vector<int>& block, const ArNoiseModel* start = nullptr);

/** Rows k usable after whitening with order p: samples k-p..k all ok and in the same block. */
std::vector<std::size_t> whitenableRows(const std::vector<int>& block, const std::vector<unsigned char>& ok, int p);

/** Whitened matrix: w(k) = M(k) - sum_j phi_j M(k - j) + theta w(k - 1) for k = rows[i]
 * (the recursion restarts, w(k-1) = 0, where k-1 is not a row or, given `block`, lies in
 * another block). With `block` and an ARMA(1,1) model, rows start a stretch exactly
 * (Prais-Winsten): the first row of each stretch is the level scaled by sqrt(sigma_a^2 /
 * gamma_0), so the level at a block start (e.g. a warm-up right after power-on) keeps its
 * information instead of being differenced away; rows must then be whitenableRows(..., 0). */
Eigen::MatrixXd whiten(const Eigen::MatrixXd& M, const ArNoiseModel& ar, const std::vector<std::size_t>& rows,
					   const std::vector<int>* block = nullptr);

/** gamma_0 / sigma_a^2 of an ARMA(1,1): (1 + theta^2 - 2 phi theta) / (1 - phi^2). */
double armaVarianceRatio(const ArNoiseModel& ar);

/** The Bartlett long-run variance factor of a whitened residual (metrics/LongRunVariance.h). */
using ::mrpt_fog::longRunVarianceFactor;

/** Upper tail P(X > x) of a chi-square variable with `dof` degrees of freedom. */
double chi2Survival(double x, double dof);

}  // namespace mrpt_fog::discrepancy
