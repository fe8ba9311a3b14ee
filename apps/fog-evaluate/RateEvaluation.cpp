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

JsonValue toJson(const RateEvaluation& e)
{
	JsonValue j = JsonValue::object();
	j["stability_dph"] = e.stats.stability_dph;
	j["range_dph"] = e.stats.range_dph;
	j["raw_peak_to_peak_dph"] = e.stats.raw_peak_to_peak_dph;
	j["mean_dph"] = e.stats.mean_dph;
	j["window_count"] = e.stats.window_count;
	j["empty_window_count"] = e.stats.empty_window_count;
	j["samples_used"] = e.stats.samples_used;
	j["dropped_tail_s"] = e.stats.dropped_tail_s;
	j["arw_dpsh"] = e.terms.arw_dpsh;
	j["bias_instability_dph"] = e.terms.bias_instability_dph;
	j["rrw_dphsh"] = e.terms.rrw_dphsh;
	j["quantization_arcsec"] = e.terms.quantization_arcsec;
	j["allan_period_s"] = e.allan_period_s;
	j["allan_samples"] = e.allan_samples;
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
