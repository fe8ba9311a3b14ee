/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/EffectSelector.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
using Mat = Eigen::MatrixXd;
using Vec = Eigen::VectorXd;

const char* toString(CandidateStatus s)
{
	static const char* const kSpelling[] = {"tested", "spanned", "untestable"};  // enumerator order
	return kSpelling[static_cast<int>(s)];
}

CandidateContext makeCandidateContext(const RunSignals& sig, const BaseDesign& base, const Vec& base_coef)
{
	CandidateContext ctx;
	ctx.sig = &sig;
	const auto n = static_cast<Eigen::Index>(sig.size());
	ctx.base_static_dph.assign(sig.size(), 0.0);
	for (Eigen::Index j = 0; j < base.X.cols() && j < base_coef.size(); ++j)
		if (base.is_static_temp[static_cast<std::size_t>(j)])
			for (Eigen::Index k = 0; k < n; ++k) ctx.base_static_dph[static_cast<std::size_t>(k)] += base.X(k, j) * base_coef(j);
	// a base without any static temperature term is tested for the linear term first (powers 1, 2)
	ctx.base_static_order = base.max_static_order;
	ctx.static_temp_C = base.static_temp_C.empty() ? sig.temp_mean_C : base.static_temp_C;
	return ctx;
}

Mat AugmentedModel::design(const BaseDesign& base, const RunSignals& sig) const
{
	const auto ctx = makeCandidateContext(sig, base, lag_base_coef);
	std::vector<Mat> blocks{base.X};
	Eigen::Index cols = base.X.cols();
	for (const auto& e : effects)
	{
		blocks.push_back(candidateById(e.id).build(ctx, e.theta));
		cols += blocks.back().cols();
	}
	Mat X(base.X.rows(), cols);
	Eigen::Index c = 0;
	for (const auto& b : blocks)
	{
		X.middleCols(c, b.cols()) = b;
		c += b.cols();
	}
	return X;
}

namespace
{
std::vector<std::size_t> rowsOf(const std::vector<unsigned char>& ok)
{
	std::vector<std::size_t> r;
	for (std::size_t k = 0; k < ok.size(); ++k)
		if (ok[k]) r.push_back(k);
	return r;
}

Mat pick(const Mat& M, const std::vector<std::size_t>& rows)
{
	Mat out(static_cast<Eigen::Index>(rows.size()), M.cols());
	for (std::size_t i = 0; i < rows.size(); ++i) out.row(static_cast<Eigen::Index>(i)) = M.row(static_cast<Eigen::Index>(rows[i]));
	return out;
}

Mat hcat(const Mat& a, const Mat& b)
{
	Mat m(a.rows(), a.cols() + b.cols());
	m << a, b;
	return m;
}

Vec yVector(const RunSignals& sig)
{
	Vec y(static_cast<Eigen::Index>(sig.size()));
	for (std::size_t k = 0; k < sig.size(); ++k) y(static_cast<Eigen::Index>(k)) = sig.bias_dph[k];
	return y;
}

/** OLS on rows, residual on every sample. */
LsFit olsOnRows(const Mat& X, const Vec& y, const std::vector<std::size_t>& rows, Vec& fullResidual)
{
	const Mat Xr = pick(X, rows);
	Vec yr(static_cast<Eigen::Index>(rows.size()));
	for (std::size_t i = 0; i < rows.size(); ++i) yr(static_cast<Eigen::Index>(i)) = y(static_cast<Eigen::Index>(rows[i]));
	auto f = leastSquares(Xr, yr);
	fullResidual = y - X * f.coef;
	return f;
}

/** Relative projection residual of the (centred) columns of C onto X, on rows: the largest
 * over C's columns. */
double spanResidual(const Mat& X, const Mat& C, const std::vector<std::size_t>& rows)
{
	const Mat Xr = pick(X, rows), Cr = pick(C, rows);
	double worst = 0.0;
	for (Eigen::Index j = 0; j < Cr.cols(); ++j)
	{
		const Vec c = Cr.col(j);
		const double spread = (c.array() - c.mean()).matrix().norm();
		if (spread <= 1e-12 * std::max(1.0, c.norm())) continue;  // constant: spanned by the offset
		const auto f = leastSquares(Xr, c);
		worst = std::max(worst, std::sqrt(f.rss) / spread);
	}
	return worst;
}

/** Feasible GLS fit of one model: ARMA(1,1) noise model by REML for this very design, then
 * whitened LS on the common rows. */
struct Gls
{
	ArNoiseModel ar;
	LsFit fit;  //!< whitened LS (coef, whitened residual, cov when asked)
	double rss = 0.0;
	double lrv = 1.0;
	double sigma2 = 1.0;  //!< whitened residual variance (dof-corrected)
};

Gls glsFit(const Mat& X, const Vec& y, const std::vector<std::size_t>& common, const std::vector<int>& block,
		   const SelectionOptions& opt, bool wantCov = false, const ArNoiseModel* start = nullptr)
{
	Gls g;
	g.ar = fitNoiseReml(X, y, common, block, start);
	g.fit = leastSquares(whiten(X, g.ar, common, &block), whiten(y, g.ar, common, &block).col(0), wantCov);
	g.rss = g.fit.rss;
	g.sigma2 = g.rss / std::max(1.0, double(common.size()) - g.fit.rank);
	g.lrv = longRunVarianceFactor(g.fit.residual, opt.lrv_max_lag);
	return g;
}

/** x with chi2Survival(x, dof) = p (bisection). */
double chi2Quantile(double p, double dof)
{
	double lo = 0.0, hi = 10.0 * dof + 100.0;
	while (chi2Survival(hi, dof) > p) hi *= 2.0;
	for (int it = 0; it < 200; ++it)
	{
		const double mid = 0.5 * (lo + hi);
		(chi2Survival(mid, dof) > p ? lo : hi) = mid;
	}
	return 0.5 * (lo + hi);
}

/** CandidateTest::detectable_rms_dph: with G the covariance of C beyond X (unwhitened, on the
 * common rows) and A = (W C)' M (W C) (whitened, beyond W X), a contribution C b gives the
 * expected chi-square b'A b / (sigma2 lrv) and RMS sqrt(b'G b); the smallest RMS reaching the
 * threshold is sqrt(chi2* sigma2 lrv lambda_min(G, A)). */
double detectableRms(const Mat& X, const Mat& C, const Vec& y, const std::vector<std::size_t>& common,
					 const std::vector<int>& block, const Gls& g0, const SelectionOptions& opt, std::size_t m,
					 std::size_t grid, double nEff)
{
	(void)y;
	const double q = static_cast<double>(C.cols());
	const double level = opt.alpha / std::max<double>(1.0, static_cast<double>(m) * static_cast<double>(std::max<std::size_t>(grid, 1)));
	const double chi2star =
		std::max(chi2Quantile(level, q), q * std::log(nEff) + std::log(static_cast<double>(std::max<std::size_t>(grid, 1))));
	const Mat Xr = pick(X, common), Cr = pick(C, common);
	Mat R(Cr.rows(), Cr.cols());
	for (Eigen::Index j = 0; j < Cr.cols(); ++j) R.col(j) = leastSquares(Xr, Cr.col(j)).residual;
	const Mat G = R.transpose() * R / std::max(1.0, static_cast<double>(common.size()));
	const Mat WX = whiten(X, g0.ar, common, &block), WC = whiten(C, g0.ar, common, &block);
	Mat RW(WC.rows(), WC.cols());
	for (Eigen::Index j = 0; j < WC.cols(); ++j) RW.col(j) = leastSquares(WX, WC.col(j)).residual;
	const Mat A = RW.transpose() * RW;
	// min b'G b / b'A b: the smallest generalized eigenvalue (A regularised against a column the
	// model spans in whitened terms)
	const Mat Areg = A + 1e-12 * std::max(1e-300, A.trace()) * Mat::Identity(A.rows(), A.cols());
	Eigen::GeneralizedSelfAdjointEigenSolver<Mat> es(G, Areg);
	if (es.info() != Eigen::Success) return std::numeric_limits<double>::quiet_NaN();
	const double lmin = std::max(0.0, es.eigenvalues().minCoeff());
	return std::sqrt(chi2star * g0.sigma2 * g0.lrv * lmin);
}

/** Wald chi-square of the columns model 1 has beyond `Xsub`, with model 1's noise model:
 * (RSS_sub - RSS_1) / (sigma2_1 x long-run factor), both whitened alike. */
double waldChi2(const Mat& Xsub, const Gls& m1, const Vec& y, const std::vector<std::size_t>& common,
				const std::vector<int>& block)
{
	const double rss0 = leastSquares(whiten(Xsub, m1.ar, common, &block), whiten(y, m1.ar, common, &block).col(0)).rss;
	return std::max(0.0, (rss0 - m1.rss) / (m1.sigma2 * m1.lrv));
}

/** How well the columns of B reproduce the named effect's fitted shape A beta_A, after
 * whitening and projecting out X: the correlation of that shape with its projection on B's
 * columns (for a one-column A this is the largest canonical correlation of A and B; for a
 * several-column A it asks about the shape the data chose, so a candidate that merely shares
 * one of A's columns is not called a look-alike of a shape it cannot reproduce). */
double shapeReproduction(const Mat& X, const Mat& A, const Vec& betaA, const Mat& B, const ArNoiseModel& ar,
						 const std::vector<std::size_t>& common, const std::vector<int>& block)
{
	const Mat Xw = whiten(X, ar, common, &block);
	auto residualised = [&](const Mat& M)
	{
		const Mat Mw = whiten(M, ar, common, &block);
		Mat R(Mw.rows(), Mw.cols());
		for (Eigen::Index j = 0; j < Mw.cols(); ++j) R.col(j) = leastSquares(Xw, Mw.col(j)).residual;
		return R;
	};
	const Mat Ra = residualised(A), Rb = residualised(B);
	const Vec a = Ra * betaA;
	if (!(a.norm() > 0) || !(Rb.norm() > 0)) return 0.0;
	const Vec r = leastSquares(Rb, a).residual;
	return std::sqrt(std::max(0.0, 1.0 - r.squaredNorm() / a.squaredNorm()));
}

double sidak(double p, int tests)
{
	if (tests <= 1) return p;
	return -std::expm1(tests * std::log1p(-std::min(p, 1.0 - 1e-16)));
}

struct CandState
{
	const CandidateEffect* eff = nullptr;
	std::vector<double> thetas;  //!< non-spanned grid values
	double theta = 0;
	Mat C;  //!< chosen columns
	CandidateTest test;
};

/** Outlier flags: robust z of the AR-whitened base residual. */
std::size_t flagOutliers(const Mat& X, const Vec& y, const RunSignals& sig, std::vector<unsigned char>& ok,
						 const SelectionOptions& opt)
{
	std::size_t flagged = 0;
	for (int pass = 0; pass < 2; ++pass)
	{
		Vec r;
		olsOnRows(X, y, rowsOf(ok), r);
		std::vector<double> rv(r.data(), r.data() + r.size());
		const auto ar = fitArNoise(rv, sig.block, ok, opt.max_ar_order);
		const auto rows = whitenableRows(sig.block, ok, ar.order());
		if (rows.size() < 20) break;
		const Vec e = whiten(r, ar, rows).col(0);
		std::vector<double> a(static_cast<std::size_t>(e.size()));
		for (Eigen::Index i = 0; i < e.size(); ++i) a[static_cast<std::size_t>(i)] = e(i);
		auto med = [](std::vector<double> v)
		{
			std::nth_element(v.begin(), v.begin() + static_cast<long>(v.size() / 2), v.end());
			return v[v.size() / 2];
		};
		const double m = med(a);
		for (auto& v : a) v = std::fabs(v - m);
		const double sd = 1.4826 * med(a);
		if (!(sd > 0)) break;
		std::size_t now = 0;
		for (std::size_t i = 0; i < rows.size(); ++i)
			if (std::fabs(e(static_cast<Eigen::Index>(i)) - m) > opt.outlier_sigma * sd)
			{
				// the innovation at k is large: the outlier is sample k (a spike also disturbs k+1..k+p,
				// which are excluded by whitenableRows once k is flagged)
				ok[rows[i]] = 0;
				++now;
			}
		flagged += now;
		if (now == 0) break;
	}
	return flagged;
}

double logSumExpWeights(const std::vector<double>& halfBic)
{
	double mx = 0.0;  // "no effect" has weight exp(0)
	for (double b : halfBic) mx = std::max(mx, b);
	double s = std::exp(-mx);
	for (double b : halfBic) s += std::exp(b - mx);
	return mx + std::log(s);
}
}  // namespace

Vec coefficientsOnRows(const Mat& X, const RunSignals& sig, const std::vector<unsigned char>& rows)
{
	std::vector<Eigen::Index> r;
	for (std::size_t k = 0; k < rows.size(); ++k)
		if (rows[k]) r.push_back(static_cast<Eigen::Index>(k));
	Mat A(static_cast<Eigen::Index>(r.size()), X.cols());
	Vec y(static_cast<Eigen::Index>(r.size()));
	for (std::size_t i = 0; i < r.size(); ++i)
	{
		A.row(static_cast<Eigen::Index>(i)) = X.row(r[i]);
		y(static_cast<Eigen::Index>(i)) = sig.bias_dph[static_cast<std::size_t>(r[i])];
	}
	return A.colPivHouseholderQr().solve(y);
}

Vec residualWithCoefficients(const Mat& X, const RunSignals& sig, const Vec& coef)
{
	const Vec y = yVector(sig);
	Vec r = y - X * coef;
	double s = 0;
	std::size_t m = 0;
	for (std::size_t k = 0; k < sig.size(); ++k)
		if (sig.usable[k])
		{
			s += r(static_cast<Eigen::Index>(k));
			++m;
		}
	const double off = m ? s / m : 0.0;
	for (std::size_t k = 0; k < sig.size(); ++k)
		r(static_cast<Eigen::Index>(k)) = sig.usable[k] ? r(static_cast<Eigen::Index>(k)) - off : 0.0;
	return r;
}

namespace
{
// The stages of one round of selectMissingEffects.

/** The candidates a round can test, each with its non-spanned grid values and the columns at
 * its OLS-best value; the untestable and spanned ones (and why) go to `report`. Skips `excluded`. */
std::vector<CandState> screenCandidates(const std::vector<std::string>& ids, const std::vector<std::string>& excluded,
										const RunSignals& sig, const CandidateContext& ctx, const Mat& X, const Vec& y,
										const std::vector<std::size_t>& rows, const SelectionOptions& opt,
										std::vector<CandidateTest>& report)
{
	std::vector<CandState> cands;
	for (const auto& id : ids)
	{
		CandState cs;
		cs.eff = &candidateById(id);
		cs.test.id = id;
		if (std::find(excluded.begin(), excluded.end(), id) != excluded.end()) continue;
		const auto why = cs.eff->untestable_reason(sig);
		if (!why.empty())
		{
			cs.test.status = CandidateStatus::Untestable;
			cs.test.note = why;
			report.push_back(cs.test);
			continue;
		}
		for (double th : cs.eff->theta_grid)
			if (spanResidual(X, cs.eff->build(ctx, th), rows) >= opt.span_tolerance) cs.thetas.push_back(th);
		if (cs.thetas.empty())
		{
			cs.test.status = CandidateStatus::Spanned;
			cs.test.note = "the model already spans its terms";
			report.push_back(cs.test);
			continue;
		}
		// OLS profile (for the kitchen-sink noise estimate)
		double best = std::numeric_limits<double>::infinity();
		for (double th : cs.thetas)
		{
			Vec rc;
			const double rss = olsOnRows(hcat(X, cs.eff->build(ctx, th)), y, rows, rc).rss;
			if (rss < best)
			{
				best = rss;
				cs.theta = th;
			}
		}
		cs.C = cs.eff->build(ctx, cs.theta);
		cs.test.status = CandidateStatus::Tested;
		cands.push_back(std::move(cs));
	}
	return cands;
}

/** A screened candidate's test against the model X: its grid value by profile search on the OLS
 * residual sum of squares, then the GLS Wald chi-square of its columns (Sidak-corrected for the
 * grid size) and its BIC gain with nEff effective samples. */
void testCandidate(CandState& cs, const CandidateContext& ctx, const Mat& X, const Vec& y,
				   const std::vector<std::size_t>& rows, const std::vector<std::size_t>& common,
				   const std::vector<int>& block, const SelectionOptions& opt, double nEff, const Gls& g0)
{
	// nonlinear parameter: profile search on the residual sum of squares whitened by the
	// model's noise model (the GLS test below is Sidak-corrected for the grid size)
	double bestRss = std::numeric_limits<double>::infinity();
	const Mat WX = whiten(X, g0.ar, common, &block);
	const Vec Wy = whiten(y, g0.ar, common, &block).col(0);
	auto whitenedRss = [&](double th, Mat& C) {
		C = cs.eff->build(ctx, th);
		return leastSquares(hcat(WX, whiten(C, g0.ar, common, &block)), Wy).rss;
	};
	std::vector<double> gridRss;
	for (double th : cs.thetas)
	{
		Mat C;
		const double rss = whitenedRss(th, C);
		gridRss.push_back(rss);
		if (rss < bestRss)
		{
			bestRss = rss;
			cs.theta = th;
			cs.C = C;
		}
	}
	// the shape family of a grid value (the candidate's own, else the sign of theta)
	const auto familyOf = [&](double th) { return cs.eff->theta_family ? cs.eff->theta_family(th) : (th > 0 ? 1 : -1); };
	std::vector<int> families;
	for (double th : cs.thetas)
		if (std::find(families.begin(), families.end(), familyOf(th)) == families.end()) families.push_back(familyOf(th));
	if (cs.eff->theta_continuous && cs.thetas.size() > 1)
		for (const int family : families)
		{
			// from a family's best grid value, golden section on log |theta| between that value's
			// neighbours of the same family (a 1-2-5 grid: a bracket spans a factor 4-5), to 2 %
			// in |theta| (one family has one sign)
			std::vector<std::pair<double, double>> same;  // |theta|, whitened RSS
			double sgn = 1.0;
			for (std::size_t i = 0; i < cs.thetas.size(); ++i)
				if (familyOf(cs.thetas[i]) == family)
				{
					same.emplace_back(std::fabs(cs.thetas[i]), gridRss[i]);
					sgn = cs.thetas[i] > 0 ? 1.0 : -1.0;
				}
			if (same.size() < 2) continue;
			std::sort(same.begin(), same.end());
			std::size_t at = 0;
			for (std::size_t i = 1; i < same.size(); ++i)
				if (same[i].second < same[at].second) at = i;
			double a = std::log(same[at > 0 ? at - 1 : at].first);
			double b = std::log(same[at + 1 < same.size() ? at + 1 : at].first);
			const double r = 0.5 * (std::sqrt(5.0) - 1.0);
			Mat C1, C2;
			double u1 = b - r * (b - a), u2 = a + r * (b - a);
			double f1 = whitenedRss(sgn * std::exp(u1), C1), f2 = whitenedRss(sgn * std::exp(u2), C2);
			while (b - a > 0.02)
			{
				if (f1 < f2)
				{
					b = u2;
					u2 = u1;
					f2 = f1;
					C2 = C1;
					u1 = b - r * (b - a);
					f1 = whitenedRss(sgn * std::exp(u1), C1);
				}
				else
				{
					a = u1;
					u1 = u2;
					f1 = f2;
					C1 = C2;
					u2 = a + r * (b - a);
					f2 = whitenedRss(sgn * std::exp(u2), C2);
				}
			}
			const bool first = f1 < f2;
			const double f = first ? f1 : f2;
			if (f < bestRss && spanResidual(X, first ? C1 : C2, rows) >= opt.span_tolerance)
			{
				bestRss = f;
				cs.theta = sgn * std::exp(first ? u1 : u2);
				cs.C = first ? C1 : C2;
			}
		}
	const Gls g1 = glsFit(hcat(X, cs.C), y, common, block, opt);
	const double bestChi2 = waldChi2(X, g1, y, common, block);
	auto& t = cs.test;
	t.theta = cs.theta;
	t.dof = static_cast<int>(cs.C.cols());
	t.chi2 = std::max(0.0, bestChi2);
	const int grid = static_cast<int>(cs.thetas.size());
	t.p = sidak(chi2Survival(t.chi2, t.dof), grid);
	t.delta_bic = t.chi2 - t.dof * std::log(nEff) - std::log(double(grid));
}

/** Holm's step-down adjustment over the tested candidates' p-values; significant = adjusted p
 * below alpha and a positive BIC gain. */
void holmAdjust(std::vector<CandState>& cands, const SelectionOptions& opt)
{
	std::vector<std::size_t> order(cands.size());
	for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
	std::sort(order.begin(), order.end(), [&](auto a, auto b) { return cands[a].test.p < cands[b].test.p; });
	double running = 0.0;
	const std::size_t m = cands.size();
	for (std::size_t i = 0; i < m; ++i)
	{
		auto& t = cands[order[i]].test;
		running = std::max(running, std::min(1.0, double(m - i) * t.p));
		t.p_adjusted = running;
		t.significant = t.p_adjusted < opt.alpha && t.delta_bic > 0;
	}
}

/** The candidate ids a selection works through: the options' list, else every bias candidate of
 * the library in its order. */
std::vector<std::string> candidateIdsToTry(const SelectionOptions& opt)
{
	std::vector<std::string> ids = opt.candidates;
	if (ids.empty())
		for (const auto& c : candidateLibrary())
			if (c.channel == ResidualChannel::Bias) ids.push_back(c.id);
	ids.erase(std::remove_if(ids.begin(), ids.end(),
							 [&](const std::string& id) {
								 return std::find(opt.left_out.begin(), opt.left_out.end(), id) != opt.left_out.end();
							 }),
			  ids.end());
	return ids;
}

/** One round's tests of the candidates against the current model. */
struct RoundTests
{
	std::vector<CandState> cands;       //!< the tested candidates, Holm-adjusted
	std::vector<CandidateTest> report;  //!< every candidate: the untestable and spanned, then the tested
	std::vector<std::size_t> common;    //!< the rows the noise model whitens
	Gls g0;                             //!< the current model's GLS fit (its noise model)
	int best = -1;                      //!< the significant candidate with the largest BIC gain; -1: none
};

/** Index of the significant candidate with the largest BIC gain (the first on a tie); -1 when
 * none is significant. */
int strongestSignificant(const std::vector<CandState>& cands)
{
	int best = -1;
	for (std::size_t i = 0; i < cands.size(); ++i)
		if (cands[i].test.significant && (best < 0 || cands[i].test.delta_bic > cands[static_cast<std::size_t>(best)].test.delta_bic))
			best = static_cast<int>(i);
	return best;
}

/** Screen, test and Holm-adjust the candidates against the model X; when none is significant,
 * each tested one's smallest detectable contribution. */
RoundTests testRound(const std::vector<std::string>& ids, const std::vector<std::string>& excluded,
					 const RunSignals& sig, const CandidateContext& ctx, const Mat& X, const Vec& y,
					 const std::vector<std::size_t>& rows, const std::vector<unsigned char>& ok,
					 const SelectionOptions& opt)
{
	RoundTests t;
	t.cands = screenCandidates(ids, excluded, sig, ctx, X, y, rows, opt, t.report);
	if (t.cands.empty()) return t;
	t.common = whitenableRows(sig.block, ok, 0);
	const double nRows = double(t.common.size());
	t.g0 = glsFit(X, y, t.common, sig.block, opt);
	const double nEff = std::max(2.0, nRows / std::max(1.0, t.g0.lrv));
	for (auto& cs : t.cands) testCandidate(cs, ctx, X, y, rows, t.common, sig.block, opt, nEff, t.g0);
	holmAdjust(t.cands, opt);
	t.best = strongestSignificant(t.cands);
	if (t.best < 0)
		for (auto& cs : t.cands)
			cs.test.detectable_rms_dph =
				detectableRms(X, cs.C, y, t.common, sig.block, t.g0, opt, t.cands.size(), cs.thetas.size(), nEff);
	for (const auto& cs : t.cands) t.report.push_back(cs.test);
	return t;
}

/** The named effect as tested: id, parameter, unit and test figures; its alias group so far only
 * itself. */
NamedEffect namedFromBest(const CandState& B)
{
	NamedEffect ne;
	ne.id = B.eff->id;
	ne.alias_group = {ne.id};
	ne.alias_theta = {B.theta};
	ne.alias_sign = {0};
	ne.theta_name = B.eff->theta_name;
	ne.theta = B.theta;
	if (B.eff->describe_theta) ne.theta_meaning = B.eff->describe_theta(B.theta);
	ne.coefficient_unit = B.eff->coefficient_unit;
	ne.chi2 = B.test.chi2;
	ne.p_adjusted = B.test.p_adjusted;
	ne.delta_bic = B.test.delta_bic;
	return ne;
}

/** How another tested candidate stands to the one being named, on this run. */
struct RelationToBest
{
	double collinearity = 0.0;  //!< how well its columns reproduce the named effect's fitted shape
	bool collinear = false;     //!< collinearity at least SelectionOptions::alias_collinearity
	bool alias = false;         //!< cannot be told apart: collinear, or significant and the named effect adds nothing beside it
	bool explained = false;     //!< not an alias, and it adds nothing beside the named effect
	int sign = 0;               //!< an alias's one-column coefficient sign (OLS beside the model); 0 otherwise
};

/** Each tested candidate's relation to the named one (`best`, whose own entry stays default):
 * its collinearity after whitening and removing what the model X explains, then, for the
 * significant or collinear ones, the two conditional Wald tests (each given the other, Sidak
 * for the grid). XB = X with the named effect's columns, gB its GLS fit. */
std::vector<RelationToBest> relationsToBest(const std::vector<CandState>& cands, int best, const Mat& X,
											const Mat& XB, const Gls& gB, const Vec& y,
											const std::vector<std::size_t>& rows, const std::vector<std::size_t>& common,
											const std::vector<int>& block, const SelectionOptions& opt)
{
	const auto& B = cands[static_cast<std::size_t>(best)];
	const std::size_t m = cands.size();
	std::vector<RelationToBest> rel(m);
	for (std::size_t i = 0; i < m; ++i)
	{
		if (static_cast<int>(i) == best) continue;
		const auto& C = cands[i];
		auto& r = rel[i];
		r.collinearity = shapeReproduction(X, B.C, gB.fit.coef.segment(X.cols(), B.C.cols()), C.C, gB.ar, common, block);
		r.collinear = r.collinearity >= opt.alias_collinearity;
		if (!C.test.significant && !r.collinear) continue;
		const Gls gBC = glsFit(hcat(XB, C.C), y, common, block, opt, false, &gB.ar);
		const double chiBgivenC = waldChi2(hcat(X, C.C), gBC, y, common, block);
		const double chiCgivenB = waldChi2(XB, gBC, y, common, block);
		const double pBgivenC = sidak(chi2Survival(chiBgivenC, double(B.C.cols())), int(B.thetas.size()));
		const double pCgivenB = sidak(chi2Survival(chiCgivenB, double(C.C.cols())), int(C.thetas.size()));
		r.alias = r.collinear || (C.test.significant && pBgivenC > opt.alias_alpha);
		r.explained = !r.alias && pCgivenB > opt.alpha / double(m);
		if (r.alias && C.C.cols() == 1)
		{
			Vec ri;
			const double c = olsOnRows(hcat(X, C.C), y, rows, ri).coef(X.cols());
			r.sign = c > 0 ? 1 : (c < 0 ? -1 : 0);
		}
	}
	return rel;
}

/** The relations written into the named effect (its alias group, in candidate order) and the
 * round's report (collinearity, "alias of" / "explained by"); aliases and explained candidates
 * are not tested again. */
void recordRelations(NamedEffect& ne, const std::vector<RelationToBest>& rel, const std::vector<CandState>& cands,
					 int best, std::vector<CandidateTest>& report, std::vector<std::string>& excluded)
{
	for (std::size_t i = 0; i < cands.size(); ++i)
	{
		if (static_cast<int>(i) == best) continue;
		const auto& C = cands[i];
		auto it = std::find_if(report.begin(), report.end(), [&](const CandidateTest& t) { return t.id == C.test.id; });
		if (it != report.end()) it->collinearity_with_best = rel[i].collinearity;
		if (rel[i].alias)
		{
			ne.alias_group.push_back(C.test.id);
			ne.alias_theta.push_back(C.theta);
			ne.alias_sign.push_back(rel[i].sign);
			ne.separating_profiles.push_back(separationAdvice(ne.id, C.test.id));
			excluded.push_back(C.test.id);
			if (it != report.end()) it->note = "alias of " + ne.id;
		}
		else if (rel[i].explained)
		{
			excluded.push_back(C.test.id);
			if (it != report.end()) it->note = "explained by " + ne.id;
		}
	}
}

/** Confidence of the named effect and of its alias group: BIC weights (exp of half the BIC gain)
 * of the group's members against "no effect"; collinear members cannot be told apart on this
 * run (their BIC differences reflect model mismatch, not evidence), so then the group's
 * confidence is shared equally. */
void setConfidence(NamedEffect& ne, const std::vector<RelationToBest>& rel, const std::vector<CandState>& cands)
{
	std::vector<double> all;
	bool anyCollinear = false;
	for (std::size_t i = 0; i < cands.size(); ++i)
		if (rel[i].alias)
		{
			all.push_back(0.5 * cands[i].test.delta_bic);
			anyCollinear = anyCollinear || rel[i].collinear;
		}
	all.push_back(0.5 * ne.delta_bic);
	const double lse = logSumExpWeights(all);
	ne.confidence = std::exp(0.5 * ne.delta_bic - lse);
	double g = 0;
	for (double b : all) g += std::exp(b - lse);
	ne.group_confidence = std::min(1.0, g);
	if (anyCollinear) ne.confidence = ne.group_confidence / double(ne.alias_group.size());
}

/** The named effect's coefficient and its 95 % interval from the GLS fit gB of the model (its
 * first q0 columns) with the effect's columns: one column, the coefficient in the effect's unit;
 * several, the RMS of the fitted terms on `rows` (delta method). */
void setCoefficient(NamedEffect& ne, const CandState& B, const Gls& gB, Eigen::Index q0,
					const std::vector<std::size_t>& rows)
{
	const auto& f = gB.fit;
	const double sigma2 = gB.sigma2 * gB.lrv;
	const Eigen::Index q = B.C.cols();
	const Vec beta = f.coef.segment(q0, q);
	const Mat cov = sigma2 * f.cov_unscaled.block(q0, q0, q, q);
	{
		const Eigen::LDLT<Mat> ldlt(cov);
		const double wald = ldlt.info() == Eigen::Success ? double(beta.transpose() * ldlt.solve(beta)) : 0.0;
		ne.zero_p = std::isfinite(wald) && wald > 0 ? chi2Survival(wald, double(q)) : 1.0;
	}
	if (q == 1)
	{
		ne.coefficient = B.eff->coefficient_scale * beta(0);
		const double half = 1.96 * std::sqrt(std::max(0.0, cov(0, 0))) * std::fabs(B.eff->coefficient_scale);
		ne.ci_low = ne.coefficient - half;
		ne.ci_high = ne.coefficient + half;
		return;
	}
	const Mat Cr = pick(B.C, rows);
	const Mat G = Cr.transpose() * Cr / double(rows.size());
	const double rms = std::sqrt(std::max(0.0, double(beta.transpose() * G * beta)));
	const Vec grad = rms > 0 ? Vec(G * beta / rms) : Vec::Zero(q);
	const double half = 1.96 * std::sqrt(std::max(0.0, double(grad.transpose() * cov * grad)));
	ne.coefficient = rms;
	// a candidate that has one column on other runs (radial_gradient without a thermistor on
	// neither side) states a per-unit coefficient; here it is an RMS
	if (ne.coefficient_unit.find("RMS") == std::string::npos) ne.coefficient_unit = "deg/h (RMS of the fitted terms)";
	ne.ci_low = std::max(0.0, rms - half);
	ne.ci_high = rms + half;
}

}  // namespace

SelectionResult selectMissingEffects(const RunSignals& sig, const BaseDesign& base, const SelectionOptions& opt)
{
	SelectionResult res;
	const Vec y = yVector(sig);
	std::vector<unsigned char> ok = sig.usable;
	if (rowsOf(ok).size() < static_cast<std::size_t>(10 * base.X.cols()))
		throw std::invalid_argument("only " + std::to_string(rowsOf(ok).size()) + " usable samples for " +
									std::to_string(base.X.cols()) + " base-model columns");
	res.outliers = flagOutliers(base.X, y, sig, ok, opt);
	res.fit_rows = ok;
	const auto rows = rowsOf(ok);

	Vec r;
	const auto baseFit = olsOnRows(base.X, y, rows, r);
	res.coef_before = baseFit.coef;
	res.residual_before = r;
	res.model.lag_base_coef = baseFit.coef;

	// rounds: test every candidate not yet named, excluded or explained; name the strongest
	// significant one with its look-alikes; add its columns to the model
	const std::vector<std::string> ids = candidateIdsToTry(opt);
	std::vector<std::string> excluded;
	Mat X = base.X;
	for (int round = 0; round < opt.max_effects; ++round)
	{
		Vec rr;
		const Vec modelCoef = olsOnRows(X, y, rows, rr).coef;
		const auto ctx = makeCandidateContext(sig, base, modelCoef.head(base.X.cols()));
		RoundTests t = testRound(ids, excluded, sig, ctx, X, y, rows, ok, opt);
		if (round == 0 && !t.cands.empty())
		{
			res.ar = t.g0.ar;
			res.lrv_factor = t.g0.lrv;
		}
		if (t.best < 0)
		{
			res.rounds.push_back(t.report);
			break;
		}
		const auto& B = t.cands[static_cast<std::size_t>(t.best)];
		NamedEffect ne = namedFromBest(B);
		const Mat XB = hcat(X, B.C);
		const Gls gB = glsFit(XB, y, t.common, sig.block, opt, true);
		const auto rel = relationsToBest(t.cands, t.best, X, XB, gB, y, rows, t.common, sig.block, opt);
		recordRelations(ne, rel, t.cands, t.best, t.report, excluded);
		setConfidence(ne, rel, t.cands);
		setCoefficient(ne, B, gB, X.cols(), rows);
		res.named.push_back(ne);
		res.ar_after = gB.ar;
		res.rounds.push_back(t.report);
		excluded.push_back(ne.id);
		if (sim::effectFromId(ne.id) == sim::Effect::ThermistorLag) res.model.lag_base_coef = modelCoef.head(base.X.cols());
		res.model.effects.push_back({ne.id, ne.theta});
		X = XB;
	}
	Vec ra;
	res.coef_after = olsOnRows(X, y, rows, ra).coef;
	res.residual_after = ra;
	return res;
}

void confirmOnRun(SelectionResult& result, const RunSignals& sig2, const BaseDesign& base2, const SelectionOptions& opt)
{
	const Vec y = yVector(sig2);
	std::vector<unsigned char> ok = sig2.usable;
	flagOutliers(base2.X, y, sig2, ok, opt);
	const auto rows = rowsOf(ok);
	Mat X = base2.X;
	Vec r;
	const auto baseFit = olsOnRows(X, y, rows, r);
	const auto ctx = makeCandidateContext(sig2, base2, baseFit.coef);
	// each named effect's coefficients on the analysed run (columns after the base, in the
	// model's order), to judge what the confirmation run could show of it
	auto analysedCoefficients = [&](const std::string& id, Eigen::Index q) -> Vec {
		Eigen::Index col = base2.X.cols();
		for (const auto& term : result.model.effects)
		{
			const Eigen::Index w = candidateById(term.id).build(ctx, term.theta).cols();
			if (term.id == id)
				return col + w <= result.coef_after.size() && w == q ? Vec(result.coef_after.segment(col, q)) : Vec();
			col += w;
		}
		return Vec();
	};
	for (auto& ne : result.named)
	{
		const auto& eff = candidateById(ne.id);
		ne.confirm_tested = true;
		if (const std::string why = eff.untestable_reason(sig2); !why.empty())
		{
			ne.confirm_tested = false;
			ne.confirm_cannot_tell = why;
			continue;
		}
		const auto common = whitenableRows(sig2.block, ok, 0);
		const Mat C = eff.build(ctx, ne.theta);
		const Mat K = hcat(X, C);
		if (common.size() < static_cast<std::size_t>(K.cols()) + 10)
		{
			ne.confirm_tested = false;
			ne.confirm_cannot_tell = "the confirmation run has " + std::to_string(common.size()) +
									 " usable rows, too few to fit the model and the effect";
			continue;
		}
		const Gls g1 = glsFit(K, y, common, sig2.block, opt);
		// power: the chi-square the effect would give on this run at the coefficient named on the
		// analysed run (its contribution beyond the model, whitened by this run's noise model);
		// below the confirmation threshold a non-confirmation says nothing: cannot tell
		if (const Vec beta1 = analysedCoefficients(ne.id, C.cols()); beta1.size() == C.cols())
		{
			const Vec contribution = C * beta1;
			const Mat Xw = whiten(X, g1.ar, common, &sig2.block);
			const Vec cw = whiten(Mat(contribution), g1.ar, common, &sig2.block).col(0);
			const double expected = leastSquares(Xw, cw).residual.squaredNorm() / (g1.sigma2 * g1.lrv);
			const double needed = chi2Quantile(opt.alias_alpha, double(C.cols()));
			if (!(expected >= needed))
			{
				char buf[300];
				std::snprintf(buf, sizeof buf,
							  "the confirmation run cannot show it: at the coefficient named its expected chi-square "
							  "there is %.3g, below the %.3g a confirmation needs (too short or too little excitation)",
							  expected, needed);
				ne.confirm_tested = false;
				ne.confirm_cannot_tell = buf;
				X = K;
				continue;
			}
		}
		ne.confirm_p = chi2Survival(waldChi2(X, g1, y, common, sig2.block), double(C.cols()));
		if (C.cols() == 1)
		{
			ne.confirm_coefficient = eff.coefficient_scale * g1.fit.coef(X.cols());
			ne.confirmed = ne.confirm_p < opt.alias_alpha && ne.confirm_coefficient * ne.coefficient > 0;
		}
		else
			ne.confirmed = ne.confirm_p < opt.alias_alpha;
		if (ne.confirmed) ne.confirmed_by = ne.id;
		// the group is what was named: a look-alike may confirm it (its own theta and sign)
		const std::size_t g = ne.alias_group.size();
		for (std::size_t j = 1; j < g && !ne.confirmed && j < ne.alias_theta.size() && j < ne.alias_sign.size(); ++j)
		{
			const auto& effJ = candidateById(ne.alias_group[j]);
			if (!effJ.untestable_reason(sig2).empty()) continue;
			const Mat CJ = effJ.build(ctx, ne.alias_theta[j]);
			const Gls gJ = glsFit(hcat(X, CJ), y, common, sig2.block, opt);
			const double pJ = chi2Survival(waldChi2(X, gJ, y, common, sig2.block), double(CJ.cols()));
			const bool signOk = CJ.cols() != 1 || ne.alias_sign[j] == 0 || gJ.fit.coef(X.cols()) * ne.alias_sign[j] > 0;
			if (pJ < opt.alias_alpha / double(g) && signOk)
			{
				ne.confirmed = true;
				ne.confirmed_by = ne.alias_group[j];
				ne.confirm_p = pJ;
			}
		}
		X = K;
	}
}

void keepConfirmedEffects(SelectionResult& result, const RunSignals& sig1, const BaseDesign& base1)
{
	std::vector<NamedEffect> kept;
	for (auto& ne : result.named)
		(ne.confirm_tested && !ne.confirmed ? result.not_confirmed : kept).push_back(ne);
	if (kept.size() == result.named.size()) return;
	result.named = kept;
	std::vector<EffectTerm> effects;
	for (const auto& term : result.model.effects)
		for (const auto& ne : kept)
			if (ne.id == term.id) effects.push_back(term);
	result.model.effects = effects;
	const Mat X = result.model.design(base1, sig1);
	Vec ra;
	result.coef_after = olsOnRows(X, yVector(sig1), rowsOf(result.fit_rows), ra).coef;
	result.residual_after = ra;
}

}  // namespace mrpt_fog::discrepancy
