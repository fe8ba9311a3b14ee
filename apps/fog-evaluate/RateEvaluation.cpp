/* fog-evaluate: bias figures of one rate record (raw or compensated). */
#include "RateEvaluation.h"

#include <cmath>

namespace mrpt_fog::evaluate
{
std::vector<double> biasOf(const FogSeries& series, std::vector<double> rate_dph)
{
	std::vector<double> bias(std::move(rate_dph));
	for (std::size_t k = 0; k < bias.size(); k++)
	{
		if (!series.table_rate_dph.empty()) bias[k] -= series.table_rate_dph[k];
		if (!series.power.empty() && series.power[k] == 0.0) bias[k] = NAN;
	}
	return bias;
}

RateEvaluation evaluateRate(const std::vector<double>& time_s, const std::vector<double>& bias_dph, double tau_s)
{
	RateEvaluation e;
	e.stats = biasStats(time_s, bias_dph, tau_s);
	const UniformRecord u = resampleUniform(time_s, bias_dph);
	e.allan_period_s = u.period_s;
	e.allan_samples = u.value.size();
	e.allan_segments = u.segments;
	if (u.value.size() >= 4)
	{
		// At least 4 clusters per point: with fewer the estimate is too noisy to be worth showing.
		e.allan = allanDeviation(u.value, u.period_s, octaveClusterSizes(u.value.size(), 4), AllanKind::Overlapping);
		e.terms = allanNoiseTerms(e.allan);
	}
	return e;
}

RateEvaluation evaluateRate(const RowSpill& rows, std::size_t col, double tau_s)
{
	RateEvaluation e;
	e.stats = biasStats(
		[&](const RecordVisitor& f) {
			rows.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
				for (std::size_t j = 0; j < n; j++) f(r[j * rows.width()], r[j * rows.width() + col]);
			});
		},
		tau_s);
	RowSpill uniform(1);
	const UniformRecord u = resampleUniform(rows, 0, col, uniform);
	e.allan_period_s = u.period_s;
	e.allan_samples = uniform.rows();
	e.allan_segments = u.segments;
	if (uniform.rows() >= 4)
	{
		// At least 4 clusters per point: with fewer the estimate is too noisy to be worth showing.
		e.allan = allanDeviationOverlapping(uniform, u.period_s, octaveClusterSizes(uniform.rows(), 4));
		e.terms = allanNoiseTerms(e.allan);
	}
	return e;
}

JsonValue toJson(const RateEvaluation& e)
{
	const BiasStats& st = e.stats;
	const AllanNoiseTerms& nt = e.terms;
	JsonValue j = JsonValue::object(
		{{"stability_dph", st.stability_dph}, {"range_dph", st.range_dph},
		 {"raw_peak_to_peak_dph", st.raw_peak_to_peak_dph}, {"mean_dph", st.mean_dph},
		 {"window_count", st.window_count}, {"empty_window_count", st.empty_window_count},
		 {"samples_used", st.samples_used}, {"dropped_tail_s", st.dropped_tail_s}, {"arw_dpsh", nt.arw_dpsh},
		 {"bias_instability_dph", nt.bias_instability_dph}, {"rrw_dphsh", nt.rrw_dphsh},
		 {"quantization_arcsec", nt.quantization_arcsec}, {"allan_period_s", e.allan_period_s},
		 {"allan_samples", e.allan_samples}});
	JsonValue taus = JsonValue::array(), adevs = JsonValue::array();
	for (const auto& p : e.allan)
	{
		taus.push_back(p.tau_s);
		adevs.push_back(p.adev);
	}
	j["allan_tau_s"] = taus;
	j["allan_adev_dph"] = adevs;
	return j;
}

}  // namespace mrpt_fog::evaluate
