/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/CalibrationFitStages.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/model/ScaleFactorFit.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace mrpt_fog
{
namespace
{
using calibration_fit::runName;

/** Two-sided 95 % quantile of Student's t with dof degrees of freedom (table to 30, then the
 * Cornish-Fisher expansion, error < 1e-4 there). */
double tQuantile975(std::size_t dof)
{
	static const double table[] = {12.706, 4.303, 3.182, 2.776, 2.571, 2.447, 2.365, 2.306, 2.262, 2.228,
								   2.201,  2.179, 2.160, 2.145, 2.131, 2.120, 2.110, 2.101, 2.093, 2.086,
								   2.080,  2.074, 2.069, 2.064, 2.060, 2.056, 2.052, 2.048, 2.045, 2.042};
	if (dof == 0) return std::numeric_limits<double>::infinity();
	if (dof <= 30) return table[dof - 1];
	const double z = 1.959963984540054, n = static_cast<double>(dof);
	const double z3 = z * z * z, z5 = z3 * z * z, z7 = z5 * z * z;
	return z + (z3 + z) / (4 * n) + (5 * z5 + 16 * z3 + 3 * z) / (96 * n * n) +
		   (3 * z7 + 19 * z5 + 17 * z3 - 15 * z) / (384 * n * n * n);
}

struct Poly
{
	Eigen::VectorXd coef;
	Eigen::MatrixXd inv_normal;  // (Z'Z)^-1
	double rss = 0;
};

Eigen::MatrixXd design(const std::vector<double>& z, int order)
{
	Eigen::MatrixXd X(static_cast<Eigen::Index>(z.size()), order + 1);
	for (std::size_t i = 0; i < z.size(); i++)
	{
		double p = 1;
		for (int k = 0; k <= order; k++, p *= z[i]) X(static_cast<Eigen::Index>(i), k) = p;
	}
	return X;
}

Poly fitPoly(const std::vector<double>& z, const std::vector<double>& y, int order)
{
	const Eigen::MatrixXd X = design(z, order);
	const Eigen::VectorXd Y = Eigen::Map<const Eigen::VectorXd>(y.data(), static_cast<Eigen::Index>(y.size()));
	Eigen::HouseholderQR<Eigen::MatrixXd> qr(X);
	Poly p;
	p.coef = qr.solve(Y);
	const Eigen::MatrixXd R = qr.matrixQR().topRows(order + 1).triangularView<Eigen::Upper>();
	const Eigen::MatrixXd Rinv = R.triangularView<Eigen::Upper>().solve(Eigen::MatrixXd::Identity(order + 1, order + 1));
	p.inv_normal = Rinv * Rinv.transpose();
	p.rss = (X * p.coef - Y).squaredNorm();
	return p;
}

double evalPoly(const Eigen::VectorXd& c, double z)
{
	double h = 0;
	for (Eigen::Index k = c.size(); k-- > 0;) h = h * z + c(k);
	return h;
}
}  // namespace

bool hasTableRates(const std::vector<FogSeries>& runs)
{
	for (const auto& r : runs)
		for (std::size_t k = 0; k < r.table_rate_dph.size(); k++)
			if (r.table_rate_dph[k] != 0.0 && (r.power.empty() || r.power[k] != 0.0)) return true;
	return false;
}

ScaleFactorModel fitScaleFactor(const std::vector<FogSeries>& runs, const Calibration& bias_cal,
								const ScaleFactorFitOptions& opt, ScaleFactorFitReport* report,
								const std::vector<std::string>& labels)
{
	if (bias_cal.scale_factor) throw std::invalid_argument("fitScaleFactor: the bias calibration already has a scale factor");
	if (!(opt.max_order >= 0 && opt.max_order <= 5)) throw std::invalid_argument("fitScaleFactor: max_order must be 0..5");
	if (!(opt.min_order >= 0 && opt.min_order <= opt.max_order))
		throw std::invalid_argument("fitScaleFactor: min_order must be 0..max_order");
	if (!(opt.settle_s >= 0 && opt.min_segment_s > 0 && opt.group_gap_C > 0))
		throw std::invalid_argument("fitScaleFactor: settle_s >= 0, min_segment_s > 0 and group_gap_C > 0 required");
	const int axis = static_cast<int>(bias_cal.axis);
	const std::size_t nt = bias_cal.layout.size();
	if (nt == 0) throw ScaleFactorFitError("scale factor: the calibration has no thermistor to model it in");

	// 1-2. segments and their scale-factor estimates
	std::vector<ScaleFactorSegment> segs;
	bool any_table = false;
	for (std::size_t r = 0; r < runs.size(); r++)
	{
		const FogSeries& s = runs[r];
		if (s.table_rate_dph.empty()) continue;
		any_table = true;
		if (!s.has_axis[axis]) throw ScaleFactorFitError(runName(labels, r) + ": no " + axisLetter(bias_cal.axis) + " axis");
		std::vector<int> col;
		for (const auto& t : bias_cal.layout) col.push_back(s.thermistorIndex(t.name));
		const CompensatedSeries comp = compensate(bias_cal, s);  // throws on a layout mismatch
		const auto& raw = s.rate_dph[axis];
		const std::size_t n = s.size();
		std::size_t k = 0;
		while (k < n)
		{
			const double w = s.table_rate_dph[k];
			const bool on = s.power.empty() || s.power[k] != 0.0;
			std::size_t e = k + 1;
			while (e < n && s.table_rate_dph[e] == w && (s.power.empty() || s.power[e] != 0.0) == on) e++;
			if (w != 0.0 && on && std::isfinite(w))
			{
				ScaleFactorSegment g;
				g.run = r;
				g.applied_dph = w;
				g.temp_C.assign(nt, 0.0);
				std::vector<std::size_t> tcount(nt, 0);
				double sum_e = 0;
				const double t0 = s.time_s[k] + opt.settle_s;
				for (std::size_t j = k; j < e; j++)
				{
					if (s.time_s[j] < t0) continue;
					const double ej = raw[j] - comp.bias_dph[j] - w;
					if (!std::isfinite(ej)) continue;
					bool all_t = true;
					for (std::size_t i = 0; i < nt; i++) all_t &= col[i] >= 0 && std::isfinite(s.temp_C[col[i]][j]);
					if (!all_t) continue;  // a dropout: the segment's temperatures must be whole
					for (std::size_t i = 0; i < nt; i++) g.temp_C[i] += s.temp_C[col[i]][j];
					sum_e += ej;
					if (g.samples == 0) g.t_begin_s = s.time_s[j];
					g.t_end_s = s.time_s[j];
					g.samples++;
				}
				if (g.samples >= 2 && g.t_end_s - g.t_begin_s >= opt.min_segment_s)
				{
					for (auto& v : g.temp_C) v /= static_cast<double>(g.samples);
					g.s_ppm = 1e6 * (sum_e / static_cast<double>(g.samples)) / w;
					segs.push_back(std::move(g));
				}
			}
			k = e;
		}
	}
	if (!any_table) throw ScaleFactorFitError("scale factor: no run has a table_rate_dph column");
	if (segs.empty())
		throw ScaleFactorFitError("scale factor: no table segment of a constant non-zero rate lasts " +
								  formatValue("%.4g", opt.settle_s + opt.min_segment_s) + " s or more with the gyro powered");
	bool pos = false, neg = false;
	for (const auto& g : segs) (g.applied_dph > 0 ? pos : neg) = true;
	if (!(pos && neg))
		throw ScaleFactorFitError(std::string("scale factor: all table segments turn one way (") + (pos ? "+" : "-") +
								  "): a bias error cannot be told from a scale-factor error; apply both signs");

	// 3. temperature groups by the mean over the thermistors
	std::vector<double> tmean(segs.size());
	for (std::size_t i = 0; i < segs.size(); i++)
		tmean[i] = std::accumulate(segs[i].temp_C.begin(), segs[i].temp_C.end(), 0.0) / static_cast<double>(nt);
	std::vector<std::size_t> order_idx(segs.size());
	std::iota(order_idx.begin(), order_idx.end(), 0);
	std::sort(order_idx.begin(), order_idx.end(), [&](std::size_t a, std::size_t b) { return tmean[a] < tmean[b]; });
	// A group also closes once it spans more than group_gap_C: segments in a ramp or a turn-on
	// follow each other closer than the gap and would otherwise chain into one group (soaks are
	// unaffected: their segments lie within a fraction of a degree).
	int groups = 0;
	double group_first_C = tmean.empty() ? 0.0 : tmean[order_idx.front()];
	for (std::size_t q = 0; q < order_idx.size(); q++)
	{
		const double tq = tmean[order_idx[q]];
		if (q > 0 && (tq - tmean[order_idx[q - 1]] > opt.group_gap_C || tq - group_first_C > opt.group_gap_C))
			groups++, group_first_C = tq;
		segs[order_idx[q]].group = groups;
	}
	groups++;
	const double span = tmean[order_idx.back()] - tmean[order_idx.front()];
	if (groups < 2 || span < opt.min_span_C)
		throw ScaleFactorFitError("scale factor: the table segments cover " + formatValue("%.4g", span) + " degC in " +
								  std::to_string(groups) + " temperature group(s); at least 2 soaks " + formatValue("%.4g", opt.min_span_C) +
								  " degC apart are needed to fit a temperature dependence");
	if (opt.min_order + 2 > groups)
		throw ScaleFactorFitError("scale factor: order " + std::to_string(opt.min_order) + " or more needs " +
								  std::to_string(opt.min_order + 2) + " soaks to be chosen by leave-one-temperature-out error; the table "
								  "segments form " + std::to_string(groups) + " temperature group(s)");

	// 4. candidates by leave-one-temperature-out error
	std::vector<double> y(segs.size());
	for (std::size_t i = 0; i < segs.size(); i++) y[i] = segs[i].s_ppm;
	ScaleFactorFitReport rep;
	rep.groups = static_cast<std::size_t>(groups);
	struct Best
	{
		std::size_t therm = 0;
		int order = 0;
		double cv = std::numeric_limits<double>::infinity();
	};
	std::vector<Best> all;
	const auto zOf = [&](std::size_t th, double& centre, double& scale, double& lo, double& hi) {
		lo = std::numeric_limits<double>::infinity();
		hi = -lo;
		for (const auto& g : segs)
		{
			lo = std::min(lo, g.temp_C[th]);
			hi = std::max(hi, g.temp_C[th]);
		}
		centre = 0.5 * (lo + hi);
		scale = std::max(0.5 * (hi - lo), 1e-9);
		std::vector<double> z(segs.size());
		for (std::size_t i = 0; i < segs.size(); i++) z[i] = (segs[i].temp_C[th] - centre) / scale;
		return z;
	};
	// thermistor_mean: one more temperature column, the mean of the thermistors, the only candidate
	if (opt.thermistor_mean)
		for (auto& g : segs)
			g.temp_C.push_back(std::accumulate(g.temp_C.begin(), g.temp_C.begin() + static_cast<std::ptrdiff_t>(nt), 0.0) /
							   static_cast<double>(nt));
	const auto candName = [&](std::size_t th) { return th < nt ? bias_cal.layout[th].name : std::string("mean"); };
	for (std::size_t th = opt.thermistor_mean ? nt : 0; th < (opt.thermistor_mean ? nt + 1 : nt); th++)
	{
		double c, sc, lo, hi;
		const std::vector<double> z = zOf(th, c, sc, lo, hi);
		for (int order = opt.min_order; order <= opt.max_order && order + 2 <= groups; order++)
		{
			double sse = 0;
			for (int g = 0; g < groups; g++)
			{
				std::vector<double> zt, yt;
				for (std::size_t i = 0; i < segs.size(); i++)
					if (segs[i].group != g)
					{
						zt.push_back(z[i]);
						yt.push_back(y[i]);
					}
				const Poly p = fitPoly(zt, yt, order);
				for (std::size_t i = 0; i < segs.size(); i++)
					if (segs[i].group == g)
					{
						const double r = y[i] - evalPoly(p.coef, z[i]);
						sse += r * r;
					}
			}
			const double cv = std::sqrt(sse / static_cast<double>(segs.size()));
			rep.candidates.push_back({candName(th), order, cv});
			all.push_back({th, order, cv});
		}
	}
	// The weighted candidate: s = c + sum_i a_i T_i over all thermistors (order 1), i.e. order 1
	// in a weighted temperature T_w = sum_i (a_i / sum a) T_i. Only data where the thermistors
	// disagree (table segments in ramps and turn-ons) can determine the weights; at soaks they
	// move together and the held-out error of this candidate says so. Needs nt + 2 groups.
	const std::size_t kWeighted = nt + 1;  // candidate index (nt is the mean)
	const auto weightedFit = [&](int leave_out, Eigen::VectorXd& a) {
		std::size_t m = 0;
		for (const auto& g : segs) m += g.group != leave_out;
		Eigen::MatrixXd X(static_cast<Eigen::Index>(m), static_cast<Eigen::Index>(nt + 1));
		Eigen::VectorXd yy(static_cast<Eigen::Index>(m));
		Eigen::Index row = 0;
		for (std::size_t i = 0; i < segs.size(); i++)
		{
			if (segs[i].group == leave_out) continue;
			X(row, 0) = 1.0;
			for (std::size_t th = 0; th < nt; th++) X(row, static_cast<Eigen::Index>(th + 1)) = segs[i].temp_C[th];
			yy(row++) = y[i];
		}
		a = X.completeOrthogonalDecomposition().solve(yy);
	};
	if (!opt.thermistor_mean && nt >= 2 && static_cast<int>(nt) + 2 <= groups && opt.min_order <= 1)
	{
		double sse = 0;
		for (int g = 0; g < groups; g++)
		{
			Eigen::VectorXd a;
			weightedFit(g, a);
			for (std::size_t i = 0; i < segs.size(); i++)
				if (segs[i].group == g)
				{
					double pred = a(0);
					for (std::size_t th = 0; th < nt; th++) pred += a(static_cast<Eigen::Index>(th + 1)) * segs[i].temp_C[th];
					sse += (y[i] - pred) * (y[i] - pred);
				}
		}
		const double cv = std::sqrt(sse / static_cast<double>(segs.size()));
		rep.candidates.push_back({"weighted", 1, std::isfinite(cv) ? cv : std::numeric_limits<double>::infinity()});
		if (std::isfinite(cv)) all.push_back({kWeighted, 1, cv});
	}
	double best_cv = std::numeric_limits<double>::infinity();
	for (const auto& b : all) best_cv = std::min(best_cv, b.cv);
	// the fewest parameters within prefer_simpler of the best (one thermistor of order k: k + 1;
	// the weighted candidate: nt + 1), then the smaller held-out error
	const auto params = [&](const Best& b) { return b.therm == kWeighted ? nt + 1 : static_cast<std::size_t>(b.order) + 1; };
	Best pick;
	bool picked = false;
	for (const auto& b : all)
		if (b.cv <= (1 + opt.prefer_simpler) * best_cv &&
			(!picked || params(b) < params(pick) || (params(b) == params(pick) && b.cv < pick.cv)))
			pick = b, picked = true;

	// 5. final fit on every thermistor with the chosen order: the model's, and the slopes that
	// bound the errors in the temperature variable (6.)
	const std::size_t np = static_cast<std::size_t>(pick.order) + 1, dof = segs.size() > np ? segs.size() - np : 0;
	struct ThermFit
	{
		double centre = 0, scale = 1, lo = 0, hi = 0;
		Poly p;
		Eigen::MatrixXd cov;
		double slope = 0, half = 0;
	};
	const auto fitOn = [&](std::size_t th) {
		ThermFit f;
		const std::vector<double> z = zOf(th, f.centre, f.scale, f.lo, f.hi);
		f.p = fitPoly(z, y, pick.order);
		const double sigma2 = dof > 0 ? f.p.rss / static_cast<double>(dof) : std::numeric_limits<double>::quiet_NaN();
		f.cov = sigma2 * f.p.inv_normal;
		// mean slope over the calibrated range: a linear functional g . coef
		Eigen::VectorXd gvec(static_cast<Eigen::Index>(np));
		const double zl = (f.lo - f.centre) / f.scale, zh = (f.hi - f.centre) / f.scale;
		for (std::size_t k = 0; k < np; k++)
			gvec(static_cast<Eigen::Index>(k)) =
				(std::pow(zh, static_cast<double>(k)) - std::pow(zl, static_cast<double>(k))) / (f.hi - f.lo);
		f.slope = gvec.dot(f.p.coef);
		f.half = tQuantile975(dof) * std::sqrt(std::max(0.0, gvec.dot(f.cov * gvec)));
		return f;
	};
	ScaleFactorModel m;
	if (pick.therm == kWeighted)
	{
		Eigen::VectorXd a;
		weightedFit(-1, a);
		const double slope_sum = a.tail(static_cast<Eigen::Index>(nt)).sum();
		if (!(std::abs(slope_sum) > 0))
			throw ScaleFactorFitError("scale factor: the weighted fit found no temperature dependence");
		for (std::size_t th = 0; th < nt; th++) m.weights.push_back(a(static_cast<Eigen::Index>(th + 1)) / slope_sum);
		// the weighted temperature as one more column (index nt + 1; the mean's nt may be unused)
		for (auto& g : segs)
		{
			double tw = 0;
			for (std::size_t th = 0; th < nt; th++) tw += m.weights[th] * g.temp_C[th];
			g.temp_C.resize(nt + 1, std::numeric_limits<double>::quiet_NaN());
			g.temp_C.push_back(tw);
		}
	}
	const ThermFit own = fitOn(pick.therm);
	m.thermistor = pick.therm == kWeighted ? std::string("weighted") : candName(pick.therm);
	if (pick.therm >= nt)
		for (const auto& t : bias_cal.layout) m.thermistors.push_back(t.name);
	m.centre_C = own.centre;
	m.scale_C = own.scale;
	m.min_C = own.lo;
	m.max_C = own.hi;
	m.coef_ppm.assign(own.p.coef.data(), own.p.coef.data() + own.p.coef.size());
	m.covariance_ppm2 = own.cov;
	m.slope_ppm_per_C = own.slope;
	m.slope_noise_ci95_lo_ppm_per_C = own.slope - own.half;
	m.slope_noise_ci95_hi_ppm_per_C = own.slope + own.half;
	m.slope_ci95_lo_ppm_per_C = m.slope_noise_ci95_lo_ppm_per_C;
	m.slope_ci95_hi_ppm_per_C = m.slope_noise_ci95_hi_ppm_per_C;
	m.slope_thermistor_min_ppm_per_C = m.slope_thermistor_max_ppm_per_C = own.slope;
	m.slope_thermistors = pick.therm < nt ? 1 : 0;  // the mean or weighted sum is not one of them
	for (std::size_t th = 0; th < nt; th++)
	{
		if (th == pick.therm) continue;
		const ThermFit f = fitOn(th);
		if (!(f.hi - f.lo >= opt.min_span_C) || !std::isfinite(f.slope)) continue;  // no usable span on this one
		m.slope_thermistors++;
		m.slope_thermistor_min_ppm_per_C = std::min(m.slope_thermistor_min_ppm_per_C, f.slope);
		m.slope_thermistor_max_ppm_per_C = std::max(m.slope_thermistor_max_ppm_per_C, f.slope);
		m.slope_ci95_lo_ppm_per_C = std::min(m.slope_ci95_lo_ppm_per_C, f.slope - f.half);
		m.slope_ci95_hi_ppm_per_C = std::max(m.slope_ci95_hi_ppm_per_C, f.slope + f.half);
	}
	m.table_rate_min_abs_dph = std::numeric_limits<double>::infinity();
	m.table_rate_max_abs_dph = 0;
	for (const auto& g : segs)
	{
		m.table_rate_min_abs_dph = std::min(m.table_rate_min_abs_dph, std::abs(g.applied_dph));
		m.table_rate_max_abs_dph = std::max(m.table_rate_max_abs_dph, std::abs(g.applied_dph));
		m.samples += g.samples;
	}
	m.segments = segs.size();
	m.rms_in_sample_ppm = std::sqrt(own.p.rss / static_cast<double>(segs.size()));
	m.rms_held_out_ppm = pick.cv;
	m.held_out_label = "leave-one-temperature-out (" + std::to_string(groups) + " soaks, " +
					   std::to_string(segs.size()) + " segments)";
	if (report)
	{
		rep.segments = segs;
		*report = std::move(rep);
	}
	return m;
}

}  // namespace mrpt_fog
