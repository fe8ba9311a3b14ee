/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/EnumNames.h>
#include <mrpt_fog/common/IntervalMask.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/BiasFit.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/model/ModelPreset.h>
#include <mrpt_fog/model/FitFigureStats.h>
#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/model/CalibrationFitStages.h>

#include <algorithm>
#include <functional>
#include <map>
#include <random>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
double BiasModel::evaluate(const double* values, bool clamp, int* clamped) const
{
	std::vector<double> f(features.termCount());
	const int c = features.features(values, f.data(), clamp);
	if (clamped) *clamped = c;
	double sum = 0;
	for (std::size_t i = 0; i < f.size(); i++) sum += coef_dph[i] * f[i];
	return sum;
}

double BiasModel::evaluate(const double* values, ExtrapolationPolicy policy, int* outside) const
{
	const std::size_t ns = features.signals().size();
	std::vector<double> f(features.termCount());
	const int c = features.features(values, f.data(), policy != ExtrapolationPolicy::Polynomial);
	if (outside)
	{
		int n = 0;
		for (std::size_t s = 0; s < ns; s++)
		{
			const auto& nm = features.normalisation()[s];
			n += values[s] < nm.min || values[s] > nm.max;
		}
		*outside = n;
	}
	double sum = 0;
	for (std::size_t i = 0; i < f.size(); i++) sum += coef_dph[i] * f[i];
	if (policy == ExtrapolationPolicy::Linear && c > 0)
		for (std::size_t s = 0; s < ns; s++)
		{
			const auto& nm = features.normalisation()[s];
			if (values[s] < nm.min) sum += edgeSlope(s, false) * (values[s] - nm.min);
			else if (values[s] > nm.max) sum += edgeSlope(s, true) * (values[s] - nm.max);
		}
	return sum;
}

double BiasModel::edgeSlope(std::size_t s, bool upper) const
{
	const auto& nm = features.normalisation().at(s);
	const double z = ((upper ? nm.max : nm.min) - nm.centre) / nm.scale;
	double slope = 0;
	for (std::size_t i = 0; i < features.termCount(); i++)
	{
		if (features.termSignal(i) != static_cast<int>(s)) continue;
		const int k = features.terms()[i].power;
		slope += coef_dph[i] * k * std::pow(z, k - 1);
	}
	return slope / nm.scale;
}

constexpr EnumName<ExtrapolationPolicy> kExtrapolationPolicies[] = {{ExtrapolationPolicy::Clamp, "clamp"},
																	   {ExtrapolationPolicy::Linear, "linear"},
																	   {ExtrapolationPolicy::Polynomial, "polynomial"}};

const char* toString(ExtrapolationPolicy p) { return nameIn(kExtrapolationPolicies, p, "polynomial"); }

ExtrapolationPolicy extrapolationPolicyFromString(const std::string& text)
{
	if (const auto p = valueIn(kExtrapolationPolicies, text)) return *p;
	throw std::invalid_argument("extrapolation policy '" + text + "': use clamp, linear or polynomial");
}

constexpr EnumName<TermSelection> kTermSelections[] = {{TermSelection::Auto, "auto"}, {TermSelection::None, "none"}};

const char* toString(TermSelection s) { return nameIn(kTermSelections, s, "auto"); }

TermSelection termSelectionFromString(const std::string& text)
{
	if (const auto s = valueIn(kTermSelections, text)) return *s;
	throw std::invalid_argument("selection must be 'auto' or 'none', got '" + text + "'");
}

const BiasModel* Calibration::fallbackFor(const std::string& thermistor) const
{
	for (const auto& f : fallbacks)
		if (f.dropped == thermistor) return &f;
	return nullptr;
}

using namespace calibration_fit;

Calibration fitCalibration(const std::vector<FogSeries>& series, const std::string& preset_text, const FitOptions& opt,
						   const std::vector<std::string>& labels)
{
	std::vector<FogRun> runs;
	for (const auto& s : series) runs.emplace_back(s);
	return fitCalibrationRuns(runs, preset_text, opt, labels);
}

Calibration fitCalibrationRuns(const std::vector<FogRun>& runs, const std::string& preset_text, const FitOptions& opt_in,
						   const std::vector<std::string>& labels)
{
	FitOptions opt = opt_in;  // the rate window may follow the thermistors' quantum (below)
	checkFitInputs(runs, opt, labels);
	const FogSeries& first = runs[0].header();
	const GyroAxis axis = opt.axis ? *opt.axis : first.primaryAxis();
	if (!first.has_axis[static_cast<int>(axis)])
		throw std::invalid_argument(runName(labels, 0) + " has no " + axisLetter(axis) + " axis to calibrate");
	const ModelPreset preset = parseModelPreset(preset_text, first.thermistors);
	// Common orders are defined for the thermistor presets (multipoint, points:K); M1..M4 and
	// term lists (differences among their own signals) keep the per-signal search.
	if (!(preset.kind == PresetKind::Multipoint || preset.kind == PresetKind::Points))
		opt.order_search = OrderSearch::PerSignal;
	const bool candidates_added =
		opt.selection == TermSelection::Auto && opt.physics_candidates && (preset.kind == PresetKind::Multipoint || preset.kind == PresetKind::Points);
	for (const double tau : opt.lag_taus_s)
		if (!(std::isfinite(tau) && tau > 0 && tau <= 1e7))
			throw std::invalid_argument("fit: lag time constant " + std::to_string(tau) + " s must be in (0, 1e7]");
	// lag candidates, like the physics candidates, only for selection auto: none is every preset term
	ThermalFeatureSet fs = calibrationFeatures(preset, first, candidates_added,
											   opt.selection == TermSelection::Auto ? opt.lag_taus_s : std::vector<double>{},
											   opt.lag_max_thermistors);

	// Rate window for the thermistors' reading quantum (FitOptions::window_for_quantum).
	const double quantum_C = readingQuantum_C(runs, fs);
	if (opt.window_for_quantum) opt.rate_estimator.window_s = windowForQuantum_s(opt.rate_estimator.window_s, quantum_C);

	std::size_t usable = 0;
	std::vector<PreparedRun> prep = prepareRuns(runs, fs, opt, axis, usable);
	if (usable == 0) throw std::invalid_argument("fit: no usable sample (every sample has a dropout or no rate yet)");
	const bool rates_unavailable = leaveOutRatesOfBurstLogs(runs, opt, axis, fs, prep, usable);

	// Pass 1: signal ranges -> normalisation; mean bias as y reference.
	SignalRanges ranges = signalRanges(prep, fs, usable);
	const double y_ref = ranges.y_ref;
	if (candidates_added) leaveOutConstantDifferences(fs, ranges);
	setNormalisation(fs, ranges, opt);
	// Feature means (the accumulation reference: the sums then hold centred features).
	const std::vector<double> x_ref = featureMeans(prep, fs, usable);

	// Pass 2: the folds (FoldPlan) and what they accumulate.
	const FoldPlan plan = planFolds(runs, prep, opt);
	FoldAccumulation acc = accumulateFolds(prep, fs, plan, opt, y_ref, x_ref);
	StreamingQr& total = acc.total;

	// The terms, the fallbacks and how stable the choice is.
	const TermSearch terms(fs, preset, opt);
	const TermSearch::Result chosen = terms.select(acc.sel, acc.folds);
	const Choice& best = chosen.best;
	const std::vector<Choice>& fallback_choices = chosen.fallback_choices;
	const SelectionStability stability = selectionStability(terms, acc, best, fs, plan, opt, y_ref, x_ref);

	Calibration cal;
	cal.selection_stability = stability;
	cal.rates_unavailable = rates_unavailable;
	cal.rate_gaps = rateGapCount(runs, opt.rate_estimator.window_s);
	cal.sensor_label = first.sensor_label;
	cal.axis = axis;
	cal.layout = first.thermistors;
	{
		std::vector<FogSeries> headers;
		for (const auto& r : runs) headers.push_back(r.header());
		cal.latitude_deg = commonLatitude_deg(headers);
	}
	cal.preset = preset_text;
	cal.selection = opt.selection;
	cal.rate_estimator = opt.rate_estimator;
	cal.reading_quantum_C = quantum_C;
	cal.extrapolation = opt.extrapolation;
	cal.mean_bias_dph = y_ref;
	for (std::size_t i = 0; i < runs.size(); i++) cal.runs.push_back(runName(labels, i));
	cal.model = makeModel(total, fs, best, "", opt);
	if (opt.fallbacks)
	{
		const auto& used = cal.model.features.thermistors();
		for (std::size_t i = 0; i < used.size() && i < fallback_choices.size(); i++)
			cal.fallbacks.push_back(makeModel(total, fs, fallback_choices[i], used[i], opt));
	}

	addStartupModel(cal, acc, fs, best, opt);

	// In-sample figures, then held-out ones.
	addInSampleFigures(cal, prep, fs, opt);
	addHeldOutFigures(cal, prep, fs, acc, plan, best, runs.size(), opt);
	return cal;
}

}  // namespace mrpt_fog
