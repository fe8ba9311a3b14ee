/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file StreamingQr.h
 * Streaming QR factorisation of a least-squares design, memory independent of the row count.
 *
 * Holds R, the (n+1) x (n+1) upper-triangular factor of the augmented design [X | y] of all rows
 * added so far (X: n features, y: response), with Q never formed: [X | y] = Q R. Rows are
 * buffered in blocks of kBlock and absorbed by Householder reflections of the stacked matrix
 * [R; block] (the triangle is kept, so each block costs 2 (n+1)^2 flops per row), a kernel
 * compiled for AVX2/FMA when the CPU has it (runtime dispatch) and for SSE2 otherwise. This is
 * orthogonal-transformation least squares: the accuracy of the coefficients degrades like
 * cond(X) x eps, not cond(X)^2 x eps as with normal equations.
 *
 * What R gives (see BiasFit.h): the last column holds Q'y, and R(n, n)^2 is the residual sum of
 * squares of the full least-squares fit; the residual of ANY coefficient vector b over the
 * accumulated rows is || R [-b; 1] || (no cancellation of y'y - 2 b'X'y + b'X'X b); the factor
 * of a column subset is the QR of those columns of R; two accumulators merge by the QR of
 * [R1; R2]. Features are shifted by x_ref and y by y_ref (e.g. their means) before they enter.
 */

#include <Eigen/Dense>

#include <cstddef>
#include <vector>

namespace mrpt_fog
{
class StreamingQr
{
   public:
	StreamingQr() = default;
	/** x_ref (optional, size n_terms): feature references; entry 0 (the constant) is ignored. */
	StreamingQr(std::size_t n_terms, double y_ref_dph, const std::vector<double>& x_ref = {});
	/** Adds one row (features f[0..n), response y [deg/h]). Throws std::invalid_argument on a
	 * non-finite value, naming the column (rows with dropouts must be filtered by the caller). */
	void add(const double* f, double y_dph);
	/** Adds the rows of another accumulator of the same size and references (else throws
	 * std::invalid_argument). */
	void merge(const StreamingQr& other);
	/** Absorbs buffered rows (the accessors below call it). */
	void flush();

	std::size_t terms() const { return n_; }
	std::size_t count() const { return count_ + in_block_; }
	double yRef() const { return y_ref_; }
	const std::vector<double>& xRef() const { return x_ref_; }

	/** R of the shifted augmented rows [x - x_ref, y - y_ref]: (n+1) x (n+1), upper triangular,
	 * column n = Q'(y - y_ref). Signs of rows are arbitrary (R'R is what is defined). */
	const Eigen::MatrixXd& r();
	/** R of [X(:, columns) | y] of the shifted rows, (columns.size()+1) square (throws
	 * std::invalid_argument for a column out of range). */
	Eigen::MatrixXd columnsR(const std::vector<int>& columns);
	/** Wild (sign-flip) bootstrap of the rows: every response y becomes 2 x'beta - y, i.e. the
	 * residual about the linear model beta (all terms, shifted coordinates: y - y_ref =
	 * (x - x_ref)'beta) changes sign while the rows' features stay. Exact on the factor (R is
	 * linear in the rows); the row count is kept. */
	void flipResiduals(const Eigen::VectorXd& beta);
	/** X'X of the shifted rows (= R'R; for tests and diagnostics). */
	Eigen::MatrixXd xtx();

	static constexpr std::size_t kBlock = 128;  //!< rows per absorbed block

   private:
	std::size_t n_ = 0, p_ = 0;  // terms, augmented width n + 1
	double y_ref_ = 0.0;
	std::vector<double> x_ref_;
	std::size_t count_ = 0;
	Eigen::MatrixXd r_;  // p x p upper triangular
	std::vector<double> block_;  // column-major kBlock x p (column j = feature j of the rows)
	std::size_t in_block_ = 0;
};

/** Absorbs the m rows of `block` (column-major, leading dimension ld, p columns; overwritten)
 * into the p x p upper-triangular `r` by Householder reflections of [r; block]. Exposed for
 * tests; m must be a multiple of 4 (pad with zero rows, which change nothing). */
void absorbRowsIntoR(Eigen::MatrixXd& r, double* block, std::size_t ld, std::size_t m);

}  // namespace mrpt_fog
