/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/WhitenedRegression.h>

#include <cmath>
#include <random>

using namespace mrpt_fog::discrepancy;

TEST(WhitenedRegression, Chi2SurvivalMatchesTables)
{
	// standard chi-square table values (e.g. Abramowitz & Stegun 26.4)
	EXPECT_NEAR(chi2Survival(3.841459, 1), 0.05, 1e-6);
	EXPECT_NEAR(chi2Survival(6.634897, 1), 0.01, 1e-6);
	EXPECT_NEAR(chi2Survival(9.210340, 2), 0.01, 1e-6);
	EXPECT_NEAR(chi2Survival(11.344867, 3), 0.01, 1e-6);
	EXPECT_NEAR(chi2Survival(2.0, 2), std::exp(-1.0), 1e-12);  // dof 2: exp(-x/2)
	EXPECT_DOUBLE_EQ(chi2Survival(0.0, 1), 1.0);
	EXPECT_GT(chi2Survival(300.0, 1), 0.0);
	EXPECT_LT(chi2Survival(300.0, 1), 1e-60);
}

TEST(WhitenedRegression, LeastSquaresRecoversCoefficientsAndHandlesRankDeficiency)
{
	Eigen::MatrixXd X(100, 3);
	Eigen::VectorXd y(100);
	for (int k = 0; k < 100; ++k)
	{
		const double t = k / 10.0;
		X.row(k) << 1.0, t, 1e4 * t * t;  // badly scaled column
		y(k) = 2.0 - 0.5 * t + 3e-4 * 1e4 * t * t;
	}
	const auto f = leastSquares(X, y, true);
	EXPECT_NEAR(f.coef(0), 2.0, 1e-9);
	EXPECT_NEAR(f.coef(1), -0.5, 1e-9);
	EXPECT_NEAR(f.coef(2), 3e-4, 1e-12);
	EXPECT_LT(f.rss, 1e-15);
	Eigen::MatrixXd Xd(100, 3);
	Xd << X.col(0), X.col(1), 2.0 * X.col(1);  // exactly collinear
	const auto g = leastSquares(Xd, y);
	EXPECT_EQ(g.rank, 2);
	EXPECT_TRUE(std::isfinite(g.rss));
}

TEST(WhitenedRegression, RemlRecoversArmaOfGaussMarkovPlusWhite)
{
	// AR(1) phi = 0.95 (sigma 1) + white (sigma 1) is ARMA(1,1) with theta ~ 0.74 (closed form:
	// theta / (1 + theta^2) = phi s_w^2 / (s_a^2 + (1 + phi^2) s_w^2), s_a^2 = 1 - phi^2)
	const double phi = 0.95;
	const double sa2 = 1 - phi * phi;
	const double r = phi / (sa2 + 1 + phi * phi);
	const double thetaTrue = (1 - std::sqrt(1 - 4 * r * r)) / (2 * r);
	std::mt19937_64 rng(7);
	std::normal_distribution<double> N(0, 1);
	const int n = 20000;
	Eigen::MatrixXd X = Eigen::MatrixXd::Ones(n, 1);
	Eigen::VectorXd y(n);
	double a = N(rng);
	for (int k = 0; k < n; ++k)
	{
		a = phi * a + std::sqrt(sa2) * N(rng);
		y(k) = 5.0 + a + N(rng);
	}
	std::vector<int> block(n, 0);
	std::vector<unsigned char> ok(n, 1);
	const auto rows = whitenableRows(block, ok, 0);
	const auto m = fitNoiseReml(X, y, rows, block);
	ASSERT_EQ(m.order(), 1);
	EXPECT_NEAR(m.phi[0], phi, 0.02);
	EXPECT_NEAR(m.theta, thetaTrue, 0.05);
	// whitened residual is close to white
	const Eigen::VectorXd e = whiten(y, m, rows, &block).col(0).array() - 5.0 * (1 - m.phi[0]);
	EXPECT_LT(longRunVarianceFactor(e, 30), 1.2);
}

TEST(WhitenedRegression, LongRunFactorOfWhiteNoiseIsAboutOne)
{
	std::mt19937_64 rng(3);
	std::normal_distribution<double> N(0, 1);
	Eigen::VectorXd e(5000);
	for (int k = 0; k < 5000; ++k) e(k) = N(rng);
	EXPECT_LT(longRunVarianceFactor(e, 30), 1.25);
	// strongly autocorrelated: large factor
	Eigen::VectorXd a(5000);
	double s = 0;
	for (int k = 0; k < 5000; ++k) a(k) = s = 0.9 * s + N(rng);
	EXPECT_GT(longRunVarianceFactor(a, 30), 5.0);
}

TEST(WhitenedRegression, WhitenableRowsRespectBlocksAndExclusions)
{
	const std::vector<int> block{0, 0, 0, 0, 1, 1, 1, -1, 2, 2};
	std::vector<unsigned char> ok{1, 1, 1, 1, 1, 1, 1, 0, 1, 1};
	ok[2] = 0;
	const auto r1 = whitenableRows(block, ok, 1);
	EXPECT_EQ(r1, (std::vector<std::size_t>{1, 5, 6, 9}));
	const auto r0 = whitenableRows(block, ok, 0);
	EXPECT_EQ(r0, (std::vector<std::size_t>{0, 1, 3, 4, 5, 6, 8, 9}));
}

TEST(WhitenedRegression, ArmaVarianceRatioClosedForm)
{
	ArNoiseModel m;
	m.phi = {0.5};
	m.theta = 0.0;
	EXPECT_NEAR(armaVarianceRatio(m), 1.0 / 0.75, 1e-12);  // AR(1): 1 / (1 - phi^2)
	m.theta = 0.5;
	EXPECT_NEAR(armaVarianceRatio(m), 1.0, 1e-12);  // theta = phi: white
}
