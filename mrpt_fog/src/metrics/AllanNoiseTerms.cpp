/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/metrics/AllanNoiseTerms.h>

#include <algorithm>
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
/** Fits the term of slope target_slope on points with tau > after_tau_s; with anchored, only a
 * run that starts at the first usable point counts (quantisation lives at the shortest taus). */
AllanLineFit fitTerm(const std::vector<AllanPoint>& c, double target_slope, const AllanTermOptions& opt,
					 double after_tau_s, bool anchored)
{
	AllanLineFit fit;
	fit.slope = target_slope;
	// Usable points: enough clusters and a positive deviation.
	std::vector<const AllanPoint*> p;
	for (const auto& q : c)
		if (q.clusters >= opt.min_clusters && q.adev > 0 && q.tau_s > 0 && q.tau_s > after_tau_s) p.push_back(&q);
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
}  // namespace

AllanNoiseTerms allanNoiseTerms(const std::vector<AllanPoint>& curve_dph, const AllanTermOptions& options)
{
	AllanNoiseTerms t;
	// In the IEEE 952 Annex C picture quantisation, ARW, bias instability and RRW dominate at increasing tau;
	// each term is looked for after the end of the previous identified ones, so that e.g. a
	// -1 slope at long tau (a slow signal removed by a fit) is not read as quantisation.
	double after = 0;
	auto next = [&](const AllanLineFit& f) {
		if (f.identified()) after = std::max(after, f.tau_max_s);
	};
	t.quantization = fitTerm(curve_dph, -1.0, options, after, true);
	next(t.quantization);
	t.arw = fitTerm(curve_dph, -0.5, options, after, false);
	next(t.arw);
	t.flat = fitTerm(curve_dph, 0.0, options, after, false);
	next(t.flat);
	t.rrw = fitTerm(curve_dph, +0.5, options, after, false);
	// Unit bookkeeping: a rate in deg/h times a time in s is an angle in deg/3600 = arcsec;
	// deg/h * sqrt(s) = deg/sqrt(h) * sqrt(s/h) = deg/sqrt(h) / 60.
	if (t.quantization.identified()) t.quantization_arcsec = t.quantization.at(std::sqrt(3.0));  // sigma = sqrt(3) Q / tau
	if (t.arw.identified()) t.arw_dpsh = t.arw.at(1.0) / 60.0;
	if (t.flat.identified()) t.bias_instability_dph = t.flat.adev_at_1s_dph / kBiasInstabilityFactor;
	if (t.rrw.identified()) t.rrw_dphsh = t.rrw.at(3.0) * 60.0;
	return t;
}

}  // namespace mrpt_fog
