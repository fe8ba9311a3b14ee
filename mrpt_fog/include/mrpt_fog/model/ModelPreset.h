/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ModelPreset.h
 * Model presets (the names users type after --model), resolved against a sensor layout:
 *
 *   multipoint            seed eq. 2 on all thermistors: per thermistor T^1..T^5, dT/dt^1..3
 *   multipoint:A,B        the same on the chosen thermistors
 *   M1[:A]                seed eq. 3: poly5(T)                        (default: first inner)
 *   M2[:A]                seed eq. 4: poly5(T) + poly3(dT/dt)
 *   M3[:IN,OUT]           seed eq. 5: M2(IN) + poly3(IN - OUT)        (default: first inner and
 *   M4[:IN,OUT]           seed eq. 6: poly3(IN-OUT) + poly3(d/dt(IN-OUT))   the outer nearest in angle)
 *   points:K              multipoint on the best K-thermistor subset, chosen by held-out error
 *   terms:NAME;NAME;...   an explicit term list (see ThermalFeatureSet.h)
 *
 * Any preset but terms: may end in "@T/R" to set the temperature / rate orders (default 5/3;
 * T 1..5, R 0..3; differences use R for M3/M4 as in the seed), e.g. "multipoint:Ti1,To1@3/1",
 * or in "@T" to set the temperature order only (e.g. "M1:imu@3"). M1 has no rate terms: a rate
 * order other than 0 is refused for it.
 */

#include <mrpt_fog/model/ThermalFeatureSet.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog
{
/** The preset grammar's kinds (docs/reference/model.md): all or chosen thermistors at full order, the
 * seed's equations M1..M4, the best K of all thermistors, or an explicit term list. */
enum class PresetKind : unsigned char
{
	Multipoint,
	M1,
	M2,
	M3,
	M4,
	Points,
	Terms
};
/** "multipoint", "M1".."M4", "points", "terms" (as written in a preset). */
const char* toString(PresetKind kind);

struct ModelPreset
{
	std::string text;  //!< as typed
	PresetKind kind = PresetKind::Multipoint;
	std::vector<std::string> thermistors;  //!< chosen points (all for multipoint/points)
	int temp_order = 5;
	int rate_order = 3;
	int points_k = 0;  //!< for "points:K"
	std::vector<ThermalTerm> explicit_terms;  //!< for "terms:"
};

/** Parses `text` against the layout of the calibration data. Throws std::invalid_argument with
 * a one-line reason: unknown preset, unknown thermistor (the known ones are listed), wrong
 * number of points, order out of range, K outside 1..thermistor count. */
ModelPreset parseModelPreset(const std::string& text, const std::vector<ThermistorInfo>& layout);

/** The terms of a preset (for "points", the multipoint terms of all its candidate thermistors;
 * the subset search happens in the fit). */
ThermalFeatureSet presetFeatures(const ModelPreset& preset);

/** Multipoint terms (seed eq. 2) for the given thermistors and orders. */
std::vector<ThermalTerm> multipointTerms(const std::vector<std::string>& thermistors, int temp_order, int rate_order);

}  // namespace mrpt_fog
