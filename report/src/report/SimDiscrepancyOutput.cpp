/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/report/DiscrepancyOutput.h>
#include <mrpt_fog/report/SimDiscrepancyOutput.h>

#include <cmath>
#include <sstream>

namespace mrpt_fog::discrepancy
{
namespace
{
/** [{"name": names[i], key: values[i], ...}, ...] for the given (key, values) columns. */
JsonValue perThermistorJson(const std::vector<std::string>& names,
							std::initializer_list<std::pair<const char*, const std::vector<double>*>> columns)
{
	JsonValue th = JsonValue::array();
	for (std::size_t i = 0; i < names.size(); ++i)
	{
		JsonValue e = JsonValue::object();
		e["name"] = names[i];
		for (const auto& [key, values] : columns) e[key] = (*values)[i];
		th.push_back(e);
	}
	return th;
}

JsonValue tempGapJson(const TemperatureGap& g)
{
	JsonValue j = JsonValue::object();
	j["run"] = g.label;
	JsonValue b = JsonValue::object(), a = JsonValue::object();
	b["rms_C"] = g.rms_before_C;
	a["rms_C"] = g.rms_after_C;
	j["before"] = b;
	j["after"] = a;
	j["thermistors"] = perThermistorJson(g.names, {{"rms_before_C", &g.rms_before_per_C}, {"rms_after_C", &g.rms_after_per_C}});
	return j;
}

JsonValue valuesJson(const std::vector<std::pair<std::string, double>>& v)
{
	JsonValue o = JsonValue::object();
	for (const auto& [k, x] : v) o[k] = x;
	return o;
}

/** {label: [low, high]} from values and half-widths (null when not estimable). */
JsonValue ciJson(const std::vector<std::pair<std::string, double>>& values,
				 const std::vector<std::pair<std::string, double>>& half)
{
	JsonValue o = JsonValue::object();
	for (const auto& [k, h] : half)
		for (const auto& [kv, v] : values)
			if (kv == k)
			{
				if (!std::isfinite(h))
				{
					o[k] = JsonValue();
					break;
				}
				o[k] = JsonValue::array({v - h, v + h});
				break;
			}
	return o;
}

std::string valuesText(const std::vector<std::pair<std::string, double>>& values,
					   const std::vector<std::pair<std::string, double>>& half)
{
	std::string out;
	for (const auto& [k, v] : values)
	{
		out += " " + k + "=" + formatValue("%.4g", v);
		for (const auto& [kh, h] : half)
			if (kh == k && std::isfinite(h)) out += " (+-" + formatValue("%.2g", h) + ")";
	}
	return out;
}

/** The temperature channel's heat-source test (HeatSourceCandidate.h). */
JsonValue heatSourceJson(const HeatSourceResult& h, const HeatSourceConfirm& confirm)
{
	JsonValue hs = JsonValue::object();
	hs["tested"] = h.tested;
	hs["untestable_reason"] = h.untestable_reason;
	hs["named"] = h.named;
	if (h.tested)
	{
		hs["tau_s"] = h.tau_s;
		hs["amplitude_C"] = h.amplitude_C;
		hs["ci"] = JsonValue::array({h.ci_low_C, h.ci_high_C});
		hs["chi2"] = h.chi2;
		hs["p_adjusted"] = h.p_adjusted;
		hs["delta_bic"] = h.delta_bic;
		hs["confidence"] = h.confidence;
		hs["same_sign"] = h.same_sign;
		hs["nearest"] = h.nearest;
		JsonValue th = JsonValue::array();
		for (const auto& t : h.thermistors)
		{
			JsonValue e = JsonValue::object();
			e["name"] = t.info.name;
			e["side"] = toString(t.info.side);
			e["angle_deg"] = t.info.angle_deg;
			e["amplitude_C"] = t.amplitude_C;
			e["se_C"] = t.se_C;
			th.push_back(e);
		}
		hs["thermistors"] = th;
	}
	hs["sentence"] = h.sentence;
	if (confirm.tested)
	{
		hs["confirmed"] = confirm.confirmed;
		hs["confirm_p"] = confirm.p;
	}
	return hs;
}

/** The thermal fit (ThermalFit.h). */
JsonValue thermalFitJson(const ThermalFit& t)
{
	JsonValue tf = JsonValue::object();
	tf["rms_C"] = t.rms_C;
	tf["threshold_C"] = t.threshold_C;
	tf["misfit"] = t.misfit;
	tf["worst_thermistor"] = t.worst_thermistor;
	tf["worst_rms_C"] = t.worst_rms_C;
	tf["max_abs_C"] = t.max_abs_C;
	tf["max_abs_thermistor"] = t.max_abs_thermistor;
	tf["max_abs_time_s"] = t.max_abs_time_s;
	tf["thermistors"] = perThermistorJson(t.names, {{"rms_C", &t.rms_per_C}});
	tf["fix"] = toString(t.fix);
	tf["lag_share"] = t.lag_share;
	tf["lag_tau_s"] = t.lag_tau_s;
	tf["power_share"] = t.power_share;
	tf["power_tau_s"] = t.power_tau_s;
	tf["sentence"] = t.sentence;
	return tf;
}

}  // namespace

JsonValue simDiscrepancyJson(const SimDiscrepancyReport& R)
{
	JsonValue j = discrepancyJson(R.report);
	j["model_kind"] = "simulator";
	JsonValue s = JsonValue::object();
	s["config"] = R.config_source;
	s["driving_input"] = R.drive;
	if (R.report.has_confirm) s["driving_input_confirm"] = R.drive_confirm;
	s["effects_before"] = JsonValue::arrayOf(R.effects_before);
	s["effects_after"] = JsonValue::arrayOf(R.effects_after);
	s["free_before"] = JsonValue::arrayOf(R.free_before);
	s["free_after"] = JsonValue::arrayOf(R.free_after);
	s["calibrated_before"] = valuesJson(R.calibrated_before);
	s["calibrated_after"] = valuesJson(R.calibrated_after);
	s["calibrated_before_ci95"] = ciJson(R.calibrated_before, R.calibrated_before_ci95_half);
	s["calibrated_after_ci95"] = ciJson(R.calibrated_after, R.calibrated_after_ci95_half);
	s["simulations"] = R.simulations;
	j["simulator"] = s;
	j["heat_source_test"] = heatSourceJson(R.heat, R.heat_confirm);
	j["temperature_gap"] = tempGapJson(R.temp_gap);
	j["thermal_fit"] = thermalFitJson(R.thermal);
	if (R.thermal.misfit)
		j["verdict"] = std::string("thermal model misfit (") + toString(R.thermal.fix) + "): first disagreement, no bias effect judged";
	if (R.drive_air_ci95_mean_C >= 0)
	{
		JsonValue a = JsonValue::object();
		a["knots"] = static_cast<double>(R.drive_air_knots);
		a["fit_rms_C"] = R.drive_air_fit_rms_C;
		a["ci95_half_mean_C"] = R.drive_air_ci95_mean_C;
		a["ci95_half_max_C"] = R.drive_air_ci95_max_C;
		if (R.unresolved_share >= 0) a["unresolved_share"] = R.unresolved_share;
		j["simulator"]["reconstructed_air"] = a;
	}
	if (R.report.has_confirm) j["temperature_gap_confirm"] = tempGapJson(R.temp_gap_confirm);
	return j;
}

std::string simDiscrepancyText(const SimDiscrepancyReport& R)
{
	std::ostringstream os;
	os << "Simulator configuration under test: " << R.config_source << "\n";
	os << "Driving input: " << R.drive << "\n";
	os << "Calibrated (" << R.simulations << " simulator runs):";
	os << valuesText(R.calibrated_before, R.calibrated_before_ci95_half) << "\n";
	os << "Temperature channel: " << R.heat.sentence << "\n";
	os << R.thermal.sentence << "\n";
	if (R.unresolved_share >= 0)
		os << "Unresolved thermal content: " << formatValue("%.0f", 100 * R.unresolved_share)
		   << " % of the bias residual follows the thermistors' measured-minus-simulated rates and Tin - Tout (air "
			  "changes faster than the reconstructed air's knots). It is taken out before the candidates are "
			  "tested: an effect acting only there cannot be told from the configured effects' response to it "
			  "without the chamber profile.\n";
	std::string body = discrepancyText(R.report);
	if (R.thermal.misfit)
	{
		const std::string from = "Verdict: no missing effect found";
		if (const auto pos = body.find(from); pos != std::string::npos)
			body.replace(pos, from.size(), std::string("Verdict: thermal model misfit (") + toString(R.thermal.fix) +
											   "): the first disagreement; no bias effect judged on top of it");
	}
	os << body;
	if (R.effects_after != R.effects_before)
	{
		os << "Recalibrated with the named effect(s) on:";
		os << valuesText(R.calibrated_after, R.calibrated_after_ci95_half) << "\n";
	}
	auto line = [&](const TemperatureGap& g)
	{
		os << "Temperature gap on " << g.label << ": thermistor residual RMS " << formatValue("%.4g", g.rms_before_C) << " -> "
		   << formatValue("%.4g", g.rms_after_C) << " C\n";
	};
	line(R.temp_gap);
	if (R.report.has_confirm) line(R.temp_gap_confirm);
	return os.str();
}

}  // namespace mrpt_fog::discrepancy
