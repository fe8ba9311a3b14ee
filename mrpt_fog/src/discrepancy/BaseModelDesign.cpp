/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/BaseModelDesign.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/LagFilter.h>
#include <mrpt_fog/model/ModelPreset.h>
#include <mrpt_fog/model/RateEstimator.h>
#include <mrpt_fog/model/ScaleFactorFit.h>

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
	return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }
}  // namespace

Calibration calibrationUnderTest(const std::string& text, const FogSeries& run, FitScope scope, ScaleFactorFitting sf)
{
	if (endsWith(text, ".yaml") || endsWith(text, ".yml")) return loadCalibrationYaml(text);
	FitOptions fo;  // fog-calibrate's defaults
	if (scope == FitScope::MainModelOnly)
	{
		fo.fallbacks = false;  // one model per thermistor left out: not the main model
		fo.stability_resamples = 0;  // refits that measure the choice's stability, not change it
	}
	// runs with table rates: as fog-calibrate, table samples serve the scale-factor fit, not the
	// bias fit; when the table segments cannot support a scale-factor fit the bias-only
	// calibration stands (fog-calibrate --scale-factor off)
	const bool table = sf == ScaleFactorFitting::Auto && hasTableRates({run});
	if (table) fo.table_samples = TableSamples::Exclude;
	Calibration cal = fitCalibration({run}, text, fo);
	if (table)
	{
		try
		{
			cal.scale_factor = fitScaleFactor({run}, cal);
		}
		catch (const ScaleFactorFitError&)
		{
		}
	}
	return cal;
}

BaseModelSpec resolveBaseModel(const std::string& text, const FogSeries& run, ScaleFactorFitting sf)
{
	BaseModelSpec s;
	s.source = text;
	const bool yaml = endsWith(text, ".yaml") || endsWith(text, ".yml");
	if (!yaml && text.rfind("static:", 0) != 0)
	{
		parseModelPreset(text, run.thermistors);  // a bad preset is named before any fitting
		const Calibration cal = calibrationUnderTest(text, run, FitScope::MainModelOnly, sf);
		s.terms = cal.model.features.terms();
		s.features = cal.model.features;
		s.rate_estimator = cal.rate_estimator;
		s.extrapolation = cal.extrapolation;
		s.scale_factor = cal.scale_factor;
		return s;
	}
	if (yaml)
	{
		const Calibration cal = calibrationUnderTest(text, run);
		s.terms = cal.model.features.terms();
		s.features = cal.model.features;
		s.rate_estimator = cal.rate_estimator;
		s.extrapolation = cal.extrapolation;
		s.scale_factor = cal.scale_factor;
		for (const auto& t : s.terms)
			if (!t.constant)
				for (const auto* name : {&t.signal.a, &t.signal.b})
					if (!name->empty() && run.thermistorIndex(*name) < 0)
						throw std::invalid_argument(text + ": term " + t.name() + " uses thermistor '" + *name +
													"', absent from the measured run");
		return s;
	}
	if (text.rfind("static:", 0) == 0)
	{
		std::stringstream ss(text.substr(7));
		std::string order, name;
		std::getline(ss, order, ':');
		std::getline(ss, name);
		try
		{
			std::size_t used = 0;
			s.static_order = std::stoi(order, &used);
			if (used != order.size() || s.static_order < 1 || s.static_order > 7) throw std::invalid_argument("");
		}
		catch (const std::exception&)
		{
			throw std::invalid_argument("model preset '" + text + "': static:P[:NAME] needs an order P in 1..7");
		}
		if (!name.empty())
		{
			if (run.thermistorIndex(name) < 0)
				throw std::invalid_argument("model preset '" + text + "': thermistor '" + name + "' is not in the run");
			s.static_name = name;
		}
		s.terms = {ThermalTerm::constantTerm()};
		return s;
	}
	throw std::logic_error("resolveBaseModel: unreachable");
}

namespace
{
/** The calibration's feature columns (constant excluded) as the compensator evaluates them:
 * its rate estimator over every sample of the log (power-off rows included: the thermistors
 * keep logging), its normalisation, outside the calibrated range its extrapolation policy
 * (Linear: each term z^k continued along its tangent at the edge, so that the bias, a linear
 * combination of the columns, is continued along its tangent as BiasModel::evaluate does). */
std::vector<std::vector<double>> compensatorColumns(const BaseModelSpec& spec, const FogSeries& run,
													std::vector<unsigned char>& defined,
													const RunSignals* centred_rates = nullptr)
{
	const auto& fs = spec.features;
	const std::size_t n = run.size(), nt = fs.thermistors().size(), ns = fs.signals().size(), nf = fs.termCount();
	std::vector<int> colOf;
	for (const auto& name : fs.thermistors())
	{
		const int i = run.thermistorIndex(name);
		if (i < 0) throw std::invalid_argument("base model uses thermistor '" + name + "', absent from the run");
		colOf.push_back(i);
	}
	std::vector<std::vector<double>> rate_C_s(nt);
	if (centred_rates)
		for (std::size_t i = 0; i < nt; ++i)
		{
			// the analysis' centred slope (RunSignals, degC/min) in place of the calibration's estimator
			rate_C_s[i] = centred_rates->dthermistor_dt_Cpm[static_cast<std::size_t>(colOf[i])];
			for (auto& v : rate_C_s[i]) v /= 60.0;
		}
	else
	{
		const auto estimator = makeRateEstimator(spec.rate_estimator);
		for (std::size_t i = 0; i < nt; ++i)
			rate_C_s[i] = estimator->estimate(run.time_s, run.temp_C[static_cast<std::size_t>(colOf[i])]);
	}
	std::vector<std::vector<double>> cols(nf, std::vector<double>(n, 0.0));
	std::vector<double> temp(nt), r(nt), values(ns), f(nf);
	LagFilterBank lags(fs.lags());  // lag-rate signals (one-thermistor calibrations), carried sample to sample
	std::vector<double> lag_rate(fs.lags().size());
	HysteresisFilterBank hyst(fs.hystereses());  // hysteresis signals (a calibration given as YAML may read them)
	std::vector<double> hyst_value(fs.hystereses().size());
	const bool clampOrTangent = spec.extrapolation != ExtrapolationPolicy::Polynomial;
	defined.assign(n, 1);
	for (std::size_t k = 0; k < n; ++k)
	{
		for (std::size_t i = 0; i < nt; ++i)
		{
			temp[i] = run.temp_C[static_cast<std::size_t>(colOf[i])][k];
			r[i] = rate_C_s[i][k];
		}
		lags.push(run.time_s[k], temp.data());
		for (std::size_t i = 0; i < lag_rate.size(); ++i) lag_rate[i] = lags.rate_C_per_s(i);
		hyst.push(temp.data());
		for (std::size_t i = 0; i < hyst_value.size(); ++i) hyst_value[i] = hyst.value(i);
		fs.signalValues(temp.data(), r.data(), lag_rate.data(), hyst_value.data(), values.data());
		fs.features(values.data(), f.data(), clampOrTangent);
		if (spec.extrapolation == ExtrapolationPolicy::Linear)
			for (std::size_t t = 1; t < nf; ++t)
			{
				const auto& nm = fs.normalisation()[static_cast<std::size_t>(fs.termSignal(t))];
				const double v = values[static_cast<std::size_t>(fs.termSignal(t))];
				const double edge = v < nm.min ? nm.min : v > nm.max ? nm.max : v;
				if (edge == v) continue;
				const int p = fs.terms()[t].power;
				const double z = (edge - nm.centre) / nm.scale;
				f[t] += p * std::pow(z, p - 1) * (v - edge) / nm.scale;
			}
		for (std::size_t t = 1; t < nf; ++t)
		{
			if (!std::isfinite(f[t])) defined[k] = 0;
			cols[t][k] = f[t];
		}
	}
	return cols;
}
}  // namespace

BaseDesign buildBaseDesign(const BaseModelSpec& spec, const FogSeries& run, const RunSignals& sig)
{
	const std::size_t n = sig.size();
	std::vector<std::vector<double>> cols;
	BaseDesign d;
	auto add = [&](std::vector<double> c, std::string name, bool isStatic)
	{
		for (auto& v : c) v = finiteOr0(v);
		cols.push_back(std::move(c));
		d.names.push_back(std::move(name));
		d.is_static_temp.push_back(isStatic ? 1 : 0);
		d.is_nuisance.push_back(0);
	};
	auto thermistor = [&](const std::string& name) -> std::size_t
	{
		const int i = run.thermistorIndex(name);
		if (i < 0) throw std::invalid_argument("base model uses thermistor '" + name + "', absent from the run");
		return static_cast<std::size_t>(i);
	};
	add(std::vector<double>(n, 1.0), "1", false);
	if (spec.static_order > 0)
	{
		const auto& T = spec.static_name == "mean" ? sig.temp_mean_C : sig.thermistor_C[thermistor(spec.static_name)];
		for (int k = 1; k <= spec.static_order; ++k)
		{
			std::vector<double> c(n);
			for (std::size_t j = 0; j < n; ++j) c[j] = std::pow(scaledTemp(T[j]), k);
			add(std::move(c), "T(" + spec.static_name + ")^" + std::to_string(k), true);
		}
		d.max_static_order = spec.static_order;
		d.static_temp_C = T;
	}
	d.defined.assign(n, 1);
	const bool calibrationColumns = spec.static_order == 0;
	if (calibrationColumns)
	{
		const auto causal = compensatorColumns(spec, run, d.defined);
		const auto& fs = spec.features;
		for (std::size_t t = 1; t < fs.termCount(); ++t)
		{
			const auto& term = fs.terms()[t];
			const bool isStatic = term.signal.kind == SignalKind::Temp;
			add(causal[t], term.name(), isStatic);
			if (isStatic)
			{
				if (d.static_temp_C.empty()) d.static_temp_C = sig.thermistor_C[thermistor(term.signal.a)];
				d.max_static_order = std::max(d.max_static_order, term.power);
			}
		}
		// Nuisance: for each rate term, the same feature on the analysis' centred rate minus the
		// feature on the calibration's causal rate. The compensator's rate estimate has noise
		// and shape errors (order 2 from 12 samples per window at 5 s sampling), so a rate term
		// fitted on it leaves part of the true rate response in the residual (errors in the
		// regressor), and the candidates' centred rate columns (shupe_rate, gradient_rate,
		// radial_gradient during ramps) would take it: a gap of the rate ESTIMATOR, named as a
		// missing physical effect. With this column the base spans "the same rate term, better
		// estimated"; a candidate must explain something beyond it.
		std::vector<unsigned char> unused;
		auto centred = compensatorColumns(spec, run, unused, &sig);
		for (std::size_t t = 1; t < fs.termCount(); ++t)
		{
			const auto& term = fs.terms()[t];
			if (term.signal.kind != SignalKind::Rate && term.signal.kind != SignalKind::DiffRate) continue;
			std::vector<double> c(n);
			for (std::size_t j = 0; j < n; ++j) c[j] = finiteOr0(centred[t][j]) - finiteOr0(causal[t][j]);
			add(std::move(c), "centred-minus-causal " + term.name(), false);
			d.is_nuisance.back() = 1;
		}
	}
	if (d.static_temp_C.empty()) d.static_temp_C = sig.temp_mean_C;
	if (sig.has_table)
	{
		std::vector<double> c(sig.table_rate_dph);
		for (auto& v : c) v *= 1e-6;
		add(std::move(c), "table_rate*1e-6", false);
		// the calibration's scale factor versus temperature, as the compensator applies it
		// (to first order: bias + 1e-6 s_ppm(T) x rate): one column per power z^k, k >= 1
		if (spec.scale_factor && spec.scale_factor->order() >= 1)
		{
			const auto& sf = *spec.scale_factor;
			// the temperature it reads: one thermistor, or the mean / weighted sum of several
			std::vector<double> sfTemp(n, 0.0);
			if (sf.thermistors.empty())
				sfTemp = sig.thermistor_C[thermistor(sf.thermistor)];
			else
				for (std::size_t i = 0; i < sf.thermistors.size(); ++i)
				{
					const std::size_t ti = thermistor(sf.thermistors[i]);
					const double w = sf.weights.empty() ? 1.0 / double(sf.thermistors.size()) : sf.weights[i];
					for (std::size_t j = 0; j < n; ++j) sfTemp[j] += w * sig.thermistor_C[ti][j];
				}
			for (std::size_t p = 1; p <= sf.order(); ++p)
			{
				std::vector<double> col(n);
				for (std::size_t j = 0; j < n; ++j)
				{
					const double T = std::min(std::max(sfTemp[j], sf.min_C), sf.max_C);
					col[j] = sig.table_rate_dph[j] * 1e-6 * std::pow((T - sf.centre_C) / sf.scale_C, static_cast<double>(p));
				}
				add(std::move(col), "table_rate*1e-6*s(" + sf.thermistor + ")^" + std::to_string(p), false);
			}
		}
	}
	d.X.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cols.size()));
	for (std::size_t c = 0; c < cols.size(); ++c)
		for (std::size_t j = 0; j < n; ++j)
			d.X(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(c)) = cols[c][j];
	return d;
}

std::size_t restrictToDefinedRows(RunSignals& sig, const BaseDesign& base)
{
	std::size_t removed = 0;
	for (std::size_t k = 0; k < sig.size() && k < base.defined.size(); ++k)
		if (!base.defined[k] && sig.usable[k])
		{
			sig.usable[k] = 0;
			sig.block[k] = -1;
			++removed;
		}
	return removed;
}

}  // namespace mrpt_fog::discrepancy
