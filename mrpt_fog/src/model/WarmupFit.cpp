/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/model/CalibrationFitStages.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/WarmupFit.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>

namespace mrpt_fog
{
namespace
{
using calibration_fit::runName;

/** 4 significant digits, as an ostream at precision 4 (the messages' format). */
std::string fmt(double v) { return formatValue("%.4g", v); }

/** The samples of one bin of one span: their times since the turn-on and the mean residual. */
struct Bin
{
	std::size_t span = 0;
	std::vector<double> dt_s;  // time since the turn-on of each sample
	double mean_dph = 0;
};

struct WarmupLinearFit
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

/** Offsets per span, then one column per time constant (none: offsets only). */
Eigen::MatrixXd designAt(const std::vector<Bin>& bins, std::size_t nspans, const std::vector<double>& taus_s)
{
	Eigen::MatrixXd X = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(bins.size()),
											  static_cast<Eigen::Index>(nspans + taus_s.size()));
	for (std::size_t i = 0; i < bins.size(); i++)
	{
		X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(bins[i].span)) = 1.0;
		for (std::size_t m = 0; m < taus_s.size(); m++)
			X(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(nspans + m)) = binExp(bins[i], taus_s[m]);
	}
	return X;
}

WarmupLinearFit solve(const Eigen::MatrixXd& X, const Eigen::VectorXd& y)
{
	WarmupLinearFit f;
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
	if (opt.exponentials != 1 && opt.exponentials != 2)
		throw std::invalid_argument("fitWarmup: exponentials must be 1 or 2");
	if (!(opt.bin_s > 0 && opt.min_tau_s > 0 && opt.max_tau_fraction > 0 && opt.min_span_s > 0))
		throw std::invalid_argument("fitWarmup: bin_s, min_tau_s, max_tau_fraction and min_span_s must be > 0");
	if (runs.empty()) throw WarmupFitError("warm-up: no run given");
	const int axis = static_cast<int>(cal.axis);

	// 1-2. turn-ons, spans and binned residuals
	WarmupFitReport rep;
	std::vector<Bin> bins;
	struct StartupSample
	{
		std::size_t span;
		double dt_s, e_dph;
	};
	std::vector<StartupSample> startup;  // rate-free start-up samples in the first rate window after a turn-on
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
				const bool startup_sample = (comp.flags[k] & (CompensationFlag::RateFree | CompensationFlag::RateWarmup)) != 0;
				const double dt = s.time_s[k] - t_on;
				// ... but that model's error right after a turn-on is fitted apart (startup_offset_dph),
				// on the samples where the compensator adds it (WarmupModel.h)
				if (!table && std::isfinite(e) && (comp.flags[k] & CompensationFlag::RateFree) != 0 &&
					dt <= cal.rate_estimator.window_s)
					startup.push_back({span_index, dt, e});
				if (table || startup_sample || !std::isfinite(e)) continue;
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

	// 3. time constants: log grid (pairs tau1 < tau2 for two terms), then golden section on each
	// in turn around the best grid point
	const std::size_t m_terms = opt.exponentials;
	rep.tau_min_s = std::max(opt.min_tau_s, 3 * opt.bin_s);
	rep.tau_max_s = opt.max_tau_fraction * shortest_span;
	if (!(rep.tau_max_s > 2 * rep.tau_min_s))
		throw WarmupFitError("warm-up: the spans after the turn-ons (" + fmt(shortest_span) +
							 " s) are too short for the time-constant search");
	const auto rssAt = [&](const std::vector<double>& log_taus) {
		std::vector<double> taus;
		for (double l : log_taus) taus.push_back(std::exp(l));
		return solve(designAt(bins, nspans, taus), y).rss;
	};
	const int grid = m_terms == 1 ? 60 : 40;
	const double l0 = std::log(rep.tau_min_s), l1 = std::log(rep.tau_max_s), step = (l1 - l0) / (grid - 1);
	std::vector<int> best(m_terms, 0);
	double best_rss = std::numeric_limits<double>::infinity();
	if (m_terms == 1)
		for (int g = 0; g < grid; g++)
		{
			const double v = rssAt({l0 + g * step});
			if (v < best_rss) best_rss = v, best = {g};
		}
	else
		for (int g = 0; g < grid; g++)
			for (int h = g + 1; h < grid; h++)
			{
				const double v = rssAt({l0 + g * step, l0 + h * step});
				if (v < best_rss) best_rss = v, best = {g, h};
			}
	for (int g : best)
		if (g == 0 || g == grid - 1)
			throw WarmupFitError("warm-up: the best time constant lies at the edge of the search range (" +
								 fmt(std::exp(l0 + g * step)) + " s in " + fmt(rep.tau_min_s) + ".." + fmt(rep.tau_max_s) +
								 " s): no decaying turn-on transient " +
								 (m_terms == 1 ? "is" : "with two time constants is") + " resolved in these runs");
	std::vector<double> lt;
	for (int g : best) lt.push_back(l0 + g * step);
	const double gr = 0.5 * (std::sqrt(5.0) - 1);
	for (int round = 0; round < (m_terms == 1 ? 1 : 4); round++)
		for (std::size_t m = 0; m < m_terms; m++)
		{
			const auto f = [&](double v) {
				std::vector<double> q = lt;
				q[m] = v;
				return rssAt(q);
			};
			double a = lt[m] - step, b = lt[m] + step;
			double c = b - gr * (b - a), d = a + gr * (b - a), fc = f(c), fd = f(d);
			for (int it = 0; it < 40 && b - a > 1e-6; it++)
			{
				if (fc < fd) b = d, d = c, fd = fc, c = b - gr * (b - a), fc = f(c);
				else a = c, c = d, fc = fd, d = a + gr * (b - a), fd = f(d);
			}
			lt[m] = 0.5 * (a + b);
		}
	std::sort(lt.begin(), lt.end());
	std::vector<double> taus;
	for (double l : lt) taus.push_back(std::exp(l));
	const Eigen::MatrixXd X = designAt(bins, nspans, taus);
	const WarmupLinearFit fit = solve(X, y);
	const WarmupLinearFit base = solve(designAt(bins, nspans, {}), y);
	std::vector<double> amps;
	for (std::size_t m = 0; m < m_terms; m++) amps.push_back(fit.coef(static_cast<Eigen::Index>(nspans + m)));

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
	const Eigen::Index p = X.cols() + static_cast<Eigen::Index>(m_terms);
	Eigen::MatrixXd J(X.rows(), p);
	J.leftCols(X.cols()) = X;
	for (std::size_t i = 0; i < bins.size(); i++)
		for (std::size_t m = 0; m < m_terms; m++)
		{
			double sd = 0;
			for (double dt : bins[i].dt_s) sd += std::exp(-dt / taus[m]) * dt / (taus[m] * taus[m]);
			J(static_cast<Eigen::Index>(i), X.cols() + static_cast<Eigen::Index>(m)) =
				amps[m] * sd / static_cast<double>(bins[i].dt_s.size());
		}
	const double dof = static_cast<double>(bins.size()) - static_cast<double>(p);
	const double sigma2 = fit.rss / dof * (1 + r1) / (1 - r1);
	const Eigen::MatrixXd cov = sigma2 * (J.transpose() * J).completeOrthogonalDecomposition().pseudoInverse();
	std::vector<double> amp_std, tau_std;
	for (std::size_t m = 0; m < m_terms; m++)
	{
		const Eigen::Index ia = static_cast<Eigen::Index>(nspans + m), it = X.cols() + static_cast<Eigen::Index>(m);
		amp_std.push_back(std::sqrt(std::max(0.0, cov(ia, ia))));
		tau_std.push_back(std::sqrt(std::max(0.0, cov(it, it))));
	}
	// A transient at all: the clearest term over 3 standard errors (whether a second term is worth
	// it is a held-out question: selectWarmupTerms).
	std::size_t clearest = 0;
	for (std::size_t m = 1; m < m_terms; m++)
		if (std::abs(amps[m]) * amp_std[clearest] > std::abs(amps[clearest]) * amp_std[m]) clearest = m;
	if (!(std::abs(amps[clearest]) >= 3 * amp_std[clearest]))
		throw WarmupFitError("warm-up: no turn-on transient resolved: amplitude " + fmt(amps[clearest]) + " +- " +
							 fmt(amp_std[clearest]) + " deg/h" +
							 (m_terms > 1 ? " (tau " + fmt(taus[clearest]) + " s, the clearer of two terms)" : "") +
							 " (under 3 standard errors) after the bias model");
	const double A = amps[0], tau = taus[0];
	WarmupModel w;
	w.amplitude_dph = A;
	w.tau_s = tau;
	w.amplitude_std_dph = amp_std[0];
	w.tau_std_s = tau_std[0];
	if (m_terms == 2)
	{
		w.amplitude2_dph = amps[1];
		w.tau2_s = taus[1];
		w.amplitude2_std_dph = amp_std[1];
		w.tau2_std_s = tau_std[1];
	}
	w.turn_ons = nspans;
	w.samples = samples;
	for (const auto& sp : rep.spans) w.fitted_span_s = std::max(w.fitted_span_s, sp.t_end_s - sp.t_on_s);
	w.rms_before_dph = std::sqrt(base.rss / static_cast<double>(bins.size()));
	w.rms_after_dph = std::sqrt(fit.rss / static_cast<double>(bins.size()));
	for (std::size_t j = 0; j < nspans; j++) rep.spans[j].offset_dph = fit.coef(static_cast<Eigen::Index>(j));
	// 5. the start-up model's error right after the turn-ons: the mean residual of its samples
	// there, after the span's offset (not applied) and the warm-up term; standard error from the
	// samples' spread (white noise dominates over 30 s)
	if (!startup.empty())
	{
		double sum = 0, sum2 = 0;
		for (const auto& u : startup)
		{
			const double r = u.e_dph - fit.coef(static_cast<Eigen::Index>(u.span)) - w.bias_dph(u.dt_s);
			sum += r, sum2 += r * r;
		}
		const double n = static_cast<double>(startup.size());
		w.startup_offset_dph = sum / n;
		const double var = n > 1 ? std::max(0.0, (sum2 - sum * sum / n) / (n - 1)) : 0.0;
		w.startup_offset_std_dph = std::sqrt(var / n);
		w.startup_samples = startup.size();
	}
	rep.lag1_autocorrelation = r1;
	if (report) *report = std::move(rep);
	return w;
}

}  // namespace mrpt_fog

namespace mrpt_fog
{
WarmupTermsChoice selectWarmupTerms(const std::vector<FogSeries>& runs, const Calibration& cal,
									const WarmupFitOptions& opt, const std::vector<std::string>& labels)
{
	WarmupTermsChoice c;
	if (runs.size() < 2)
	{
		c.why = "one warm-up run: no other run to judge a second term on; one term";
		return c;
	}
	c.judged = true;
	for (std::size_t m = 1; m <= 2; m++)
	{
		double ss = 0;
		std::size_t nb = 0;
		bool ok = true;
		for (std::size_t h = 0; h < runs.size() && ok; h++)
		{
			std::vector<FogSeries> train;
			std::vector<std::string> train_labels;
			for (std::size_t r = 0; r < runs.size(); r++)
				if (r != h)
				{
					train.push_back(runs[r]);
					train_labels.push_back(runName(labels, r));
				}
			WarmupFitOptions o = opt;
			o.exponentials = m;
			Calibration with = cal;
			try
			{
				with.warmup = fitWarmup(train, cal, o, nullptr, train_labels);
			}
			catch (const WarmupFitError&)
			{
				ok = false;  // this many terms cannot be fitted without run h
				break;
			}
			// held-out run h: binned residual after the term, each turn-on span about its own mean
			// (the bias model's static error there, which the term does not carry)
			const FogSeries& s = runs[h];
			const CompensatedSeries comp = compensate(with, s);
			const int axis = static_cast<int>(cal.axis);
			std::vector<double> means;
			double bsum = 0;
			std::size_t bn = 0;
			long long bid = -1;
			double t_on = s.time_s.empty() ? 0.0 : s.time_s.front();
			auto flushBin = [&]() {
				if (bn) means.push_back(bsum / static_cast<double>(bn));
				bsum = 0, bn = 0;
			};
			auto flushSpan = [&]() {
				flushBin();
				if (means.size() > 1)
				{
					double mu = 0;
					for (double v : means) mu += v;
					mu /= static_cast<double>(means.size());
					for (double v : means) ss += (v - mu) * (v - mu), nb++;
				}
				means.clear();
				bid = -1;
			};
			for (std::size_t k = 0; k < s.size(); k++)
			{
				if (k > 0 && !s.power.empty() && s.power[k] != 0.0 && s.power[k - 1] == 0.0)
				{
					flushSpan();
					t_on = s.time_s[k];
				}
				const double e = comp.compensated_dph[k];
				const bool table = !s.table_rate_dph.empty() && s.table_rate_dph[k] != 0.0;
				const bool skip = (comp.flags[k] & (CompensationFlag::RateFree | CompensationFlag::RateWarmup)) != 0;
				if (table || skip || !std::isfinite(e) || !s.has_axis[axis]) continue;
				const auto id = static_cast<long long>(std::floor((s.time_s[k] - t_on) / opt.bin_s));
				if (id != bid) flushBin(), bid = id;
				bsum += e, bn++;
			}
			flushSpan();
		}
		c.held_out_rms_dph[m - 1] = ok && nb > 0 ? std::sqrt(ss / static_cast<double>(nb))
												 : std::numeric_limits<double>::infinity();
	}
	c.exponentials = c.held_out_rms_dph[1] < c.held_out_rms_dph[0] ? 2 : 1;
	c.why = "leave-one-run-out over " + std::to_string(runs.size()) + " warm-up runs: held-out RMS " +
			fmt(c.held_out_rms_dph[0]) + " (1 term) vs " + fmt(c.held_out_rms_dph[1]) + " deg/h (2 terms)";
	return c;
}
}  // namespace mrpt_fog
