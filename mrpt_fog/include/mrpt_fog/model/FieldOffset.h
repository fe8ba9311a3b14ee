/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FieldOffset.h
 * What a calibration learns in the field (fog-refine): the bias offset the thermal model does
 * not hold, and its trend with the device's age, measured at the standstills of field logs. It
 * is the `field_offset:` section at the end of a calibration file:
 *
 *   field_offset:  # learned in the field by fog-refine; revision 2
 *     offset_dph: 0.2931          # at reference_unix_s [deg/h], added to the thermal bias
 *     sigma_dph: 0.0123           # its 1-sigma (a turn-on's own draw comes on top) [deg/h]
 *     aging_dph_per_day: 0.00014  # trend [deg/h per day]; 0 when one date only
 *     aging_sigma_dph_per_day: 0.00003
 *     reference_unix_s: 1722297600
 *     revision: 2
 *     previous: "cal_r1.yaml"     # the file it was refined from (kept, never overwritten)
 *     logs: ["field1.rawlog", "field2.rawlog"]
 *
 * The bias of a log taken at UNIX time t is the thermal bias + offset_dph + aging_dph_per_day x
 * (t - reference_unix_s) / 86400. Who applies it: the heading pipeline it is given to
 * (mrpt_fog_heading/HeadingPipeline.h, PipelineOptions::field_offset: before its standstill
 * updates, whose prior it then is), as fog-drift's compensated variant does. fog-compensate and
 * the Compensator do not: their output is the thermal model's alone. A build that predates the
 * section ignores it. */

#include <optional>
#include <string>
#include <vector>

namespace mrpt_fog
{
struct FieldOffset
{
	double offset_dph = 0;
	double sigma_dph = 0;
	double aging_dph_per_day = 0;
	double aging_sigma_dph_per_day = 0;
	double reference_unix_s = 0;
	int revision = 1;
	std::string previous;
	std::vector<std::string> logs;

	/** The offset at UNIX time t_s [deg/h]. */
	double offsetAt_dph(double t_unix_s) const;
	/** Its 1-sigma there (offset and trend uncertainties, independent) [deg/h]. */
	double sigmaAt_dph(double t_unix_s) const;
};

/** The field_offset section of a calibration file's text, if any. Throws std::invalid_argument
 * "<source>: field_offset.<key>: <reason>" on a malformed section. */
std::optional<FieldOffset> fieldOffsetFromYaml(const std::string& text, const std::string& source);
/** The same from a file (throws std::runtime_error when it cannot be read). */
std::optional<FieldOffset> loadFieldOffset(const std::string& calibration_path);

/** The calibration text with its field_offset section (if any) replaced by `offset`'s. The
 * section is always the file's last top-level key, written from a line "field_offset:". */
std::string withFieldOffset(const std::string& calibration_text, const FieldOffset& offset);

}  // namespace mrpt_fog
