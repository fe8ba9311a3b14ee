/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/HeatSourceCandidate.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/discrepancy/WhitenedRegression.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
struct GlsAmplitude
{
	double a = 0, se = 0, chi2 = 0, lrv = 1;
	std::size_t n = 0;
	bool ok = false;
};

/** Blocks: a time gap > 3 median periods starts a new block; rows with a finite y. */
void blocksOf(const std::vector<double>& t, const std::vector<double>& y, std::vector<int>& block,
			  std::vector<unsigned char>& ok)
{
	const std::size_t n = t.size();
	std::vector<double> d;
	for (std::size_t k = 1; k < n; ++k) d.push_back(t[k] - t[k - 1]);
	std::sort(d.begin(), d.end());
	const double dt = d.empty() ? 1.0 : d[d.size() / 2];
	block.assign(n, -1);
	ok.assign(n, 0);
	int b = -1;
	for (std::size_t k = 0; k < n; ++k)
	{
		if (!std::isfinite(y[k])) continue;
		ok[k] = 1;
		if (k == 0 || !ok[k - 1] || t[k] - t[k - 1] > 3.0 * dt) ++b;
		block[k] = b;
	}
}

GlsAmplitude glsAmplitude(const std::vector<double>& t, const std::vector<double>& y, const std::vector<double>& h,
						  int lrv_max_lag)
{
	GlsAmplitude g;
	std::vector<int> block;
	std::vector<unsigned char> ok;
	blocksOf(t, y, block, ok);
	const auto rows = whitenableRows(block, ok, 0);
	if (rows.size() < 20) return g;
	const auto n = static_cast<Eigen::Index>(t.size());
	Eigen::MatrixXd X(n, 2);
	Eigen::VectorXd yy(n);
	for (Eigen::Index k = 0; k < n; ++k)
	{
		X(k, 0) = 1.0;
		X(k, 1) = h[static_cast<std::size_t>(k)];
		yy(k) = std::isfinite(y[static_cast<std::size_t>(k)]) ? y[static_cast<std::size_t>(k)] : 0.0;
	}
	const ArNoiseModel ar = fitNoiseReml(X, yy, rows, block);
	const Eigen::MatrixXd Xw = whiten(X, ar, rows, &block);
	const Eigen::VectorXd yw = whiten(yy, ar, rows, &block).col(0);
	const LsFit fit = leastSquares(Xw, yw, true);
	if (fit.rank < 2) return g;
	const double m = static_cast<double>(rows.size());
	const double sigma2 = fit.rss / std::max(1.0, m - 2.0);
	g.lrv = longRunVarianceFactor(fit.residual, lrv_max_lag);
	g.a = fit.coef(1);
	g.se = std::sqrt(std::max(0.0, sigma2 * fit.cov_unscaled(1, 1) * g.lrv));
	g.chi2 = g.se > 0 ? g.a * g.a / (g.se * g.se) : 0.0;
	g.n = rows.size();
	g.ok = g.se > 0;
	return g;
}

std::vector<double> commonMode(const std::vector<std::vector<double>>& r, std::size_t n)
{
	std::vector<double> c(n, std::nan(""));
	for (std::size_t k = 0; k < n; ++k)
	{
		double s = 0;
		bool all = !r.empty();
		for (const auto& ri : r)
		{
			if (!std::isfinite(ri[k])) all = false;
			s += ri[k];
		}
		if (all) c[k] = s / static_cast<double>(r.size());
	}
	return c;
}

bool powerChanges(const std::vector<double>& power)
{
	for (std::size_t k = 1; k < power.size(); ++k)
		if ((power[k] >= 0.5) != (power[k - 1] >= 0.5)) return true;
	return false;
}

}  // namespace

std::vector<double> powerResponse(const std::vector<double>& t, const std::vector<double>& power, double tau_s)
{
	std::vector<double> h(t.size(), 1.0);
	if (power.empty()) return h;
	for (std::size_t k = 0; k < t.size(); ++k)
	{
		const double p = power[k] >= 0.5 ? 1.0 : 0.0;
		if (k == 0)
		{
			h[k] = p;
			continue;
		}
		// the power held over (t_{k-1}, t_k] is the state at t_k (fog-sim's convention)
		const double a = std::exp(-(t[k] - t[k - 1]) / tau_s);
		h[k] = a * h[k - 1] + (1 - a) * p;
	}
	return h;
}

HeatSourceResult testHeatSource(const std::vector<double>& t, const std::vector<double>& power,
								const std::vector<std::vector<double>>& r, const std::vector<ThermistorInfo>& info,
								const HeatSourceOptions& opt)
{
	HeatSourceResult res;
	if (r.empty() || r.size() != info.size()) throw std::invalid_argument("testHeatSource: one residual per thermistor needed");
	for (const auto& ri : r)
		if (ri.size() != t.size()) throw std::invalid_argument("testHeatSource: residual and time lengths differ");
	if (power.empty() || !powerChanges(power))
	{
		res.untestable_reason = "the run has no power change (a constant power is absorbed by the thermistor offsets)";
		res.sentence = "heat_source not testable: " + res.untestable_reason;
		return res;
	}
	const auto cm = commonMode(r, t.size());
	GlsAmplitude best;
	for (double tau : opt.tau_grid_s)
	{
		const auto g = glsAmplitude(t, cm, powerResponse(t, power, tau), opt.lrv_max_lag);
		if (g.ok && (!best.ok || g.chi2 > best.chi2))
		{
			best = g;
			res.tau_s = tau;
		}
	}
	if (!best.ok)
	{
		res.untestable_reason = "too few samples with every thermistor known";
		res.sentence = "heat_source not testable: " + res.untestable_reason;
		return res;
	}
	res.tested = true;
	const double grid = static_cast<double>(std::max<std::size_t>(1, opt.tau_grid_s.size()));
	res.amplitude_C = best.a;
	res.ci_low_C = best.a - 1.959964 * best.se;
	res.ci_high_C = best.a + 1.959964 * best.se;
	res.chi2 = best.chi2;
	res.lrv_factor = best.lrv;
	res.p = chi2Survival(best.chi2, 1.0);
	res.p_adjusted = 1.0 - std::pow(1.0 - res.p, grid);
	if (res.p < 1e-12) res.p_adjusted = res.p * grid;  // pow() loses it below machine precision
	const double nEff = std::max(2.0, static_cast<double>(best.n) / std::max(1.0, best.lrv));
	res.delta_bic = best.chi2 - std::log(nEff) - std::log(grid);
	res.confidence = 1.0 / (1.0 + std::exp(-0.5 * res.delta_bic));
	res.significant = res.p_adjusted < opt.alpha && res.delta_bic > 0;

	const auto h = powerResponse(t, power, res.tau_s);
	res.same_sign = true;
	double largest = -1e300;
	for (std::size_t i = 0; i < r.size(); ++i)
	{
		const auto g = glsAmplitude(t, r[i], h, opt.lrv_max_lag);
		ThermistorHeatResponse tr;
		tr.info = info[i];
		tr.amplitude_C = g.a;
		tr.se_C = g.se;
		res.thermistors.push_back(tr);
		if (!(g.a > 0) || (g.a > 0) != (res.amplitude_C > 0)) res.same_sign = false;
		if (g.a > largest)
		{
			largest = g.a;
			res.nearest = info[i].name;
		}
	}
	res.named = res.significant && res.amplitude_C > 0 && res.same_sign;
	if (res.named)
	{
		const auto& n = *std::find_if(res.thermistors.begin(), res.thermistors.end(),
									  [&](const ThermistorHeatResponse& x) { return x.info.name == res.nearest; });
		res.sentence = "The thermistor residual follows the gyro power (first-order, tau " + formatValue("%.0f", res.tau_s) +
					   " s): +" + formatValue("%.3g", res.amplitude_C) + " C at full power on average, warmer on all " +
					   std::to_string(r.size()) + " thermistors, largest at " + res.nearest + " (" +
					   toString(n.info.side) + ", " + formatValue("%.0f", n.info.angle_deg) + " deg, +" +
					   formatValue("%.3g", n.amplitude_C) + " C): an unmodelled internal heat source nearest " + res.nearest +
					   ".";
	}
	else if (res.significant)
		res.sentence = "The thermistor residual correlates with the gyro power (amplitude " +
					   formatValue("%.3g", res.amplitude_C) + " C, Sidak p " + formatValue("%.2g", res.p_adjusted) +
					   ") but not with the same warming sign on every thermistor: not named as a heat source.";
	else
		res.sentence = "No heat-source signature in the thermistor residual (Sidak p " + formatValue("%.2g", res.p_adjusted) + ").";
	return res;
}

HeatSourceConfirm confirmHeatSource(const std::vector<double>& t, const std::vector<double>& power,
									const std::vector<std::vector<double>>& r, double tau_s, double alpha, int lrv_max_lag)
{
	HeatSourceConfirm c;
	if (power.empty() || !powerChanges(power) || r.empty()) return c;
	const auto g = glsAmplitude(t, commonMode(r, t.size()), powerResponse(t, power, tau_s), lrv_max_lag);
	if (!g.ok) return c;
	c.tested = true;
	c.amplitude_C = g.a;
	c.p = chi2Survival(g.chi2, 1.0);
	c.confirmed = c.p < alpha && g.a > 0;
	return c;
}

}  // namespace mrpt_fog::discrepancy
