/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file BiasFit.h
 * Least squares for the bias model, with memory independent of the log length.
 *
 * Rows are accumulated by StreamingQr (StreamingQr.h): the triangular factor R of the augmented
 * design [X | y] of normalised features (ThermalFeatureSet: every feature is a power of a signal
 * scaled to [-1, 1]), by Householder reflections, block by block. Features are shifted by x_ref
 * (their means, from a first pass) and y by y_ref (the mean bias).
 *
 * solveBiasFit() on a column subset: (1) the QR of those columns of R, with the constant first:
 * its trailing block is the R factor of the CENTRED features (so the ridge penalty never shrinks
 * the mean bias) and of the centred response; (2) equilibration of that factor to unit column
 * norms; (3) its SVD, U S V': condition number = (s_max / s_min)^2 (the condition number of the
 * centred, equilibrated normal matrix, i.e. cond(X)^2 of the centred, equilibrated design, kept
 * in that definition for continuity), numerical rank = singular values with s > rcond x s_max;
 * (4) coefficients b = V diag(s / (s^2 + lambda)) U' Q'y over the numerical rank, with an
 * optional ridge lambda (relative to the unit diagonal). Everything is computed from the factor,
 * never from X'X: the coefficients are accurate to about cond(X) x eps, not cond(X)^2 x eps.
 * Conditioning check (documented): with lambda = 0 a rank-deficient system (a singular value
 * below rcond = 1e-10 of the largest, i.e. cond(X) > 1e10 for the centred, equilibrated design)
 * is refused by the caller rather than solved. Why 1e-10: R is accurate to a few eps x s_max, so
 * a kept direction retains at least ~5 of 16 digits; NumPy's lstsq default, eps x max(rows,
 * cols), is 5e-11 for 2.4e5 rows. (Normal equations needed 1e-6: they square the condition.)
 *
 * The residual of any coefficient vector over any accumulated block is exact from the block's
 * factor (|| R [-b; 1] ||), which is what blocked k-fold cross-validation uses: one accumulator
 * per fold, no stored samples.
 */

#include <mrpt_fog/model/StreamingQr.h>

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace mrpt_fog
{

/** A solved linear bias model on a subset of the accumulated columns. */
struct LinearFit
{
	std::vector<int> columns;  //!< accumulated column of each coefficient (0 = constant)
	Eigen::VectorXd coef_dph;  //!< coefficients [deg/h per unit normalised feature]
	Eigen::MatrixXd covariance;  //!< of coef_dph [(deg/h)^2], sigma^2 from the residual
	double ridge = 0.0;  //!< lambda used (relative to the equilibrated, unit-diagonal matrix)
	double condition_number = 0.0;  //!< of the centred equilibrated normal matrix (inf if singular)
	std::size_t numerical_rank = 0;  //!< including the constant
	double effective_dof = 0.0;  //!< trace of the hat matrix (= rank without ridge)
	std::size_t samples = 0;
	double rms_dph = 0.0;  //!< in-sample residual RMS [deg/h]
	double residual_mean_dph = 0.0;
};

/** Solves on `columns` (must contain 0, the constant). See the file comment. Throws
 * std::invalid_argument for an empty accumulator, a missing constant, or a column index out of
 * range. A feature with zero variance gives numerical_rank < columns.size(). */
LinearFit solveBiasFit(StreamingQr& acc, const std::vector<int>& columns, double ridge = 0.0, double rcond = 1e-10);

/** The model coef_dph (on `columns`, as solveBiasFit returns it) as a vector over all of the
 * accumulator's terms in its shifted coordinates (y - y_ref = (x - x_ref)' beta; zero off
 * `columns`): the beta of StreamingQr::flipResiduals. */
Eigen::VectorXd shiftedFullCoefficients(const StreamingQr& acc, const std::vector<int>& columns,
										const Eigen::VectorXd& coef_dph);

/** Residual sum of squares of coef (on `columns`) over the rows accumulated in `acc`. */
double residualSumOfSquares(StreamingQr& acc, const std::vector<int>& columns, const Eigen::VectorXd& coef_dph);

/** For each fold, an accumulator of all the OTHER folds (its training set). */
std::vector<StreamingQr> trainingSets(std::vector<StreamingQr>& folds);

/** Blocked k-fold cross-validation: for each ridge value, the held-out residual RMS [deg/h]
 * pooled over folds (each fold predicted by a model fitted on the others; `training` from
 * trainingSets(folds)). Folds with no rows are skipped; returns +inf for a ridge value whose
 * training systems are rank deficient when ridge == 0. */
std::vector<double> crossValidatedRms(std::vector<StreamingQr>& folds, std::vector<StreamingQr>& training,
									  const std::vector<int>& columns, const std::vector<double>& ridges,
									  double rcond = 1e-10);
/** Per-fold held-out residual sums of squares: sse[r][f] for ridge r and fold f (NaN for a
 * fold with no rows or no training rows; +inf for ridge 0 on a rank-deficient training set),
 * for the standard error of the cross-validated error. */
std::vector<std::vector<double>> crossValidatedFoldSse(std::vector<StreamingQr>& folds, std::vector<StreamingQr>& training,
													   const std::vector<int>& columns, const std::vector<double>& ridges,
													   double rcond = 1e-10);
/** Per-block held-out residual sums of squares: sse[r][f][u] for ridge r, fold f and block u of
 * that fold (units[f]: accumulators partitioning the fold's held-out rows, e.g. time blocks),
 * each block predicted by the model fitted on training[f]. Summed over u it is
 * crossValidatedFoldSse's sse[r][f]. NaN for an empty training set, +inf for ridge 0 on a
 * rank-deficient one. The blocks' spread is what a paired comparison of two models needs. */
std::vector<std::vector<std::vector<double>>> crossValidatedBlockSse(std::vector<StreamingQr>& training,
																	 std::vector<std::vector<StreamingQr>>& units,
																	 const std::vector<int>& columns,
																	 const std::vector<double>& ridges, double rcond = 1e-10);
/** The same, building the training sets itself. */
std::vector<double> crossValidatedRms(std::vector<StreamingQr>& folds, const std::vector<int>& columns,
									  const std::vector<double>& ridges, double rcond = 1e-10);

}  // namespace mrpt_fog
