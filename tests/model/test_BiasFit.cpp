/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/model/BiasFit.h>

#include <cstdio>
#include <limits>
#include <random>

using namespace mrpt_fog;

namespace
{
/** Random design: constant + 6 features in [-1, 1] (two of them correlated), y = X b + noise. */
struct Problem
{
	Eigen::MatrixXd X;
	Eigen::VectorXd y, b;
};
Problem makeProblem(int n, double noise, unsigned seed)
{
	std::mt19937 rng(seed);
	std::uniform_real_distribution<double> u(-1, 1);
	std::normal_distribution<double> nd(0, 1);
	Problem p;
	p.X.resize(n, 7);
	p.b.resize(7);
	p.b << 1.5, 0.3, -0.2, 0.05, 0.8, -0.4, 0.01;
	for (int i = 0; i < n; i++)
	{
		const double z = u(rng);
		p.X.row(i) << 1, z, z * z, z * z * z, u(rng), 0.9 * z + 0.1 * u(rng), u(rng) * u(rng);
	}
	p.y = p.X * p.b;
	for (int i = 0; i < n; i++) p.y[i] += noise * nd(rng);
	return p;
}
StreamingQr accumulate(const Problem& p, int from, int to, double y_ref)
{
	StreamingQr ne(static_cast<std::size_t>(p.X.cols()), y_ref);
	for (int i = from; i < to; i++)
	{
		const Eigen::VectorXd row = p.X.row(i).transpose();
		ne.add(row.data(), p.y[i]);
	}
	return ne;
}
const std::vector<int> kAll = {0, 1, 2, 3, 4, 5, 6};
/** The reference for the cross-validation tests: the least-squares fit on the rows of all folds
 * but `f` (2000 rows in 4 folds of 500), by a dense QR of its own. */
Eigen::VectorXd refitWithoutFold(const Problem& p, int f)
{
	Eigen::MatrixXd Xt(1500, p.X.cols());
	Eigen::VectorXd yt(1500);
	int r = 0;
	for (int i = 0; i < 2000; i++)
		if (i / 500 != f)
		{
			Xt.row(r) = p.X.row(i);
			yt[r++] = p.y[i];
		}
	return Xt.colPivHouseholderQr().solve(yt);
}
}  // namespace

// Reference: Householder QR least squares on the stored matrix (Eigen), and the classical
// covariance sigma^2 (X'X)^-1 with sigma^2 = SSE / (n - p).
TEST(BiasFit, MatchesQrLeastSquaresAndCovariance)
{
	const auto p = makeProblem(5000, 0.01, 3);
	auto ne = accumulate(p, 0, 5000, 1.4);
	const LinearFit fit = solveBiasFit(ne, kAll);
	const Eigen::VectorXd ref = p.X.colPivHouseholderQr().solve(p.y);
	for (int j = 0; j < 7; j++) EXPECT_NEAR(fit.coef_dph[j], ref[j], 1e-9 * (1 + std::abs(ref[j]))) << j;
	const Eigen::VectorXd r = p.y - p.X * ref;
	const double sigma2 = r.squaredNorm() / (5000 - 7);
	const Eigen::MatrixXd cov = sigma2 * (p.X.transpose() * p.X).inverse();
	EXPECT_LT((fit.covariance - cov).norm(), 1e-7 * cov.norm());
	EXPECT_NEAR(fit.rms_dph, std::sqrt(r.squaredNorm() / 5000), 1e-9);
	EXPECT_EQ(fit.numerical_rank, 7u);
	EXPECT_NEAR(fit.effective_dof, 7.0, 1e-12);
	EXPECT_NEAR(fit.residual_mean_dph, r.mean(), 1e-9);
	EXPECT_GT(fit.condition_number, 1.0);
	// recovered truth within 5 sigma (the noise is the only error source)
	for (int j = 0; j < 7; j++) EXPECT_NEAR(fit.coef_dph[j], p.b[j], 5 * std::sqrt(cov(j, j))) << j;
}

TEST(BiasFit, MergeEqualsSingleAccumulatorAndSubsetsWork)
{
	const auto p = makeProblem(3000, 0.02, 4);
	auto all = accumulate(p, 0, 3000, 0.0);
	auto a = accumulate(p, 0, 1000, 0.0), b = accumulate(p, 1000, 3000, 0.0);
	a.merge(b);
	EXPECT_EQ(a.count(), 3000u);
	EXPECT_LT((a.xtx() - all.xtx()).norm(), 1e-9 * all.xtx().norm());
	const std::vector<int> sub = {0, 1, 4};
	const LinearFit f = solveBiasFit(a, sub);
	Eigen::MatrixXd Xs(3000, 3);
	Xs << p.X.col(0), p.X.col(1), p.X.col(4);
	const Eigen::VectorXd ref = Xs.colPivHouseholderQr().solve(p.y);
	for (int j = 0; j < 3; j++) EXPECT_NEAR(f.coef_dph[j], ref[j], 1e-9) << j;
}

// Held-out RMS from the folds' sums equals explicit refits on stored data.
TEST(BiasFit, CrossValidationMatchesExplicitRefits)
{
	const auto p = makeProblem(2000, 0.05, 5);
	std::vector<StreamingQr> folds;
	for (int f = 0; f < 4; f++) folds.push_back(accumulate(p, f * 500, (f + 1) * 500, 1.0));
	const auto cv = crossValidatedRms(folds, kAll, {0.0});
	double sse = 0;
	for (int f = 0; f < 4; f++)
	{
		const Eigen::VectorXd b = refitWithoutFold(p, f);
		sse += (p.y.segment(f * 500, 500) - p.X.middleRows(f * 500, 500) * b).squaredNorm();
	}
	EXPECT_NEAR(cv[0], std::sqrt(sse / 2000), 1e-9);
}

// Held-out SSE per block (crossValidatedBlockSse): each block of a fold predicted by an explicit
// refit on the other folds' stored rows; summed over a fold's blocks it is that fold's SSE.
TEST(BiasFit, BlockSseMatchesExplicitRefitsPerBlock)
{
	const auto p = makeProblem(2000, 0.05, 6);
	std::vector<StreamingQr> folds;
	std::vector<std::vector<StreamingQr>> units(4);
	for (int f = 0; f < 4; f++)
	{
		folds.push_back(accumulate(p, f * 500, (f + 1) * 500, 1.0));
		for (int u = 0; u < 5; u++) units[f].push_back(accumulate(p, f * 500 + u * 100, f * 500 + (u + 1) * 100, 1.0));
	}
	auto training = trainingSets(folds);
	const auto block = crossValidatedBlockSse(training, units, kAll, {0.0, 1e-3});
	const auto fold = crossValidatedFoldSse(folds, training, kAll, {0.0, 1e-3});
	ASSERT_EQ(block.size(), 2u);
	for (int f = 0; f < 4; f++)
	{
		const Eigen::VectorXd b = refitWithoutFold(p, f);
		for (int u = 0; u < 5; u++)
		{
			const int from = f * 500 + u * 100;
			const double ref = (p.y.segment(from, 100) - p.X.middleRows(from, 100) * b).squaredNorm();
			EXPECT_NEAR(block[0][f][u], ref, 1e-9 * (1 + ref)) << f << " " << u;
		}
		for (int ridge = 0; ridge < 2; ridge++)
		{
			double sum = 0;
			for (double x : block[ridge][f]) sum += x;
			EXPECT_NEAR(sum, fold[ridge][f], 1e-9 * (1 + fold[ridge][f])) << f;
		}
	}
}

TEST(BiasFit, RidgeShrinksAndKeepsMean)
{
	const auto p = makeProblem(2000, 0.05, 6);
	auto ne = accumulate(p, 0, 2000, 0.0);
	const LinearFit f0 = solveBiasFit(ne, kAll, 0.0), f1 = solveBiasFit(ne, kAll, 0.1);
	EXPECT_LT(f1.coef_dph.tail(6).norm(), f0.coef_dph.tail(6).norm());
	EXPECT_LT(f1.effective_dof, 7.0);
	EXPECT_NEAR(f1.residual_mean_dph, 0.0, 1e-12);  // the constant is not penalised
	EXPECT_GT(f1.rms_dph, f0.rms_dph);
}

// The streaming factor equals a dense Householder QR of the stored [X | y] up to row signs
// (R'R = [X y]'[X y] and |diag R| equal), whatever the block boundaries: 1000 rows = 7 full
// blocks of 128 + 104, and the same rows added as 3 merged pieces.
TEST(StreamingQr, FactorEqualsDenseQrAndMergeIsExact)
{
	const auto p = makeProblem(1000, 0.01, 7);
	auto one = accumulate(p, 0, 1000, 0.0);
	auto a = accumulate(p, 0, 333, 0.0), b = accumulate(p, 333, 900, 0.0), c = accumulate(p, 900, 1000, 0.0);
	a.merge(b);
	a.merge(c);
	Eigen::MatrixXd Xy(1000, 8);
	Xy << p.X, p.y;
	const Eigen::MatrixXd Rd = Xy.householderQr().matrixQR().topRows(8).triangularView<Eigen::Upper>();
	for (auto* acc : {&one, &a})
	{
		const Eigen::MatrixXd& R = acc->r();
		EXPECT_EQ(acc->count(), 1000u);
		EXPECT_LT((R.transpose() * R - Xy.transpose() * Xy).norm(), 1e-12 * (Xy.transpose() * Xy).norm());
		for (int j = 0; j < 8; j++) EXPECT_NEAR(std::abs(R(j, j)), std::abs(Rd(j, j)), 1e-12 * Rd.norm()) << j;
		EXPECT_TRUE(R.isUpperTriangular(0.0));
	}
	// the residual of any coefficient vector from the factor
	Eigen::VectorXd b0(7);
	b0 << 1, -1, 0.5, 0.25, 0, 2, -3;
	EXPECT_NEAR(residualSumOfSquares(one, kAll, b0), (p.y - p.X * b0).squaredNorm(), 1e-12 * (p.y - p.X * b0).squaredNorm());
	// bad input
	StreamingQr other(6, 0.0);
	EXPECT_THROW(one.merge(other), std::invalid_argument);
	EXPECT_THROW(one.columnsR({0, 7}), std::invalid_argument);
	EXPECT_THROW(StreamingQr(3, 0.0, {0.0, 1.0}), std::invalid_argument);
}

// Ill-conditioned design (monomials 1, z..z^12 of z in [0, 1], cond(X) ~ 1e8-1e9) with an exactly
// known truth (noise-free y = X b): a backward-stable solver recovers b to a norm-wise relative
// error of order cond(X) x eps; the streaming QR must stay within 10 cond(X) eps. Normal
// equations (the previous method) square the condition number: their error is printed for
// comparison and must exceed the QR error by far.
TEST(BiasFit, IllConditionedDesignWithinCondTimesEps)
{
	const int n = 20000, p = 13;
	std::mt19937 rng(8);
	std::uniform_real_distribution<double> u(0, 1);
	Eigen::MatrixXd X(n, p);
	Eigen::VectorXd b(p);
	for (int j = 0; j < p; j++) b[j] = (j % 2 ? -1.0 : 1.0) * (1 + 0.1 * j);
	for (int i = 0; i < n; i++)
	{
		const double z = u(rng);
		double zk = 1;
		for (int j = 0; j < p; j++, zk *= z) X(i, j) = zk;
	}
	const Eigen::VectorXd y = X * b;
	Eigen::JacobiSVD<Eigen::MatrixXd> svd(X);
	const double cond = svd.singularValues()(0) / svd.singularValues()(p - 1);
	EXPECT_GT(cond, 1e7);  // the test must be ill-conditioned to mean anything
	StreamingQr acc(p, 0.0);
	for (int i = 0; i < n; i++)
	{
		const Eigen::VectorXd row = X.row(i).transpose();
		acc.add(row.data(), y[i]);
	}
	std::vector<int> cols(p);
	for (int j = 0; j < p; j++) cols[j] = j;
	const LinearFit fit = solveBiasFit(acc, cols);
	ASSERT_EQ(fit.numerical_rank, static_cast<std::size_t>(p));
	const double eps = std::numeric_limits<double>::epsilon();
	const double err_qr = (fit.coef_dph - b).norm() / b.norm();
	const Eigen::VectorXd b_ne = (X.transpose() * X).ldlt().solve(X.transpose() * y);
	const double err_ne = (b_ne - b).norm() / b.norm();
	std::printf("  cond(X) %.3g: streaming QR error %.3g (%.3g cond eps), normal equations %.3g\n", cond, err_qr,
				err_qr / (cond * eps), err_ne);
	EXPECT_LE(err_qr, 10 * cond * eps);
	EXPECT_GT(err_ne, 100 * err_qr);
	EXPECT_LT(fit.rms_dph, 1e-9);
}

// A duplicated feature is detected: numerical rank below the column count.
TEST(BiasFit, RankDeficiencyAndBadInput)
{
	StreamingQr ne(3, 0.0);
	std::mt19937 rng(1);
	std::uniform_real_distribution<double> u(-1, 1);
	for (int i = 0; i < 100; i++)
	{
		const double z = u(rng), f[3] = {1, z, z};
		ne.add(f, 2 * z);
	}
	const LinearFit f = solveBiasFit(ne, {0, 1, 2});
	EXPECT_EQ(f.numerical_rank, 2u);
	EXPECT_NEAR(f.coef_dph[1] + f.coef_dph[2], 2.0, 1e-9);  // minimum-norm solution
	StreamingQr empty(3, 0.0);
	EXPECT_THROW(solveBiasFit(empty, {0, 1}), std::invalid_argument);
	EXPECT_THROW(solveBiasFit(ne, {1, 2}), std::invalid_argument);  // no constant
	EXPECT_THROW(solveBiasFit(ne, {0, 3}), std::invalid_argument);
	const double bad[3] = {1, std::nan(""), 0};
	EXPECT_THROW(ne.add(bad, 0), std::invalid_argument);
	// a constant feature has zero variance: rank loss
	StreamingQr c(2, 0.0);
	for (int i = 0; i < 50; i++)
	{
		const double g[2] = {1, 0.5};
		c.add(g, 1.0);
	}
	EXPECT_EQ(solveBiasFit(c, {0, 1}).numerical_rank, 1u);
}
