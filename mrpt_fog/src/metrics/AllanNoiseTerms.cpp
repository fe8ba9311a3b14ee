/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/metrics/AllanNoiseTerms.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>

namespace mrpt_fog
{
double AllanLineFit::at(double tau_s) const
{
	if (!identified()) return NAN;
	return adev_at_1s_dph * std::pow(tau_s, slope);
}

namespace
{
bool usable(const AllanPoint& q, const AllanTermOptions& opt)
{
	return q.clusters >= opt.min_clusters && q.adev > 0 && std::isfinite(q.adev) && q.tau_s > 0;
}

/** Fits the term of slope target_slope on usable points with after_tau_s < tau < before_tau_s;
 * with anchored, only a run that starts at the first usable point counts (quantisation lives at
 * the shortest taus). */
AllanLineFit fitTerm(const std::vector<AllanPoint>& c, double target_slope, const AllanTermOptions& opt,
					 double after_tau_s, double before_tau_s, bool anchored)
{
	AllanLineFit fit;
	fit.slope = target_slope;
	std::vector<const AllanPoint*> p;
	for (const auto& q : c)
		if (usable(q, opt) && q.tau_s > after_tau_s && q.tau_s < before_tau_s) p.push_back(&q);
	if (p.size() < 2) return fit;
	std::vector<double> seg(p.size() - 1);
	for (std::size_t i = 0; i + 1 < p.size(); i++)
		seg[i] = std::log(p[i + 1]->adev / p[i]->adev) / std::log(p[i + 1]->tau_s / p[i]->tau_s);
	std::vector<bool> in(p.size(), false);
	for (std::size_t i = 0; i < p.size(); i++)
	{
		double s = 0;
		int n = 0;
		if (i > 0)
		{
			s += seg[i - 1];
			n++;
		}
		if (i + 1 < p.size())
		{
			s += seg[i];
			n++;
		}
		in[i] = std::abs(s / n - target_slope) <= opt.slope_tolerance;
	}
	// Contiguous run with the largest weight.
	std::size_t best_a = 0, best_b = 0;
	double best_w = 0;
	for (std::size_t a = 0; a < p.size();)
	{
		if (!in[a])
		{
			a++;
			continue;
		}
		std::size_t b = a;
		double w = 0;
		while (b < p.size() && in[b]) w += static_cast<double>(p[b++]->clusters);
		if (w > best_w && (!anchored || a == 0))
		{
			best_w = w;
			best_a = a;
			best_b = b;
		}
		a = b;
	}
	if (best_w <= 0) return fit;
	double sum_w = 0, sum_c = 0;
	for (std::size_t i = best_a; i < best_b; i++)
	{
		const double w = static_cast<double>(p[i]->clusters);
		sum_c += w * (std::log(p[i]->adev) - target_slope * std::log(p[i]->tau_s));
		sum_w += w;
	}
	fit.adev_at_1s_dph = std::exp(sum_c / sum_w);
	fit.tau_min_s = p[best_a]->tau_s;
	fit.tau_max_s = p[best_b - 1]->tau_s;
	fit.points = best_b - best_a;
	return fit;
}

/** Powers of tau in the joint Allan-variance model AVAR = sum_k c_k tau^k: quantisation (-2),
 * angle random walk (-1), bias instability (0), rate random walk (+1). */
constexpr std::array<int, 4> kPowers = {-2, -1, 0, 1};

/** Non-negative weighted least squares of avar_i ~ sum_k c_k tau_i^k, residuals relative to the
 * model (iteratively reweighted: the relative variance of an Allan variance estimate is about
 * 1/clusters, so weight = clusters / model^2). Four unknowns: the exact non-negative solution is
 * the best of the 16 subsets whose unconstrained solution is non-negative. */
std::array<double, 4> fitPowerLaws(const std::vector<const AllanPoint*>& p)
{
	const Eigen::Index n = static_cast<Eigen::Index>(p.size());
	Eigen::MatrixXd A(n, 4);
	Eigen::VectorXd y(n), w(n), den(n);
	for (Eigen::Index i = 0; i < n; i++)
	{
		for (int k = 0; k < 4; k++) A(i, k) = std::pow(p[i]->tau_s, kPowers[k]);
		y(i) = p[i]->adev * p[i]->adev;
		w(i) = static_cast<double>(p[i]->clusters);
		den(i) = y(i);
	}
	std::array<double, 4> best_c{0, 0, 0, 0};
	for (int iteration = 0; iteration < 6; iteration++)
	{
		const Eigen::VectorXd sw = w.cwiseSqrt().cwiseQuotient(den);
		double best_r = INFINITY;
		for (int mask = 1; mask < 16; mask++)
		{
			std::vector<int> idx;
			for (int k = 0; k < 4; k++)
				if (mask & (1 << k)) idx.push_back(k);
			if (static_cast<Eigen::Index>(idx.size()) > n) continue;
			Eigen::MatrixXd As(n, static_cast<Eigen::Index>(idx.size()));
			for (std::size_t j = 0; j < idx.size(); j++) As.col(static_cast<Eigen::Index>(j)) = A.col(idx[j]).cwiseProduct(sw);
			const Eigen::VectorXd sol = As.colPivHouseholderQr().solve(y.cwiseProduct(sw));
			if ((sol.array() < 0).any() || !sol.allFinite()) continue;
			const double r = (As * sol - y.cwiseProduct(sw)).squaredNorm();
			if (r < best_r)
			{
				best_r = r;
				best_c = {0, 0, 0, 0};
				for (std::size_t j = 0; j < idx.size(); j++) best_c[static_cast<std::size_t>(idx[j])] = sol(static_cast<Eigen::Index>(j));
			}
		}
		Eigen::Vector4d c(best_c[0], best_c[1], best_c[2], best_c[3]);
		const Eigen::VectorXd model = A * c;
		if (!(model.array() > 0).all()) break;
		den = model;
	}
	return best_c;
}

/** The flat region: usable points where the flat term of the joint fit holds at least half the
 * fitted Allan variance. Identified only when at least two curve points lie in it. */
AllanLineFit flatRegion(const std::vector<AllanPoint>& c, const AllanTermOptions& opt)
{
	AllanLineFit fit;
	fit.slope = 0;
	std::vector<const AllanPoint*> p;
	for (const auto& q : c)
		if (usable(q, opt)) p.push_back(&q);
	if (p.size() < 3) return fit;
	const std::array<double, 4> coef = fitPowerLaws(p);
	const double flat_avar = coef[2];
	if (!(flat_avar > 0)) return fit;
	std::size_t in = 0;
	double lo = NAN, hi = NAN;
	for (const AllanPoint* q : p)
	{
		double model = 0;
		for (int k = 0; k < 4; k++) model += coef[static_cast<std::size_t>(k)] * std::pow(q->tau_s, kPowers[static_cast<std::size_t>(k)]);
		if (flat_avar < opt.flat_share * model) continue;
		in++;
		if (std::isnan(lo)) lo = q->tau_s;
		hi = q->tau_s;
	}
	if (in < 2) return fit;
	fit.adev_at_1s_dph = std::sqrt(flat_avar);
	fit.tau_min_s = lo;
	fit.tau_max_s = hi;
	fit.points = in;
	return fit;
}
}  // namespace

AllanNoiseTerms allanNoiseTerms(const std::vector<AllanPoint>& curve_dph, const AllanTermOptions& options)
{
	AllanNoiseTerms t;
	// In the IEEE 952 Annex C picture quantisation, ARW, bias instability and RRW dominate at
	// increasing tau. The flat region (bias instability) is found first, from the joint fit;
	// quantisation only at the shortest taus; ARW after quantisation and before the flat region
	// (a noisy -1/2 stretch at the long-tau end of a flicker curve is not ARW); RRW after both.
	t.flat = flatRegion(curve_dph, options);
	const double flat_start = t.flat.identified() ? t.flat.tau_min_s : INFINITY;
	t.quantization = fitTerm(curve_dph, -1.0, options, 0, flat_start, true);
	double after = t.quantization.identified() ? t.quantization.tau_max_s : 0;
	t.arw = fitTerm(curve_dph, -0.5, options, after, flat_start, false);
	if (t.arw.identified()) after = std::max(after, t.arw.tau_max_s);
	if (t.flat.identified()) after = std::max(after, t.flat.tau_max_s);
	t.rrw = fitTerm(curve_dph, +0.5, options, after, INFINITY, false);
	// Unit bookkeeping: a rate in deg/h times a time in s is an angle in deg/3600 = arcsec;
	// deg/h * sqrt(s) = deg/sqrt(h) * sqrt(s/h) = deg/sqrt(h) / 60.
	if (t.quantization.identified()) t.quantization_arcsec = t.quantization.at(std::sqrt(3.0));  // sigma = sqrt(3) Q / tau
	if (t.arw.identified()) t.arw_dpsh = t.arw.at(1.0) / 60.0;
	if (t.flat.identified()) t.bias_instability_dph = t.flat.adev_at_1s_dph / kBiasInstabilityFactor;
	if (t.rrw.identified()) t.rrw_dphsh = t.rrw.at(3.0) * 60.0;
	return t;
}

}  // namespace mrpt_fog
