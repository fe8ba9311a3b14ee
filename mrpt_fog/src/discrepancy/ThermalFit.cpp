/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/ThermalFit.h>
#include <mrpt_fog/common/NumberFormat.h>

#include <cmath>

namespace mrpt_fog::discrepancy
{
const char* toString(ThermalFix f)
{
	switch (f)
	{
		case ThermalFix::None: return "none";
		case ThermalFix::Lag: return "lag";
		case ThermalFix::HeatSource: return "heat_source";
		case ThermalFix::MissingNode: return "missing_node";
	}
	return "none";
}

namespace
{
/** Pooled explained share of r_i ~ a_i + b x_i (per thermistor) and the pooled slope. */
struct Explained
{
	double share = 0, slope = 0;
};
Explained explain(const std::vector<std::vector<double>>& r, const std::vector<std::vector<double>>& x)
{
	double sst = 0, sse = 0, sxy = 0, sxx = 0;
	for (std::size_t i = 0; i < r.size(); ++i)
	{
		double n = 0, mr = 0, mx = 0;
		for (std::size_t k = 0; k < r[i].size(); ++k)
			if (std::isfinite(r[i][k]) && std::isfinite(x[i][k]))
			{
				n++;
				mr += r[i][k];
				mx += x[i][k];
			}
		if (n < 3) continue;
		mr /= n;
		mx /= n;
		double cxy = 0, cxx = 0, cyy = 0;
		for (std::size_t k = 0; k < r[i].size(); ++k)
			if (std::isfinite(r[i][k]) && std::isfinite(x[i][k]))
			{
				cxy += (x[i][k] - mx) * (r[i][k] - mr);
				cxx += (x[i][k] - mx) * (x[i][k] - mx);
				cyy += (r[i][k] - mr) * (r[i][k] - mr);
			}
		sst += cyy;
		sse += cxx > 0 ? cyy - cxy * cxy / cxx : cyy;
		sxy += cxy;
		sxx += cxx;
	}
	Explained e;
	if (sst > 0) e.share = 1.0 - sse / sst;
	if (sxx > 0) e.slope = sxy / sxx;
	return e;
}
}  // namespace

ThermalFit assessThermalFit(const FogSeries& run, const std::vector<std::vector<double>>& r, const ThermalFitOptions& opt)
{
	ThermalFit f;
	f.threshold_C = opt.misfit_rms_C;
	double ss = 0, n = 0;
	for (std::size_t i = 0; i < r.size() && i < run.thermistorCount(); ++i)
	{
		double si = 0, ni = 0;
		for (std::size_t k = 0; k < r[i].size(); ++k)
			if (std::isfinite(r[i][k]))
			{
				si += r[i][k] * r[i][k];
				ni++;
				if (std::abs(r[i][k]) > f.max_abs_C)
				{
					f.max_abs_C = std::abs(r[i][k]);
					f.max_abs_time_s = run.time_s[k];
					f.max_abs_thermistor = run.thermistors[i].name;
				}
			}
		ss += si;
		n += ni;
		const double rms = ni > 0 ? std::sqrt(si / ni) : NAN;
		f.names.push_back(run.thermistors[i].name);
		f.rms_per_C.push_back(rms);
		if (rms > f.worst_rms_C)
		{
			f.worst_rms_C = rms;
			f.worst_thermistor = run.thermistors[i].name;
		}
	}
	f.rms_C = n > 0 ? std::sqrt(ss / n) : 0.0;
	f.misfit = f.rms_C > opt.misfit_rms_C;

	// Shapes: -dT/dt of each measured thermistor [C/s]; the lagged power.
	const std::size_t N = run.size();
	std::vector<std::vector<double>> dTdt(r.size(), std::vector<double>(N, NAN));
	for (std::size_t i = 0; i < r.size() && i < run.thermistorCount(); ++i)
		for (std::size_t k = 1; k + 1 < N; ++k)
		{
			const double a = run.temp_C[i][k - 1], b = run.temp_C[i][k + 1], dt = run.time_s[k + 1] - run.time_s[k - 1];
			if (std::isfinite(a) && std::isfinite(b) && dt > 0) dTdt[i][k] = (b - a) / dt;
		}
	const Explained lag = explain(r, dTdt);
	f.lag_share = lag.share;
	f.lag_tau_s = -lag.slope;
	if (run.power.size() == N)
	{
		for (double tau : {120.0, 300.0, 600.0, 1200.0, 2400.0, 4800.0})
		{
			std::vector<double> p(N, NAN);
			double state = run.power.empty() ? 1.0 : (run.power[0] >= 0.5 ? 1.0 : 0.0);
			for (std::size_t k = 0; k < N; ++k)
			{
				const double on = run.power[k] >= 0.5 ? 1.0 : 0.0;
				if (k > 0) state += (on - state) * (1.0 - std::exp(-(run.time_s[k] - run.time_s[k - 1]) / tau));
				p[k] = state;
			}
			const Explained e = explain(r, std::vector<std::vector<double>>(r.size(), p));
			if (e.share > f.power_share)
			{
				f.power_share = e.share;
				f.power_tau_s = tau;
			}
		}
	}
	std::string s = "Thermal fit: thermistor residual RMS " + formatValue("%.3g", f.rms_C) + " C (";
	for (std::size_t i = 0; i < f.names.size(); ++i) s += (i ? ", " : "") + f.names[i] + " " + formatValue("%.3g", f.rms_per_C[i]);
	s += "), largest " + formatValue("%.3g", f.max_abs_C) + " C at " + f.max_abs_thermistor + ", t = " + formatValue("%.0f", f.max_abs_time_s) + " s";
	if (!f.misfit)
	{
		s += "; below the " + formatValue("%.2g", f.threshold_C) + " C misfit threshold: the optical part is judged on it.";
		f.sentence = s;
		return f;
	}
	const bool lagWins = f.lag_share >= opt.min_explained_share && f.lag_share >= f.power_share && f.lag_tau_s > 0;
	const bool powerWins = !lagWins && f.power_share >= opt.min_explained_share;
	f.fix = lagWins ? ThermalFix::Lag : powerWins ? ThermalFix::HeatSource : ThermalFix::MissingNode;
	s += ". THE THERMAL MODEL IS THE FIRST DISAGREEMENT (above the " + formatValue("%.2g", f.threshold_C) +
		 " C threshold): no bias effect is named on top of it. ";
	switch (f.fix)
	{
		case ThermalFix::Lag:
			s += "What would fix it: a lag: the residual follows -tau dT/dt with tau = " + formatValue("%.3g", f.lag_tau_s) +
				 " s (explains " + formatValue("%.0f", 100 * f.lag_share) + " % of it): a thermistor lag or a node slower than modelled.";
			break;
		case ThermalFix::HeatSource:
			s += "What would fix it: a heat source: the residual follows the gyro power through a " +
				 formatValue("%.0f", f.power_tau_s) + " s lag (explains " + formatValue("%.0f", 100 * f.power_share) + " % of it).";
			break;
		default:
			s += "What would fix it: a missing node or path (or wrong thermistor placements): neither a lag (" +
				 formatValue("%.0f", 100 * f.lag_share) + " %) nor a heat source following the power (" +
				 formatValue("%.0f", 100 * f.power_share) + " %) explains the residual.";
	}
	f.sentence = s;
	return f;
}

}  // namespace mrpt_fog::discrepancy
