/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The fit's runs prepared: usable samples, feature set, ranges, normalisation, feature means. */
#include <mrpt_fog/model/CalibrationFitStages.h>
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/FitFigureStats.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <map>
#include <random>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::calibration_fit
{
PreparedRun prepare(const FogRun& s, const ThermalFeatureSet& fs, const RateEstimatorSettings& est, GyroAxis axis,
					TableSamples table, double exclusion_s)
{
	PreparedRun r;
	r.run = &s;
	const std::size_t n = s.size(), nt = fs.thermistors().size();
	for (const auto& name : fs.thermistors()) r.col.push_back(s.header().thermistorIndex(name));
	r.axis = static_cast<int>(axis);
	// A table sample is not a bias sample (nor in the raw figures) when excluded.
	r.exclude_table = table == TableSamples::Exclude;
	r.est = est;
	r.lags = fs.lags();
	r.hyst = fs.hystereses();
	if (est.kind != RateEstimatorKind::Causal)
	{
		// The centred estimator needs whole columns (studies only: memory grows with the run).
		FogSeries loaded;
		const FogSeries* whole = s.inMemory();
		if (!whole)
		{
			loaded = s.load();
			whole = &loaded;
		}
		auto e = makeRateEstimator(est);
		r.rate.resize(nt);
		for (std::size_t i = 0; i < nt; i++) r.rate[i] = e->estimate(whole->time_s, whole->temp_C[r.col[i]]);
	}
	// The same multi-channel tracker as the compensator (RowCursor): identical numbers.
	RowCursor cur(r);
	std::vector<double> temp(nt), rate(nt);
	r.ok.assign(n, true);
	// turn-ons: the samples of the first turn_on_exclusion_s after each stay out (FitOptions)
	double excluded_until_s = -std::numeric_limits<double>::infinity();
	double previous_power = 1.0;
	bool first_sample = true;
	forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
		cur.row(c, k0, k0 + j, temp.data(), rate.data());
		if (exclusion_s > 0)
		{
			if (first_sample)
			{
				const std::string meta = s.header().metadataValue("power_on_time_s");
				const double t_on = meta.empty() ? std::numeric_limits<double>::quiet_NaN() : std::strtod(meta.c_str(), nullptr);
				if (std::isfinite(t_on) && t_on <= c.time_s[j]) excluded_until_s = t_on + exclusion_s;
				first_sample = false;
			}
			const double power = c.power.empty() ? 1.0 : c.power[j];
			if (power != 0.0 && previous_power == 0.0) excluded_until_s = c.time_s[j] + exclusion_s;
			previous_power = power;
		}
		bool ok = std::isfinite(r.y(c, j)) && (c.power.empty() || c.power[j] != 0.0) && !(c.time_s[j] < excluded_until_s);
		for (std::size_t i = 0; i < nt && ok; i++) ok = std::isfinite(temp[i]) && std::isfinite(rate[i]);
		r.ok.set(k0 + j, ok);
		r.usable += ok;
		r.short_rate_span += ok && cur.shortSpan();
	});
	return r;
}

void rowSignals(RowCursor& cur, const ThermalFeatureSet& fs, const FogSeries& c, std::size_t k0, std::size_t j,
				std::vector<double>& temp, std::vector<double>& rate, std::vector<double>& values)
{
	cur.row(c, k0, k0 + j, temp.data(), rate.data());
	// the feature set's lags are those the run was prepared with (only differences leave it after)
	if (fs.lags().size() != cur.lagCount()) throw std::logic_error("fit: feature set and prepared run disagree on the lags");
	if (fs.hystereses().size() != cur.hysteresisCount())
		throw std::logic_error("fit: feature set and prepared run disagree on the hysteresis operators");
	fs.signalValues(temp.data(), rate.data(), cur.lagRates(), cur.hysteresis(), values.data());
}

std::string runName(const std::vector<std::string>& labels, std::size_t i)
{
	return i < labels.size() ? labels[i] : "run " + std::to_string(i + 1);
}

/** The fit's options and runs are valid (throws std::invalid_argument naming the run). */
void checkFitInputs(const std::vector<FogRun>& runs, const FitOptions& opt, const std::vector<std::string>& labels)
{
	if (runs.empty()) throw std::invalid_argument("fit: no calibration runs given");
	opt.rate_estimator.validate();
	if (!(opt.ridge >= 0)) throw std::invalid_argument("fit: ridge must be >= 0");
	if (runs.size() == 1 && opt.folds < 2) throw std::invalid_argument("fit: folds must be >= 2");
	if (opt.blocks_per_fold < 1) throw std::invalid_argument("fit: blocks_per_fold must be >= 1");
	if (!(opt.min_relative_gain >= 0 && opt.min_relative_gain < 1))
		throw std::invalid_argument("fit: min_relative_gain must be in [0, 1)");
	if (!(opt.tau_s > 0)) throw std::invalid_argument("fit: tau_s must be > 0");
	if (!(opt.turn_on_exclusion_s >= 0) || !std::isfinite(opt.turn_on_exclusion_s))
		throw std::invalid_argument("fit: turn_on_exclusion_s must be finite and >= 0 [s]");
	for (std::size_t i = 0; i < runs.size(); i++)
	{
		try
		{
			runs[i].validate();
		}
		catch (const std::exception& e)
		{
			throw std::invalid_argument(runName(labels, i) + ": " + e.what());
		}
		if (runs[i].empty()) throw std::invalid_argument(runName(labels, i) + ": no samples");
		if (i > 0 && !runs[i].header().sameLayout(runs[0].header()))
			throw std::invalid_argument(runName(labels, i) + " has another sensor layout (thermistors or axes) than " +
										runName(labels, 0));
	}
}

/** The preset's feature set, with the physics candidates when `candidates_added`: for every
 * inner thermistor of the preset, the difference to the outer one at the same angle (and its
 * rate when the preset reads rates). */
ThermalFeatureSet calibrationFeatures(const ModelPreset& preset, const FogSeries& first, bool candidates_added,
									   const std::vector<double>& lag_taus_s, std::size_t lag_max_thermistors)
{
	ThermalFeatureSet fs = presetFeatures(preset);
	const bool lags = !lag_taus_s.empty() && (preset.kind == PresetKind::Multipoint || preset.kind == PresetKind::Points) &&
					  fs.thermistors().size() <= lag_max_thermistors;
	if (!candidates_added && !lags) return fs;
	std::vector<ThermalTerm> terms(fs.terms().begin() + 1, fs.terms().end());
	if (lags)  // the lag-rate candidates of every thermistor of the preset (FitOptions::lag_taus_s)
		for (const auto& name : fs.thermistors())
			for (const double tau : lag_taus_s) terms.push_back(ThermalTerm::lagRate(name, tau, 1));
	if (!candidates_added) return ThermalFeatureSet(terms);
	for (const auto& in : first.thermistors)
	{
		if (in.side != CoilSide::Inner ||
			std::find(preset.thermistors.begin(), preset.thermistors.end(), in.name) == preset.thermistors.end())
			continue;
		for (const auto& out : first.thermistors)
			if (out.side == CoilSide::Outer && out.angle_deg == in.angle_deg &&
				std::find(preset.thermistors.begin(), preset.thermistors.end(), out.name) != preset.thermistors.end())
			{
				terms.push_back(ThermalTerm::of(SignalKind::Diff, in.name, out.name, 1));
				if (preset.rate_order > 0) terms.push_back(ThermalTerm::of(SignalKind::DiffRate, in.name, out.name, 1));
			}
	}
	return ThermalFeatureSet(terms);
}

/** The coarsest reading quantum of the feature set's thermistors over the runs [degC] (0 when
 * none is found): one sequential pass per run. */
double readingQuantum_C(const std::vector<FogRun>& runs, const ThermalFeatureSet& fs)
{
	double quantum_C = 0;
	const auto& names = fs.thermistors();
	std::vector<double> q(names.size(), std::numeric_limits<double>::infinity());
	for (const auto& r : runs)  // one sequential pass per run
	{
		std::vector<ReadingQuantum> acc(names.size());
		std::vector<std::size_t> col;
		for (const auto& name : names) col.push_back(static_cast<std::size_t>(r.header().thermistorIndex(name)));
		r.forEachChunk([&](const FogSeries& chunk, std::size_t) {
			for (std::size_t i = 0; i < names.size(); i++)
				for (const double v : chunk.temp_C[col[i]]) acc[i].add(v);
		});
		for (std::size_t i = 0; i < names.size(); i++) q[i] = std::min(q[i], acc[i].quantum_C());
	}
	for (const double qi : q)
		if (std::isfinite(qi)) quantum_C = std::max(quantum_C, qi);
	return quantum_C;
}

/** Every run prepared for the fit; `usable` = their usable samples. */
std::vector<PreparedRun> prepareRuns(const std::vector<FogRun>& runs, const ThermalFeatureSet& fs, const FitOptions& opt,
									 GyroAxis axis, std::size_t& usable)
{
	std::vector<PreparedRun> prep;
	usable = 0;
	for (const auto& r : runs)
	{
		prep.push_back(prepare(r, fs, opt.rate_estimator, axis, opt.table_samples, opt.turn_on_exclusion_s));
		usable += prep.back().usable;
	}
	return prep;
}

/** Burst logs (e.g. 5 s bursts every 5 min): within a burst the rate window never covers half
 * its length, so the compensator could never use a model that reads rates (it would run the
 * rate-free start-up model on every sample). When that holds for most usable samples, the
 * rates are not estimable from this log: the rate signals leave the feature set and the runs
 * are prepared again. Returns whether they did. */
bool leaveOutRatesOfBurstLogs(const std::vector<FogRun>& runs, const FitOptions& opt, GyroAxis axis,
							  ThermalFeatureSet& fs, std::vector<PreparedRun>& prep, std::size_t& usable)
{
	std::size_t short_span = 0;
	for (const auto& r : prep) short_span += r.short_rate_span;
	if (!(2 * short_span > usable)) return false;
	std::vector<bool> keep(fs.signals().size());
	bool any_rate = false;
	for (std::size_t s = 0; s < keep.size(); s++)
	{
		keep[s] = !fs.signals()[s].isRate();
		any_rate |= !keep[s];
	}
	if (!any_rate) return false;
	fs = fs.selectSignals(keep);
	prep = prepareRuns(runs, fs, opt, axis, usable);  // the thermistors may have changed (one read only through its rate)
	return true;
}

SignalRanges signalRanges(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, std::size_t usable)
{
	const std::size_t ns = fs.signals().size(), nt = fs.thermistors().size();
	SignalRanges g;
	g.lo.assign(ns, std::numeric_limits<double>::infinity());
	g.hi.assign(ns, -std::numeric_limits<double>::infinity());
	std::vector<double> temp(nt), rate(nt), values(ns);
	double ysum = 0;
	for (const auto& r : prep)
	{
		RowCursor cur(r);
		forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
			if (!r.ok[k0 + j]) return;
			rowSignals(cur, fs, c, k0, j, temp, rate, values);
			for (std::size_t s = 0; s < ns; s++)
			{
				g.lo[s] = std::min(g.lo[s], values[s]);
				g.hi[s] = std::max(g.hi[s], values[s]);
			}
			ysum += r.y(c, j);
		});
	}
	g.y_ref = ysum / static_cast<double>(usable);
	return g;
}

/** A physics candidate without variation (e.g. two identical readings) leaves the feature set. */
void leaveOutConstantDifferences(ThermalFeatureSet& fs, SignalRanges& g)
{
	const std::size_t ns = fs.signals().size();
	std::vector<bool> keep(ns, true);
	bool any = false;
	for (std::size_t s = 0; s < ns; s++)
		if (fs.signals()[s].isDifference() && !(g.hi[s] - g.lo[s] > 1e-9 * (1 + std::abs(g.hi[s]))))
		{
			keep[s] = false;
			any = true;
		}
	if (!any) return;
	fs = fs.selectSignals(keep);
	std::vector<double> lo2, hi2;
	for (std::size_t s = 0; s < ns; s++)
		if (keep[s])
		{
			lo2.push_back(g.lo[s]);
			hi2.push_back(g.hi[s]);
		}
	g.lo = lo2;
	g.hi = hi2;
}

/** Each signal's normalisation from its range: a temperature to [-1, 1] about its centre, a rate
 * or difference scaled by its largest magnitude. Throws when a temperature spans too little for
 * its polynomial order or a signal is constant. */
void setNormalisation(ThermalFeatureSet& fs, const SignalRanges& g, const FitOptions& opt)
{
	const std::size_t ns = fs.signals().size();
	const auto& lo = g.lo;
	const auto& hi = g.hi;
	for (std::size_t s = 0; s < ns; s++)
	{
		const auto& sig = fs.signals()[s];
		int order = 0;
		for (std::size_t i = 0; i < fs.termCount(); i++)
			if (fs.termSignal(i) == static_cast<int>(s)) order = std::max(order, fs.terms()[i].power);
		const double span = hi[s] - lo[s];
		std::ostringstream why;
		if (sig.kind == SignalKind::Temp && span < order * opt.min_temp_span_per_order_C)
		{
			why << sig.name() << " spans only " << span << " degC in the calibration data; an order-" << order
				<< " polynomial needs at least " << order * opt.min_temp_span_per_order_C << " degC ("
				<< opt.min_temp_span_per_order_C << " degC per order): calibrate over a wider range or lower the order";
			throw std::invalid_argument(why.str());
		}
		if (!(span > 0))
			throw std::invalid_argument(sig.name() + " is constant in the calibration data: it cannot be fitted");
		auto& nm = fs.normalisation()[s];
		nm.min = lo[s];
		nm.max = hi[s];
		if (sig.kind == SignalKind::Temp)
		{
			nm.centre = 0.5 * (lo[s] + hi[s]);
			nm.scale = 0.5 * span;
		}
		else if (sig.isHysteresis())  // bounded by construction: its own range, never clamped
		{
			nm.centre = 0.0;
			nm.scale = 1.0;
			nm.min = -1.0;
			nm.max = 1.0;
		}
		else
		{
			nm.centre = 0.0;
			nm.scale = std::max(std::abs(lo[s]), std::abs(hi[s]));
		}
	}
}

/** The mean of each feature over the usable samples (the accumulation reference of the QR
 * factors: their sums then hold centred features). */
std::vector<double> featureMeans(const std::vector<PreparedRun>& prep, const ThermalFeatureSet& fs, std::size_t usable)
{
	const std::size_t nt = fs.thermistors().size();
	std::vector<double> temp(nt), rate(nt), values(fs.signals().size()), f(fs.termCount());
	std::vector<double> fsum(fs.termCount(), 0.0);
	for (const auto& r : prep)
	{
		RowCursor cur(r);
		forEachSample(r, &cur, [&](const FogSeries& c, std::size_t k0, std::size_t j) {
			if (!r.ok[k0 + j]) return;
			rowSignals(cur, fs, c, k0, j, temp, rate, values);
			fs.features(values.data(), f.data(), false);
			for (std::size_t q = 0; q < f.size(); q++) fsum[q] += f[q];
		});
	}
	std::vector<double> x_ref(fs.termCount());
	for (std::size_t j = 0; j < x_ref.size(); j++) x_ref[j] = fsum[j] / static_cast<double>(usable);
	return x_ref;
}

/** Gaps between consecutive samples longer than the rate window, over every run. */
std::size_t rateGapCount(const std::vector<FogRun>& runs, double window_s)
{
	std::size_t rate_gaps = 0;
	for (const auto& r : runs)
	{
		bool first_sample = true;
		double prev_t = 0;
		r.forEachChunk([&](const FogSeries& c, std::size_t) {
			for (double t : c.time_s)
			{
				if (!first_sample) rate_gaps += t - prev_t > window_s;
				first_sample = false;
				prev_t = t;
			}
		});
	}
	return rate_gaps;
}

}  // namespace mrpt_fog::calibration_fit
