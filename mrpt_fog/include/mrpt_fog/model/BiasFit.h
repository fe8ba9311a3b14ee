/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file BiasFit.h
 * Streaming least squares for the bias model, with memory independent of the log length.
 *
 * NormalEquations accumulates X'X, X'y, y'y of normalised features (ThermalFeatureSet: every
 * feature is a power of a signal scaled to [-1, 1], so columns have comparable size). Rows are
 * buffered in blocks of 256 and added with a symmetric rank-k update, which also keeps the
 * summation pairwise-like (small partial sums added to the total); y is accumulated relative to
 * a reference y_ref (the expected mean bias) and every feature relative to a reference x_ref
 * (its expected mean, from a first pass) so that the sums hold centred quantities: without
 * this, removing the mean later cancels most digits of X'X for nearly collinear terms.
 *
 * solveBiasFit() then (1) removes the constant by centring (so the ridge penalty never shrinks
 * the mean bias), (2) equilibrates the centred matrix to unit diagonal, (3) eigen-decomposes it:
 * condition number = ratio of extreme eigenvalues (this is cond(X)^2 of the centred,
 * equilibrated design), numerical rank = eigenvalues above rank_tol x largest, and (4) solves
 * with an optional ridge lambda (relative to the unit diagonal), as a pseudo-inverse over the
 * numerical rank. Conditioning check (documented): with lambda = 0 a rank-deficient system
 * (any eigenvalue below rank_tol = 1e-12, i.e. cond(X) > 1e6, beyond which the normal equations
 * lose more than ~4 of 16 digits) is refused by the caller rather than solved.
 *
 * Held-out error of any coefficient vector on any accumulated block is exact from the block's
 * sums (y'y - 2 b'X'y + b'X'X b), which is what blocked k-fold cross-validation uses: one
 * NormalEquations per fold, no stored samples.
 */

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace mrpt_fog
{
class NormalEquations
{
   public:
	NormalEquations() = default;
	/** x_ref (optional, size n_terms): feature references; entry 0 (the constant) is ignored. */
	NormalEquations(std::size_t n_terms, double y_ref_dph, const std::vector<double>& x_ref = {});
	/** Adds one row (features f[0..n), response y [deg/h]). Rows with a non-finite value must
	 * be filtered by the caller (throws std::invalid_argument on NaN, naming the column). */
	void add(const double* f, double y_dph);
	/** Adds another accumulator of the same size and y_ref (throws std::invalid_argument). */
	void merge(const NormalEquations& other);
	/** Flushes buffered rows (accessors below call it). */
	void flush();

	std::size_t terms() const { return n_; }
	std::size_t count() const { return count_; }
	double yRef() const { return y_ref_; }
	const std::vector<double>& xRef() const { return x_ref_; }
	/** Sums (after flush) of the shifted rows (x - x_ref, y - y_ref): X'X (full symmetric),
	 * X'y, y'y. Coefficients passed to / returned by the functions below are always for the
	 * unshifted features. */
	const Eigen::MatrixXd& xtx();
	const Eigen::VectorXd& xty();
	double yty();

   private:
	static constexpr std::size_t kBlock = 256;
	std::size_t n_ = 0;
	double y_ref_ = 0.0;
	std::vector<double> x_ref_;
	std::size_t count_ = 0;
	Eigen::MatrixXd xtx_;  // lower triangle accumulated; symmetrised on access
	Eigen::VectorXd xty_;
	double yty_ = 0.0;
	Eigen::MatrixXd block_;  // n x kBlock, column per row of X
	Eigen::VectorXd block_y_;
	std::size_t in_block_ = 0;
	bool symmetric_ = true;
};

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
LinearFit solveBiasFit(NormalEquations& ne, const std::vector<int>& columns, double ridge = 0.0, double rank_tol = 1e-12);

/** Residual sum of squares of coef (on fit.columns) over the rows accumulated in `ne`. */
double residualSumOfSquares(NormalEquations& ne, const std::vector<int>& columns, const Eigen::VectorXd& coef_dph);

/** Blocked k-fold cross-validation: for each ridge value, the held-out residual RMS [deg/h]
 * pooled over folds (each fold predicted by a model fitted on the others). Folds with no rows
 * are skipped; returns +inf for a ridge value whose training systems are rank deficient when
 * ridge == 0. */
std::vector<double> crossValidatedRms(std::vector<NormalEquations>& folds, const std::vector<int>& columns,
									  const std::vector<double>& ridges, double rank_tol = 1e-12);

}  // namespace mrpt_fog
