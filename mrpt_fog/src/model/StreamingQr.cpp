/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/StreamingQr.h>

#include <cmath>
#include <cstring>
#include <stdexcept>
#include <string>

namespace mrpt_fog
{
namespace
{
typedef double v4d __attribute__((vector_size(32)));

/** Householder QR of [R; A] in place (R: p x p column-major upper triangular, A: m x p
 * column-major with leading dimension ld, m a multiple of 4; A is destroyed). Column j's
 * reflector is H = I - tau v v' with v = [1 (row j of R); A(:, j) / v0]; it is applied to the
 * columns k > j four at a time (one pass for the four dot products, one for the updates) so that
 * each load of v serves four columns. Written with GCC vector types, compiled twice (AVX2/FMA and
 * the baseline) with the clone chosen at load time from the CPU. */
__attribute__((target_clones("arch=x86-64-v3", "default"))) void householderAbsorb(double* R, std::size_t p, double* A,
																					  std::size_t ld, std::size_t m)
{
#define FOG_LD(ptr) ({ v4d v_; std::memcpy(&v_, (ptr), sizeof v_); v_; })
#define FOG_ST(ptr, val) do { const v4d s_ = (val); std::memcpy((ptr), &s_, sizeof s_); } while (0)
	for (std::size_t j = 0; j < p; j++)
	{
		double* a = A + j * ld;
		v4d s = {0, 0, 0, 0};
		for (std::size_t i = 0; i < m; i += 4)
		{
			const v4d x = FOG_LD(a + i);
			s += x * x;
		}
		const double sigma = (s[0] + s[1]) + (s[2] + s[3]);
		if (sigma == 0.0) continue;  // nothing below the diagonal: H = I
		double& rjj = R[j + j * p];
		const double alpha = rjj;
		const double norm = std::sqrt(alpha * alpha + sigma);
		const double beta = alpha > 0 ? -norm : norm;
		const double v0 = alpha - beta;  // |v0| >= norm > 0
		const double tau = -v0 / beta;
		const double inv_v0 = 1.0 / v0;
		const v4d iv = {inv_v0, inv_v0, inv_v0, inv_v0};
		for (std::size_t i = 0; i < m; i += 4) FOG_ST(a + i, FOG_LD(a + i) * iv);
		rjj = beta;
		std::size_t k = j + 1;
		for (; k + 4 <= p; k += 4)
		{
			double* b0 = A + k * ld;
			double* b1 = b0 + ld;
			double* b2 = b1 + ld;
			double* b3 = b2 + ld;
			v4d w0 = {0, 0, 0, 0}, w1 = w0, w2 = w0, w3 = w0;
			for (std::size_t i = 0; i < m; i += 4)
			{
				const v4d x = FOG_LD(a + i);
				w0 += x * FOG_LD(b0 + i);
				w1 += x * FOG_LD(b1 + i);
				w2 += x * FOG_LD(b2 + i);
				w3 += x * FOG_LD(b3 + i);
			}
			double* r0 = R + j + k * p;
			const double t0 = tau * (r0[0] + (w0[0] + w0[1]) + (w0[2] + w0[3]));
			const double t1 = tau * (r0[p] + (w1[0] + w1[1]) + (w1[2] + w1[3]));
			const double t2 = tau * (r0[2 * p] + (w2[0] + w2[1]) + (w2[2] + w2[3]));
			const double t3 = tau * (r0[3 * p] + (w3[0] + w3[1]) + (w3[2] + w3[3]));
			r0[0] -= t0;
			r0[p] -= t1;
			r0[2 * p] -= t2;
			r0[3 * p] -= t3;
			const v4d T0 = {t0, t0, t0, t0}, T1 = {t1, t1, t1, t1}, T2 = {t2, t2, t2, t2}, T3 = {t3, t3, t3, t3};
			for (std::size_t i = 0; i < m; i += 4)
			{
				const v4d x = FOG_LD(a + i);
				FOG_ST(b0 + i, FOG_LD(b0 + i) - T0 * x);
				FOG_ST(b1 + i, FOG_LD(b1 + i) - T1 * x);
				FOG_ST(b2 + i, FOG_LD(b2 + i) - T2 * x);
				FOG_ST(b3 + i, FOG_LD(b3 + i) - T3 * x);
			}
		}
		for (; k < p; k++)
		{
			double* b0 = A + k * ld;
			v4d w0 = {0, 0, 0, 0};
			for (std::size_t i = 0; i < m; i += 4) w0 += FOG_LD(a + i) * FOG_LD(b0 + i);
			double& r0 = R[j + k * p];
			const double t0 = tau * (r0 + (w0[0] + w0[1]) + (w0[2] + w0[3]));
			r0 -= t0;
			const v4d T0 = {t0, t0, t0, t0};
			for (std::size_t i = 0; i < m; i += 4) FOG_ST(b0 + i, FOG_LD(b0 + i) - T0 * FOG_LD(a + i));
		}
	}
#undef FOG_LD
#undef FOG_ST
}

std::size_t roundUp4(std::size_t m) { return (m + 3) / 4 * 4; }
}  // namespace

void absorbRowsIntoR(Eigen::MatrixXd& r, double* block, std::size_t ld, std::size_t m)
{
	if (r.rows() != r.cols()) throw std::invalid_argument("absorbRowsIntoR: R is not square");
	if (m % 4 != 0 || ld < m) throw std::invalid_argument("absorbRowsIntoR: rows must be a multiple of 4, <= ld");
	householderAbsorb(r.data(), static_cast<std::size_t>(r.rows()), block, ld, m);
}

StreamingQr::StreamingQr(std::size_t n, double y_ref, const std::vector<double>& x_ref) : n_(n), p_(n + 1), y_ref_(y_ref)
{
	if (!x_ref.empty() && x_ref.size() != n) throw std::invalid_argument("StreamingQr: x_ref size differs from the term count");
	if (!std::isfinite(y_ref)) throw std::invalid_argument("StreamingQr: y_ref is not finite");
	x_ref_ = x_ref.empty() ? std::vector<double>(n, 0.0) : x_ref;
	if (n > 0) x_ref_[0] = 0.0;
	for (double v : x_ref_)
		if (!std::isfinite(v)) throw std::invalid_argument("StreamingQr: x_ref is not finite");
	r_.setZero(static_cast<Eigen::Index>(p_), static_cast<Eigen::Index>(p_));
	block_.assign(kBlock * p_, 0.0);
}

void StreamingQr::add(const double* f, double y)
{
	double* row = block_.data() + in_block_;
	double sum = y;  // NaN or inf anywhere makes the sum non-finite: one test per row
	for (std::size_t j = 0; j < n_; j++)
	{
		sum += f[j];
		row[j * kBlock] = f[j] - x_ref_[j];
	}
	if (!std::isfinite(sum))
	{
		if (!std::isfinite(y)) throw std::invalid_argument("StreamingQr::add: response is not finite");
		for (std::size_t j = 0; j < n_; j++)
			if (!std::isfinite(f[j]))
				throw std::invalid_argument("StreamingQr::add: feature " + std::to_string(j) + " is not finite");
		// finite values whose sum overflowed: accepted (the row is not stored until here)
	}
	row[n_ * kBlock] = y - y_ref_;
	if (++in_block_ == kBlock) flush();
}

void StreamingQr::flush()
{
	if (in_block_ == 0) return;
	const std::size_t m = roundUp4(in_block_);
	for (std::size_t j = 0; j < p_; j++)
		for (std::size_t i = in_block_; i < m; i++) block_[j * kBlock + i] = 0.0;  // zero rows change nothing
	householderAbsorb(r_.data(), p_, block_.data(), kBlock, m);
	count_ += in_block_;
	in_block_ = 0;
	for (std::size_t j = 0; j < p_; j++)
		if (!std::isfinite(r_(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(j))))
			throw std::overflow_error("StreamingQr: the factor overflowed (features or response far too large)");
}

void StreamingQr::merge(const StreamingQr& o_in)
{
	if (o_in.n_ != n_ || o_in.y_ref_ != y_ref_ || o_in.x_ref_ != x_ref_)
		throw std::invalid_argument("StreamingQr::merge: different size or reference");
	StreamingQr o = o_in;
	o.flush();
	flush();
	const std::size_t m = roundUp4(p_);
	std::vector<double> a(m * p_, 0.0);
	for (std::size_t k = 0; k < p_; k++)
		for (std::size_t i = 0; i <= k; i++) a[k * m + i] = o.r_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k));
	householderAbsorb(r_.data(), p_, a.data(), m, m);
	count_ += o.count_;
}

const Eigen::MatrixXd& StreamingQr::r()
{
	flush();
	return r_;
}

void StreamingQr::flipResiduals(const Eigen::VectorXd& beta)
{
	if (static_cast<std::size_t>(beta.size()) != n_)
		throw std::invalid_argument("StreamingQr::flipResiduals: beta has " + std::to_string(beta.size()) + " terms, not " +
									std::to_string(n_));
	flush();
	const auto n = static_cast<Eigen::Index>(n_);
	Eigen::MatrixXd a = r_;
	a.col(n) = 2.0 * (a.leftCols(n) * beta) - a.col(n);
	Eigen::HouseholderQR<Eigen::MatrixXd> qr(a);
	r_ = qr.matrixQR().triangularView<Eigen::Upper>();
}

Eigen::MatrixXd StreamingQr::columnsR(const std::vector<int>& cols)
{
	flush();
	const std::size_t c = cols.size() + 1, m = roundUp4(p_);
	std::vector<double> a(m * c, 0.0);
	for (std::size_t k = 0; k < c; k++)
	{
		const std::size_t src = k + 1 < c ? static_cast<std::size_t>(cols[k]) : n_;
		if (k + 1 < c && (cols[k] < 0 || src >= n_))
			throw std::invalid_argument("StreamingQr::columnsR: column " + std::to_string(cols[k]) + " out of range");
		for (std::size_t i = 0; i <= src; i++) a[k * m + i] = r_(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(src));
	}
	Eigen::MatrixXd out = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(c), static_cast<Eigen::Index>(c));
	householderAbsorb(out.data(), c, a.data(), m, m);
	return out;
}

Eigen::MatrixXd StreamingQr::xtx()
{
	flush();
	const auto n = static_cast<Eigen::Index>(n_);
	const Eigen::MatrixXd Rx = r_.topLeftCorner(n, n).triangularView<Eigen::Upper>();
	return Rx.transpose() * Rx;
}

}  // namespace mrpt_fog
