/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/WarmupFit.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>

namespace mrpt_fog
{
namespace
{
std::string runName(const std::vector<std::string>& labels, std::size_t i)
{
	return i < labels.size() ? labels[i] : "run " + std::to_string(i + 1);
}

std::string fmt(double v)
{
	std::ostringstream o;
	o.precision(4);
	o << v;
	return o.str();
}

/** The samples of one bin of one span: their times since the turn-on and the mean residual. */
struct Bin
{
	std::size_t span = 0;
	std::vector<double> dt_s;  // time since the turn-on of each sample
	double mean_dph = 0;
};

struct LinearFit
{
	Eigen::VectorXd coef;  // offsets per span, then A
	double rss = std::numeric_limits<double>::infinity();
};

/** Mean of exp(-dt / tau) over a bin's samples. */
double binExp(const Bin& b, double tau_s)
{
	double s = 0;
	for (double d : b.dt_s) s += std::exp(-d / tau_s);
	return s / static_cast<double>(b.dt_s.size());
}

Eigen::MatrixXd designAt(const std::vector<Bin>& bins, std::size_t nspans, double tau_s, bool with_warmup)
{
	Eigen::MatrixXd X = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(bins.size()),
											  static_cast<Eigen::Index>(nspans + (with_warmup ? 1 : 0)));
	for (std::size_t i = 0; i < bins.size(); i++)
	{
		X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(bins[i].span)) = 1.0;
		if (with_warmup) X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(nspans)) = binExp(bins[i], tau_s);
	}
	return X;
}

LinearFit solve(const Eigen::MatrixXd& X, const Eigen::VectorXd& y)
{
	LinearFit f;
	Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(X);
	f.coef = qr.solve(y);
	f.rss = (X * f.coef - y).squaredNorm();
	return f;
}
}  // namespace

WarmupModel fitWarmup(const std::vector<FogSeries>& runs, const Calibration& cal, const WarmupFitOptions& opt,
					  WarmupFitReport* report, const std::vector<std::string>& labels)
{
	if (cal.warmup) throw std::invalid_argument("fitWarmup: the calibration already has a warm-up term");
	if (!(opt.bin_s > 0 && opt.min_tau_s > 0 && opt.max_tau_fraction > 0 && opt.min_span_s > 0))
		throw std::invalid_argument("fitWarmup: bin_s, min_tau_s, max_tau_fraction and min_span_s must be > 0");
	if (runs.empty()) throw WarmupFitError("warm-up: no run given");
	const int axis = static_cast<int>(cal.axis);

	// 1-2. turn-ons, spans and binned residuals
	WarmupFitReport rep;
	std::vector<Bin> bins;
	std::size_t samples = 0;
	double shortest_span = std::numeric_limits<double>::infinity();
	for (std::size_t r = 0; r < runs.size(); r++)
	{
		const FogSeries& s = runs[r];
		if (!s.has_axis[axis]) throw WarmupFitError(runName(labels, r) + ": no " + axisLetter(cal.axis) + " axis");
		const std::size_t n = s.size();
		if (n == 0) throw WarmupFitError(runName(labels, r) + ": no samples");
		std::vector<std::pair<std::size_t, double>> ons;  // first sample index, turn-on time
		const std::string meta = s.metadataValue("power_on_time_s");
		if (!meta.empty())
		{
			char* end = nullptr;
			const double t_on = std::strtod(meta.c_str(), &end);
			if (!std::isfinite(t_on) || *end != '\0')
				throw WarmupFitError(runName(labels, r) + ": metadata power_on_time_s: '" + meta + "' is not a time [s]");
			if (t_on <= s.time_s.front() + 1e-9) ons.emplace_back(0, t_on);
		}
		for (std::size_t k : s.turnOnSamples()) ons.emplace_back(k, s.time_s[k]);
		if (ons.empty())
			throw WarmupFitError(runName(labels, r) +
								 ": holds no turn-on (no 0 -> 1 step in power, no metadata power_on_time_s at or before "
								 "its first sample): a warm-up run starts with the gyro off or cold");
		const CompensatedSeries comp = compensate(cal, s);  // throws on a layout mismatch
		for (const auto& [k0, t_on] : ons)
		{
			std::size_t k1 = k0;
			while (k1 < n && (s.power.empty() || s.power[k1] != 0.0)) k1++;
			const double span = k1 > k0 ? s.time_s[k1 - 1] - t_on : 0.0;  // off at the metadata turn-on: no span
			if (span < opt.min_span_s)
				throw WarmupFitError(runName(labels, r) + ": the gyro stays on for " + fmt(span) + " s after the turn-on at " +
									 fmt(t_on) + " s; the warm-up fit needs " + fmt(opt.min_span_s) + " s or more");
			WarmupFitReport::Span sp;
			sp.run = r;
			sp.t_on_s = t_on;
			const std::size_t span_index = rep.spans.size();
			Bin cur;
			cur.span = span_index;
			double sum = 0;
			long long bin_id = -1;
			auto flush = [&]() {
				if (!cur.dt_s.empty())
				{
					cur.mean_dph = sum / static_cast<double>(cur.dt_s.size());
					bins.push_back(cur);
					sp.bins++;
				}
				cur.dt_s.clear();
				sum = 0;
			};
			for (std::size_t k = k0; k < k1; k++)
			{
				const double e = comp.compensated_dph[k];
				const bool table = !s.table_rate_dph.empty() && s.table_rate_dph[k] != 0.0;
				// Only where the main model (or a fallback) with its rates runs: the term is fitted to
				// what that model leaves after a turn-on; the rate-free start-up model of the first half
				// rate window is another model, whose own error would otherwise pull the fit (on the
				// bundled warm-up run -1.4 deg/h for 30 s, and the time constant to its search edge).
				const bool startup = (comp.flags[k] & (compflags::RateFree | compflags::RateWarmup)) != 0;
				if (table || startup || !std::isfinite(e)) continue;
				const double dt = s.time_s[k] - t_on;
				const auto id = static_cast<long long>(std::floor(dt / opt.bin_s));
				if (id != bin_id) flush(), bin_id = id;
				cur.dt_s.push_back(dt);
				sum += e;
				samples++;
				sp.t_end_s = s.time_s[k];
			}
			flush();
			shortest_span = std::min(shortest_span, span);
			rep.spans.push_back(sp);
		}
	}
	const std::size_t nspans = rep.spans.size();
	if (bins.size() < nspans + 10) throw WarmupFitError("warm-up: too few usable samples after the turn-ons");
	Eigen::VectorXd y(static_cast<Eigen::Index>(bins.size()));
	for (std::size_t i = 0; i < bins.size(); i++) y(static_cast<Eigen::Index>(i)) = bins[i].mean_dph;

	// 3. tau: log grid, then golden section around the best grid point
	rep.tau_min_s = std::max(opt.min_tau_s, 3 * opt.bin_s);
	rep.tau_max_s = opt.max_tau_fraction * shortest_span;
	if (!(rep.tau_max_s > 2 * rep.tau_min_s))
		throw WarmupFitError("warm-up: the spans after the turn-ons (" + fmt(shortest_span) +
							 " s) are too short for the time-constant search");
	const auto rssAt = [&](double log_tau) { return solve(designAt(bins, nspans, std::exp(log_tau), true), y).rss; };
	const int grid = 60;
	const double l0 = std::log(rep.tau_min_s), l1 = std::log(rep.tau_max_s), step = (l1 - l0) / (grid - 1);
	int best = 0;
	double best_rss = std::numeric_limits<double>::infinity();
	for (int g = 0; g < grid; g++)
	{
		const double v = rssAt(l0 + g * step);
		if (v < best_rss) best_rss = v, best = g;
	}
	if (best == 0 || best == grid - 1)
		throw WarmupFitError("warm-up: the best time constant lies at the edge of the search range (" +
							 fmt(std::exp(l0 + best * step)) + " s in " + fmt(rep.tau_min_s) + ".." + fmt(rep.tau_max_s) +
							 " s): no decaying turn-on transient is resolved in these runs");
	double a = l0 + (best - 1) * step, b = l0 + (best + 1) * step;
	const double gr = 0.5 * (std::sqrt(5.0) - 1);
	double c = b - gr * (b - a), d = a + gr * (b - a), fc = rssAt(c), fd = rssAt(d);
	for (int it = 0; it < 40 && b - a > 1e-6; it++)
	{
		if (fc < fd) b = d, d = c, fd = fc, c = b - gr * (b - a), fc = rssAt(c);
		else a = c, c = d, fc = fd, d = a + gr * (b - a), fd = rssAt(d);
	}
	const double tau = std::exp(0.5 * (a + b));
	const Eigen::MatrixXd X = designAt(bins, nspans, tau, true);
	const LinearFit fit = solve(X, y);
	const LinearFit base = solve(designAt(bins, nspans, tau, false), y);
	const double A = fit.coef(static_cast<Eigen::Index>(nspans));

	// 4. uncertainties: Gauss-Newton covariance with an AR(1) variance inflation
	const Eigen::VectorXd res = y - X * fit.coef;
	double r1 = 0;
	{
		double num = 0, den = 0;
		for (Eigen::Index i = 0; i < res.size(); i++)
		{
			den += res(i) * res(i);
			if (i > 0 && bins[static_cast<std::size_t>(i)].span == bins[static_cast<std::size_t>(i - 1)].span)
				num += res(i) * res(i - 1);
		}
		r1 = den > 0 ? std::clamp(num / den, 0.0, 0.99) : 0.0;
	}
	const Eigen::Index p = X.cols() + 1;
	Eigen::MatrixXd J(X.rows(), p);
	J.leftCols(X.cols()) = X;
	for (std::size_t i = 0; i < bins.size(); i++)
	{
		double s = 0;
		for (double dt : bins[i].dt_s) s += std::exp(-dt / tau) * dt / (tau * tau);
		J(static_cast<Eigen::Index>(i), p - 1) = A * s / static_cast<double>(bins[i].dt_s.size());
	}
	const double dof = static_cast<double>(bins.size()) - static_cast<double>(p);
	const double sigma2 = fit.rss / dof * (1 + r1) / (1 - r1);
	const Eigen::MatrixXd cov = sigma2 * (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse();

	const double A_std = std::sqrt(std::max(0.0, cov(p - 2, p - 2)));
	if (!(std::abs(A) >= 3 * A_std))
		throw WarmupFitError("warm-up: no turn-on transient resolved: amplitude " + fmt(A) + " +- " + fmt(A_std) +
							 " deg/h (under 3 standard errors) after the bias model");
	WarmupModel w;
	w.amplitude_dph = A;
	w.tau_s = tau;
	w.amplitude_std_dph = A_std;
	w.tau_std_s = std::sqrt(std::max(0.0, cov(p - 1, p - 1)));
	w.turn_ons = nspans;
	w.samples = samples;
	for (const auto& sp : rep.spans) w.fitted_span_s = std::max(w.fitted_span_s, sp.t_end_s - sp.t_on_s);
	w.rms_before_dph = std::sqrt(base.rss / static_cast<double>(bins.size()));
	w.rms_after_dph = std::sqrt(fit.rss / static_cast<double>(bins.size()));
	for (std::size_t j = 0; j < nspans; j++) rep.spans[j].offset_dph = fit.coef(static_cast<Eigen::Index>(j));
	rep.lag1_autocorrelation = r1;
	if (report) *report = std::move(rep);
	return w;
}

}  // namespace mrpt_fog
