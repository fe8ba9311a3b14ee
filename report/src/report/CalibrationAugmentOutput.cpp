/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/report/CalibrationAugmentOutput.h>

namespace mrpt_fog::discrepancy
{
namespace
{
/** The added terms' names, then the refitted scale factor: "scale_factor(T(thermistor), order
 * N, slope ppm/degC)", then the magnetic sensitivity: "magnetic(k +- std deg/h per uT, field
 * min .. max uT)". */
std::vector<std::string> addedTermLabels(const AugmentedCalibration& aug)
{
	std::vector<std::string> labels = aug.added_terms;
	if (aug.scale_factor_added && aug.augmented.scale_factor)
	{
		const ScaleFactorModel& sf = *aug.augmented.scale_factor;
		labels.push_back("scale_factor(T(" + sf.thermistor + "), order " + std::to_string(sf.order()) + ", " +
						 formatValue("%.4g", sf.slope_ppm_per_C) + " ppm/degC)");
	}
	if (aug.magnetic_added && aug.augmented.magnetic)
	{
		const MagneticModel& m = *aug.augmented.magnetic;
		labels.push_back("magnetic(" + formatValue("%.4g", m.dph_per_uT) + " +- " + formatValue("%.2g", m.dph_per_uT_std) +
						 " deg/h per uT, field " + formatValue("%g", m.field_min_uT) + " .. " +
						 formatValue("%g", m.field_max_uT) + " uT)");
	}
	return labels;
}

JsonValue figures(const FitFigures& f)
{
	return JsonValue::object({{"label", f.label}, {"samples", static_cast<unsigned long>(f.samples)},
							  {"rms_dph", f.rms_dph}, {"stability_dph", f.stability_dph},
							  {"range_dph", f.range_dph}, {"tau_s", f.tau_s}});
}
}  // namespace

std::string rateWindowNote(const AugmentedCalibration& aug)
{
	return "rate estimator " + aug.augmented.rate_estimator.describe() + " instead of " +
		   aug.base.rate_estimator.describe() + " (analysed-run RMS " + formatValue("%.4g", aug.rate_window.rms_dph) +
		   " vs " + formatValue("%.4g", aug.rate_window.base_window_rms_dph) + " deg/h with the added terms)";
}

std::string augmentedCalibrationText(const AugmentedCalibration& aug, const std::string& path)
{
	std::string t = "Calibration written to " + path + ": ";
	const auto added = addedTermLabels(aug);
	if (added.empty()) t += "the calibration under test, nothing added\n";
	else
	{
		t += "the calibration under test plus";
		for (const auto& a : added) t += " " + a;
		t += " (refitted on the analysed run)\n";
	}
	if (aug.rate_window.changed) t += "  " + rateWindowNote(aug) + "\n";
	for (const auto& [id, why] : aug.not_written) t += "  not written: " + id + " (" + why + ")\n";
	if (aug.has_confirm)
		t += "  through the compensator on the confirmation run: RMS " + formatValue("%.4g", aug.before.rms_dph) + " -> " +
			 formatValue("%.4g", aug.after.rms_dph) + " deg/h, " + formatValue("%.4g", aug.before.tau_s) + " s stability " +
			 formatValue("%.4g", aug.before.stability_dph) + " -> " + formatValue("%.4g", aug.after.stability_dph) + " deg/h\n";
	return t;
}

JsonValue augmentedCalibrationJson(const AugmentedCalibration& aug, const std::string& path)
{
	JsonValue j = JsonValue::object();
	j["path"] = path;
	j["added_terms"] = JsonValue::arrayOf(addedTermLabels(aug));
	if (aug.rate_window.changed) j["rate_estimator_chosen"] = rateWindowNote(aug);
	if (aug.magnetic_added && aug.augmented.magnetic)
	{
		const MagneticModel& m = *aug.augmented.magnetic;
		j["magnetic"] = JsonValue::object({{"dph_per_uT", m.dph_per_uT},
										   {"dph_per_uT_std", m.dph_per_uT_std},
										   {"field_min_uT", m.field_min_uT},
										   {"field_max_uT", m.field_max_uT},
										   {"samples", static_cast<unsigned long>(m.samples)}});
	}
	j["not_written"] = JsonValue::arrayOf(
		aug.not_written, [](const auto& nw) { return JsonValue::object({{"id", nw.first}, {"reason", nw.second}}); });
	if (aug.has_confirm)
		j["confirm_through_compensator"] =
			JsonValue::object({{"before", figures(aug.before)}, {"after", figures(aug.after)}});
	return j;
}

}  // namespace mrpt_fog::discrepancy
