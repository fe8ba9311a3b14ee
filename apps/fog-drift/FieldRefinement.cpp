/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "FieldRefinement.h"

#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/CalibrationEarthRate.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::drift
{
nav::FieldRefinementOptions refinementOptionsFor(const FieldRefinementSettings& st, const Calibration& zcal,
												 double latitude_deg, double t0_unix_s, FieldRefinementResult& r)
{
	nav::FieldRefinementOptions o;
	o.standstill = st.standstill;
	o.noise = st.noise;
	o.min_still_s = st.min_still_s;
	o.guard_s = st.guard_s;
	o.significance_sigma = st.significance_sigma;
	r.significance_sigma = st.significance_sigma;
	o.expected_rate_dph = heading::verticalEarthRate_dph(latitude_deg);
	// the thermal model's uncertainty: its held-out 100 s stability (else the in-sample one)
	const double held = zcal.held_out.stability_dph, in = zcal.in_sample.stability_dph;
	r.thermal_sigma_dph = std::isfinite(held) && held > 0 ? held : (std::isfinite(in) && in > 0 ? in : 0.0);
	o.prior_offset_dph = 0.0;
	o.prior_sigma_dph = std::hypot(r.thermal_sigma_dph, st.turn_on_repeatability_dph);
	if (r.calibration_offset)  // the calibration's field offset is already applied: its uncertainty adds
		o.prior_sigma_dph = std::hypot(o.prior_sigma_dph, r.calibration_offset->sigmaAt_dph(t0_unix_s));
	r.prior_offset_dph = o.prior_offset_dph;
	r.prior_sigma_dph = o.prior_sigma_dph;
	r.expected_rate_dph = o.expected_rate_dph;
	return o;
}

void noteRefinement(const nav::FieldBiasRefiner& f, FieldRefinementResult& r)
{
	r.ran = true;
	r.updates = f.updates();
	r.short_standstills = f.shortStandstills();
	r.restarts = f.restarts();
	r.offset_dph = f.filter().offset_dph();
	r.offset_sigma_dph = f.filter().offset_sigma_dph();
	r.applied = f.applied();
	r.applied_since_s = f.appliedSince_s();
	if (r.updates.empty())
		r.note = "no standstill long enough to beat the prior (" + std::to_string(r.short_standstills) +
				 " shorter ones): no update; the compensated output is the thermal model's alone, identical to "
				 "--no-field-refinement";
	else if (!r.applied)
		r.note = std::to_string(r.updates.size()) +
				 " standstill update(s), offset within " + formatValue("%.3g", r.significance_sigma) +
				 " sigma of the prior: not applied; the compensated output is the thermal model's alone, identical "
				 "to --no-field-refinement";
	else
		r.note = std::to_string(r.updates.size()) + " standstill update(s), the estimate applied from the first "
				 "that showed the prior wrong";
}

void refineInMemory(const std::vector<double>& t_s, std::vector<double>& rate_dph, const std::vector<bool>& on,
					const OdometryPoses& odo, const nav::FieldRefinementOptions& options, FieldRefinementResult& result)
{
	if (t_s.size() != rate_dph.size() || on.size() != t_s.size())
		throw std::logic_error("refineInMemory: series of different lengths");
	if (t_s.empty()) return;
	nav::FieldBiasRefiner f(options, t_s.front());
	std::size_t j = 0, k_out = 0;
	const auto drain = [&] {
		nav::RefinedRate x;
		while (f.next(x))
		{
			if (k_out >= t_s.size() || x.t_s != t_s[k_out]) throw std::logic_error("refineInMemory: output out of step");
			if (on[k_out]) rate_dph[k_out] = x.rate_dph;
			k_out++;
		}
	};
	for (std::size_t k = 0; k < t_s.size(); k++)
	{
		for (; j < odo.t_s.size() && odo.t_s[j] <= t_s[k]; j++) f.addOdometry(odo.t_s[j], odo.x_m[j], odo.y_m[j], odo.phi_rad[j]);
		f.addRate(t_s[k], on[k] ? rate_dph[k] : std::numeric_limits<double>::quiet_NaN(), k > 0 && on[k] && !on[k - 1]);
		drain();
	}
	for (; j < odo.t_s.size(); j++) f.addOdometry(odo.t_s[j], odo.x_m[j], odo.y_m[j], odo.phi_rad[j]);
	f.finish();
	drain();
	if (k_out != t_s.size()) throw std::logic_error("refineInMemory: samples lost (times not increasing)");
	noteRefinement(f, result);
}

std::string refinementText(const FieldRefinementResult& r, double epoch_s)
{
	std::string s;
	if (r.calibration_offset)
		s += formatValue("  calibration field offset (fog-refine, revision %.0f): ", r.calibration_offset->revision) +
			 formatValue("%+.4f deg/h at the drive's date applied", r.calibration_offset_at_drive_dph) + "\n";
	if (!r.ran) return s + (r.note.empty() ? "" : "  field refinement: " + r.note + "\n");
	s += formatValue("  field refinement (standstill zero-rate updates; prior offset %.4f", r.prior_offset_dph) +
					formatValue(" +- %.4f deg/h", r.prior_sigma_dph) +
					formatValue(", thermal model share %.4f", r.thermal_sigma_dph) +
					formatValue("; still reads Earth rate %.4f deg/h): ", r.expected_rate_dph) + r.note + "\n";
	for (const auto& u : r.updates)
		s += formatValue("    still %.1f", u.start_s - epoch_s) + formatValue("-%.1f s: ", u.end_s - epoch_s) +
			 std::to_string(u.samples) + " samples used, read" + formatValue(" %+.4f deg/h; offset", u.mean_reading_dph) +
			 formatValue(" %+.4f", u.offset_before_dph) + formatValue(" +- %.4f ->", u.sigma_before_dph) +
			 formatValue(" %+.4f", u.offset_after_dph) + formatValue(" +- %.4f deg/h", u.sigma_after_dph) +
			 (u.applied ? ", applied" : "") + "\n";
	if (!r.updates.empty())
		s += formatValue("    offset at the end %+.4f", r.offset_dph) + formatValue(" +- %.4f deg/h", r.offset_sigma_dph) +
			 (r.restarts ? ", restarted at " + std::to_string(r.restarts) + " turn-on(s)" : std::string()) + "\n";
	return s;
}

}  // namespace mrpt_fog::drift
