/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "FieldRefinement.h"

#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/obs/Units.h>

#include <cmath>
#include <stdexcept>

namespace mrpt_fog::drift
{
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
