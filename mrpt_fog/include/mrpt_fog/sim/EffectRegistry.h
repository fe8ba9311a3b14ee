/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file EffectRegistry.h
 * One descriptor per switchable error source of the simulator: what every other part of the
 * project (the simulator's terms, fog-sim's --help, the simulator configuration of the
 * model-gap workflow, the proof trials, the completeness tests) reads about an effect. The ids
 * are stable (files and command lines refer to them; never rename one) and the table's order is
 * the order of ErrorEffects.h's allEffectIds() and of the "sim.effects" metadata.
 *
 * Adding an effect: one FOG_EFFECT row at the end of EffectTable.inc, which holds all that is
 * known about it (the enumerator and the descriptor are both generated from that row): its id and what it means, the default of its coefficient (the
 * device keeps one value per effect, ErrorCoefficients::coefficients), its simulator term when
 * it is an additive bias, and from that term its missing-effect candidate (a hand-written one in
 * the discrepancy room's CandidateEffect.cpp replaces it when the effect needs more, e.g. a
 * nonlinear parameter). The device YAML fields, the simulator calibration's free parameters
 * (slots, finite-difference steps, bounds), fog-sim --help and the proof trials read the
 * descriptor too. EffectRegistry.cpp checks at compile time that descriptor i is enumerator i;
 * tests/sim/test_EffectRegistry.cpp and tests/discrepancy/test_EffectRegistryCandidates.cpp
 * fail until every part is there.
 */

#include <array>
#include <cstddef>
#include <limits>
#include <optional>
#include <string>

namespace mrpt_fog::sim
{
struct ErrorCoefficients;
struct FogDevice;

/** The switchable error sources, generated from EffectTable.inc (one row per effect). */
enum class Effect : unsigned char
{
#define FOG_EFFECT(enumerator, ...) enumerator,
#include <mrpt_fog/sim/EffectTable.inc>
#undef FOG_EFFECT
};
/** How many effects EffectTable.inc lists. */
constexpr std::size_t kEffectCount = 0
#define FOG_EFFECT(enumerator, ...) +1
#include <mrpt_fog/sim/EffectTable.inc>
#undef FOG_EFFECT
	;

/** The effect's position in effectDescriptors() and in ErrorCoefficients::coefficients. */
constexpr std::size_t indexOf(Effect effect) { return static_cast<std::size_t>(effect); }

/** Which residual of a measured run can identify the effect in the model-gap workflow. */
enum class IdentifiedIn
{
	Bias,  //!< the gyro-bias residual (a column of the bias model)
	Temperature,  //!< the thermistor residual
	NotIdentified  //!< not a missing-effect candidate (e.g. Earth rate: known, a constant)
};

/** Inputs of the additive bias terms at one simulator step. */
struct EffectTermInputs
{
	double gradient_C = 0;  //!< inner minus outer layer mean temperature [degC]
	double time_since_power_on_s = 0;  //!< +inf while never powered
	double field_uT = 0;  //!< applied axial magnetic field
	double electronics_C = 0;  //!< electronics (source) node temperature
};

/** A field of the device's `errors:` section that shapes an effect without setting its
 * strength (a time constant, a span, a reference temperature). */
struct ShapeField
{
	const char* key = nullptr;  //!< YAML key under `errors:`; nullptr = none
	double ErrorCoefficients::*member = nullptr;
};

/** How a simulator calibration moves the effect's calibration parameter (SimulatorCalibration.h). */
struct CalibrationSlots
{
	double fd_step = 1e-3;  //!< finite-difference step: a typical size of the parameter
	double min_value = -std::numeric_limits<double>::infinity();  //!< kept at or above this
	bool indexed = false;  //!< several slots, labelled "id[i]"
	/** Slot `index` of the parameter in a device, nullptr past the last one; nullptr when the
	 * parameter is the scalar `coefficient` (its only slot). */
	double* (*slot)(FogDevice& device, std::size_t index) = nullptr;
};

struct EffectDescriptor
{
	Effect effect;
	const char* id;  //!< stable id
	const char* summary;  //!< the physics in one line (fog-sim --help, docs)
	/** Device YAML key of the effect's strength ("errors.magnetic_dph_per_uT"); for effects
	 * whose strength is not one scalar of `errors`, the parameter(s) that set it. */
	const char* coefficient_key;
	const char* coefficient_unit;
	/** Default of its scalar coefficient (ErrorCoefficients::coefficient(effect), the default
	 * device's value); nullopt when its strength is not one scalar of `errors` (set elsewhere). */
	std::optional<double> default_coefficient;
	/** Free parameter of a simulator configuration that calibrates it (SimulatorConfig.h), ""
	 * when none. */
	const char* calibration_parameter;
	IdentifiedIn identified_in;
	const char* identified_by;  //!< the data (test-profile segments) that excite and separate it
	/** Proof-trial scaling (tests/support/SimEffectTrial): the parameter multiplied to reach an
	 * effect-to-noise ratio ("" = not trialled on the simulator). */
	const char* trial_scaling;
	/** Its additive bias term per unit of its coefficient [deg/h per coefficient_unit], for an
	 * effect linear in its scalar coefficient: the simulator adds coefficient x this (in the
	 * table's order), and, unless the discrepancy room has a hand-written candidate for it, the
	 * missing-effect candidate's column is this on each sample of the measured run (inputs it
	 * cannot measure, the electronics temperature, are NaN there; shape fields at the default
	 * device's values). nullptr when the term is not of that form (see add_bias_term_dph) or
	 * needs the simulator's state (Shupe, gradient rate, hysteresis), acts elsewhere (lag, heat
	 * source, scale factor on the applied rate, Earth rate) and is written in FogSimulator.cpp. */
	double (*bias_per_coefficient)(const EffectTermInputs& in, const ErrorCoefficients& e);
	/** An additive bias term [deg/h] not linear in one scalar (the electronics polynomial), added
	 * to the sum in place; nullptr otherwise. */
	void (*add_bias_term_dph)(const EffectTermInputs& in, const ErrorCoefficients& e, double& sum_dph);
	/** Its other `errors:` fields, in the device file's order after the coefficient. */
	std::array<ShapeField, 1> shape_fields;
	/** How a simulator calibration moves `calibration_parameter` (unused when that is ""). */
	CalibrationSlots calibration;
};

/** Every effect, in enumerator order. */
const std::array<EffectDescriptor, kEffectCount>& effectDescriptors();

/** The descriptor of an effect. */
const EffectDescriptor& descriptorOf(Effect effect);

/** Effect by id; throws std::invalid_argument "unknown effect 'x' (known: ...)". */
Effect effectFromId(const std::string& id);

/** The effect whose calibration_parameter is `parameter`, or nullptr. */
const EffectDescriptor* descriptorOfCalibrationParameter(const std::string& parameter);

/** Slot `index` of the effect's calibration parameter in `device`, nullptr past the last one
 * (or when the effect has no calibration parameter). */
double* calibrationSlot(const EffectDescriptor& effect, FogDevice& device, std::size_t index);

/** The effect's scalar coefficient in `e`, nullptr when it has none (default_coefficient). */
double* coefficientIn(const EffectDescriptor& effect, ErrorCoefficients& e);

/** The defaults of every effect's coefficient, indexed by Effect (NaN where none). */
std::array<double, kEffectCount> defaultCoefficients();

/** How many slots the effect's calibration parameter has in `device`. */
std::size_t calibrationSlotCount(const EffectDescriptor& effect, const FogDevice& device);

/** Its stable id. */
inline const char* toString(Effect effect) { return descriptorOf(effect).id; }

}  // namespace mrpt_fog::sim
