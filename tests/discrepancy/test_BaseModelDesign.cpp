/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt_fog/discrepancy/BaseModelDesign.h>
#include <mrpt_fog/model/Compensator.h>
#include "support/SyntheticChamberRun.h"

#include <algorithm>
#include <cmath>

using namespace mrpt_fog;
using namespace mrpt_fog::discrepancy;

namespace
{
struct Fixture
{
	SyntheticRun run;
	RunSignals sig;
	Fixture()
	{
		run = makeSyntheticChamberRun(10);  // the default causal estimator (order 2) needs >= 2 samples in 30 s
		sig = computeRunSignals(run.series);
	}
};
}  // namespace

TEST(BaseModelDesign, StaticPresetColumns)
{
	Fixture f;
	const auto spec = resolveBaseModel("static:3", f.run.series);
	const auto d = buildBaseDesign(spec, f.run.series, f.sig);
	// constant, x, x^2, x^3 and the table-rate nuisance column (the all_conditions profile has a table)
	EXPECT_EQ(d.names, (std::vector<std::string>{"1", "T(mean)^1", "T(mean)^2", "T(mean)^3", "table_rate*1e-6"}));
	EXPECT_EQ(d.max_static_order, 3);
	EXPECT_EQ(d.is_static_temp, (std::vector<unsigned char>{0, 1, 1, 1, 0}));
	const std::size_t k = 100;
	const double x = (f.sig.temp_mean_C[k] - 20.0) / 50.0;
	EXPECT_NEAR(d.X(k, 3), x * x * x, 1e-12);
}

TEST(BaseModelDesign, ModelRoomPresetsAreTheCalibrationsSelectedTerms)
{
	// a preset is fitted by the calibration code (fog-calibrate's defaults); its selected terms
	// are the columns (+ constant + table nuisance)
	Fixture f;
	for (const char* preset : {"multipoint", "M2:Ti1", "M4:Ti1,To1"})
	{
		const auto cal = calibrationUnderTest(preset, f.run.series);
		const auto d = buildBaseDesign(resolveBaseModel(preset, f.run.series), f.run.series, f.sig);
		auto expected = cal.model.features.termNames();
		// the nuisance "centred minus causal" column of each rate term (the rate estimator's gap)
		for (const auto& t : cal.model.features.terms())
			if (!t.constant && (t.signal.kind == SignalKind::Rate || t.signal.kind == SignalKind::DiffRate))
				expected.push_back("centred-minus-causal " + t.name());
		expected.push_back("table_rate*1e-6");
		EXPECT_EQ(d.names, expected) << preset;
	}
}

TEST(BaseModelDesign, MainModelOnlyFitsTheSameMainModel)
{
	// the analysis skips the fallbacks and the stability refits: the main model must not change
	Fixture f;
	const auto full = calibrationUnderTest("M2:Ti1", f.run.series, FitScope::Full);
	const auto main = calibrationUnderTest("M2:Ti1", f.run.series, FitScope::MainModelOnly);
	EXPECT_EQ(full.model.features.termNames(), main.model.features.termNames());
	ASSERT_EQ(full.model.coef_dph.size(), main.model.coef_dph.size());
	for (std::size_t i = 0; i < full.model.coef_dph.size(); ++i)
		EXPECT_DOUBLE_EQ(full.model.coef_dph[i], main.model.coef_dph[i]);
	EXPECT_FALSE(full.fallbacks.empty());
	EXPECT_TRUE(main.fallbacks.empty());
}

TEST(BaseModelDesign, ColumnsAreWhatTheCompensatorEvaluates)
{
	// one model path: the base columns times the calibration's coefficients are the bias the
	// compensator computes (independent code: the compiled kernel), sample by sample, inside
	// and outside the calibrated range (a second run 8 C warmer: tangent continuation)
	Fixture f;
	auto warmer = makeSyntheticChamberRun(10, 2);
	for (auto& col : warmer.series.temp_C)
		for (auto& v : col) v += 8.0;
	const auto sigW = computeRunSignals(warmer.series);
	for (const auto* run : {&f.run.series, &warmer.series})
	{
		const auto& sig = run == &f.run.series ? f.sig : sigW;
		const auto cal = calibrationUnderTest("M2:Ti1", f.run.series);
		const auto d = buildBaseDesign(resolveBaseModel("M2:Ti1", f.run.series), *run, sig);
		const auto comp = compensate(cal, *run);
		std::size_t checked = 0, outside = 0;
		for (std::size_t k = 0; k < run->size(); ++k)
		{
			if (!std::isfinite(comp.bias_dph[k]) || !d.defined[k]) continue;
			if (comp.flags[k] & mrpt_fog::CompensationFlag::RateFree) continue;  // the rate-free start-up model, not the main one
			double b = 0;
			for (std::size_t t = 0; t < cal.model.coef_dph.size(); ++t)
				b += cal.model.coef_dph[t] * d.X(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(t));
			EXPECT_NEAR(b, comp.bias_dph[k], 1e-9 * (1 + std::fabs(comp.bias_dph[k]))) << k;
			++checked;
			outside += comp.flags[k] != 0;
		}
		EXPECT_GT(checked, run->size() / 2);
		if (run == &warmer.series) EXPECT_GT(outside, 100u);  // flagged outside the calibrated range
	}
}

TEST(BaseModelDesign, RowsWithoutARateEstimateAreNotDefined)
{
	// the causal estimator has no rate before two samples in its window: the first row of the
	// log is undefined and leaves the usable rows; every other row of this gap-free run is defined
	Fixture f;
	const auto d = buildBaseDesign(resolveBaseModel("M2:Ti1", f.run.series), f.run.series, f.sig);
	ASSERT_EQ(d.defined.size(), f.run.series.size());
	EXPECT_EQ(d.defined.front(), 0);
	std::size_t undefined = 0, usableUndefined = 0;
	for (std::size_t k = 0; k < d.defined.size(); ++k)
	{
		undefined += !d.defined[k];
		usableUndefined += !d.defined[k] && f.sig.usable[k];
	}
	EXPECT_LE(undefined, 2u);
	auto sig = f.sig;
	EXPECT_EQ(restrictToDefinedRows(sig, d), usableUndefined);
	for (std::size_t k = 0; k < d.defined.size(); ++k)
		if (!d.defined[k]) EXPECT_EQ(sig.usable[k], 0) << k;
}

TEST(BaseModelDesign, BadPresetsThrow)
{
	Fixture f;
	EXPECT_THROW(resolveBaseModel("static:x", f.run.series), std::invalid_argument);
	EXPECT_THROW(resolveBaseModel("static:3:Nope", f.run.series), std::invalid_argument);
	EXPECT_THROW(resolveBaseModel("M2:Nope", f.run.series), std::invalid_argument);
	EXPECT_THROW(resolveBaseModel("quadratic", f.run.series), std::invalid_argument);
	EXPECT_ANY_THROW(resolveBaseModel("/nonexistent/cal.yaml", f.run.series));
}

TEST(BaseModelDesign, WeightedScaleFactorColumnReadsTheWeightedSum)
{
	// a calibration whose scale factor reads a weighted sum of thermistors (ScaleFactorModel
	// `weighted`) is tested as the compensator runs it: the column is table rate x 1e-6
	// x z, z of sum w_i T_i (clamped to the calibrated range); it used to throw "base model uses
	// thermistor 'weighted'"
	Fixture f;
	auto spec = resolveBaseModel("M2:Ti1", f.run.series, ScaleFactorFitting::Off);
	ScaleFactorModel sf;
	sf.thermistor = "weighted";
	ASSERT_GE(f.run.series.thermistors.size(), 2u);
	const auto& a = f.run.series.thermistors[0].name;
	const auto& b = f.run.series.thermistors[1].name;
	sf.thermistors = {a, b};
	sf.weights = {1.5, -0.5};
	sf.centre_C = 20.0;
	sf.scale_C = 10.0;
	sf.min_C = -100.0;
	sf.max_C = 100.0;
	sf.coef_ppm = {0.0, 7.0};
	spec.scale_factor = sf;
	const auto d = buildBaseDesign(spec, f.run.series, f.sig);
	ASSERT_EQ(d.names.back(), "table_rate*1e-6*s(weighted)^1");
	std::size_t checked = 0;
	for (std::size_t k = 0; k < f.run.series.size(); ++k)
	{
		const double Ta = f.sig.thermistor_C[0][k], Tb = f.sig.thermistor_C[1][k];
		if (!std::isfinite(Ta) || !std::isfinite(Tb) || f.sig.table_rate_dph[k] == 0) continue;
		const double z = (1.5 * Ta - 0.5 * Tb - 20.0) / 10.0;
		EXPECT_NEAR(d.X(static_cast<Eigen::Index>(k), d.X.cols() - 1), f.sig.table_rate_dph[k] * 1e-6 * z, 1e-12);
		++checked;
	}
	EXPECT_GT(checked, 100u);
}

TEST(BaseModelDesign, NuisanceColumnIsCentredMinusCausalRateFeature)
{
	// the rate term's column plus its nuisance column is the same feature evaluated on the
	// analysis' centred slope (RunSignals::dthermistor_dt_Cpm, degC/min -> degC/s), inside the
	// calibrated range (no clamp or tangent there)
	Fixture f;
	const auto spec = resolveBaseModel("M2:Ti1", f.run.series);
	const auto d = buildBaseDesign(spec, f.run.series, f.sig);
	const auto& fs = spec.features;
	std::size_t checkedTerms = 0;
	for (std::size_t t = 1; t < fs.termCount(); ++t)
	{
		const auto& term = fs.terms()[t];
		if (term.signal.kind != SignalKind::Rate) continue;
		const auto nuis = std::find(d.names.begin(), d.names.end(), "centred-minus-causal " + term.name());
		ASSERT_NE(nuis, d.names.end()) << term.name();
		const auto c = static_cast<Eigen::Index>(nuis - d.names.begin());
		EXPECT_EQ(d.is_nuisance[static_cast<std::size_t>(c)], 1);
		const auto& nm = fs.normalisation()[static_cast<std::size_t>(fs.termSignal(t))];
		const int i = f.run.series.thermistorIndex(term.signal.a);
		ASSERT_GE(i, 0);
		std::size_t checked = 0;
		for (std::size_t k = 0; k < f.run.series.size(); ++k)
		{
			const double r = f.sig.dthermistor_dt_Cpm[static_cast<std::size_t>(i)][k] / 60.0;
			if (!d.defined[k] || !f.sig.usable[k] || r < nm.min || r > nm.max) continue;
			const double expected = std::pow((r - nm.centre) / nm.scale, term.power);
			EXPECT_NEAR(d.X(static_cast<Eigen::Index>(k), static_cast<Eigen::Index>(t)) + d.X(static_cast<Eigen::Index>(k), c),
						expected, 1e-9 * (1 + std::fabs(expected)))
				<< k;
			++checked;
		}
		EXPECT_GT(checked, f.run.series.size() / 4);
		++checkedTerms;
	}
	EXPECT_GE(checkedTerms, 1u);
}
