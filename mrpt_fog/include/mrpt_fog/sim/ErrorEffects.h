/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ErrorEffects.h
 * Stable ids of the simulator's switchable error sources (the model-gap workflow refers to
 * them by these names; never rename one). Each one's descriptor (EffectRegistry.h) is the
 * single source of what is known about it:
 *   shupe_rate         Shupe term from the node temperature rates (CoilWinding)
 *   radial_gradient    elasto-optic bias proportional to Tin - Tout (coil layer means)
 *   gradient_rate      bias proportional to d(Tin - Tout)/dt
 *   thermistor_lag     first-order lag of the thermistors (off: they read the node instantly)
 *   hysteresis         heating vs cooling offset (rate-independent play over a temperature span)
 *   warmup             decaying exponential after each power-on
 *   scale_factor_temp  scale factor vs coil temperature, acting on applied rate and Earth rate
 *   magnetic           axial magnetic field sensitivity
 *   temp_poly_order    static bias polynomial in the electronics (source) temperature
 *   heat_source        electronics self-heating (off: zero power into the thermal network)
 *   earth_rate         vertical Earth rate at the device latitude
 * Noise (ARW, bias instability, rate random walk, quantisation) is not an effect: it is the
 * device's noise section. */

#include <set>
#include <string>
#include <vector>

namespace mrpt_fog::sim
{
using EffectSet = std::set<std::string>;

/** All ids, in the order above. */
const std::vector<std::string>& allEffectIds();
/** The default set (all of them). */
EffectSet defaultEffects();
/** Throws std::invalid_argument "unknown effect 'x' (known: ...)" for an unknown id. */
void checkEffectId(const std::string& id);
/** Applies command-line style selections to the default set: "ID" entries select exactly the
 * listed ids (plus any later "+ID"), "-ID" removes one, "+ID" adds one, "all" / "none" select
 * all or none. Throws on unknown ids. */
EffectSet effectsFromSelection(const std::vector<std::string>& selection);
/** Comma-separated ids (for metadata), "none" when empty. */
std::string effectsToString(const EffectSet& effects);

}  // namespace mrpt_fog::sim
