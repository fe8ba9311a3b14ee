/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ThermistorHealth.h
 * Screening of thermistor readings before the Compensator: a reading that cannot be trusted is
 * turned into a dropout (NaN), which the Compensator already handles with its fallback model
 * (Compensator.h). Causal, sample by sample, O(n^2) per sample for n thermistors (n is 4-8).
 *
 * What is screened, per thermistor (temperatures in degC, times in s):
 *  - OutOfRange: a non-finite reading or one outside [valid_min_C, valid_max_C].
 *  - Spike: a reading further from the last accepted reading than
 *      spike_jump_C + max_rate_C_per_s * (time since that accepted reading).
 *    A coil-mounted thermistor cannot move faster than the coil, so such a jump is a glitch.
 *    If the readings stay that far away for longer than spike_max_duration_s, the new level is
 *    accepted (a real jump, e.g. a re-seated sensor), counted as a level change.
 *  - Stuck: a reading that has stayed within stuck_tolerance_C of one value for at least
 *    stuck_window_s AND stuck_min_samples readings while some other thermistor of the same gyro
 *    moved by at least stuck_peer_change_C over that same interval. (The sample count keeps
 *    slow logs honest: at 0.1 Hz a quantised (0.01 C) reading legitimately repeats for 3-4
 *    samples at a temperature turnaround while a peer on the other coil surface moves.) It stays flagged until the reading moves
 *    again. A sensor that is constant while all others are constant too is not flagged: its
 *    value is then right, and a single thermistor cannot be told stuck from steady.
 *    Readings of a stuck sensor before detection (up to stuck_window_s) pass unchanged.
 *  - a NaN reading is already a dropout; it passes as NaN and counts as Dropout.
 *
 * Bad input: time not strictly increasing or not finite throws std::invalid_argument naming
 * the time; settings out of range throw std::invalid_argument naming the field.
 */

#include <mrpt_fog/obs/FogSeries.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mrpt_fog
{
struct ThermistorHealthSettings
{
	double valid_min_C = -80.0;  //!< readings below are OutOfRange [degC]
	double valid_max_C = 150.0;  //!< readings above are OutOfRange [degC]
	double spike_jump_C = 0.5;  //!< allowed jump on top of the rate allowance [degC]
	double max_rate_C_per_s = 0.2;  //!< fastest credible coil temperature change [degC/s]
	double spike_max_duration_s = 20.0;  //!< a longer excursion is accepted as a new level [s]
	double stuck_window_s = 30.0;  //!< constant this long (with a moving peer) = stuck [s]
	std::size_t stuck_min_samples = 10;  //!< ... and for at least this many readings
	double stuck_tolerance_C = 0.0;  //!< "constant": within this of the run's first value [degC]
	double stuck_peer_change_C = 0.2;  //!< a peer must move this much in the window [degC]

	/** Throws std::invalid_argument naming the first bad field. */
	void validate() const;
};

enum class ThermistorState : std::uint8_t
{
	Ok = 0,
	Dropout = 1,  //!< NaN on input
	OutOfRange = 2,
	Spike = 3,
	Stuck = 4
};
const char* toString(ThermistorState s);

/** Per-thermistor sample counts of a screening. */
struct ThermistorHealthCounters
{
	std::size_t ok = 0, dropout = 0, out_of_range = 0, spike = 0, stuck = 0;
	std::size_t level_changes = 0;  //!< long excursions accepted as a new level
	std::size_t stuck_events = 0;  //!< times a stuck condition was detected
};

class ThermistorHealth
{
   public:
	/** Screens `thermistor_count` readings per sample (throws on bad settings). */
	explicit ThermistorHealth(std::size_t thermistor_count, const ThermistorHealthSettings& settings = {});

	/** One sample: time [s] strictly increasing; temp_C[thermistor_count] [degC] is screened in
	 * place (rejected readings become NaN). Returns true when any reading was rejected
	 * (OutOfRange, Spike or Stuck). */
	bool step(double time_s, double* temp_C);

	std::size_t thermistorCount() const { return ch_.size(); }
	/** State of thermistor i at the last sample. */
	ThermistorState state(std::size_t i) const { return ch_.at(i).state; }
	const ThermistorHealthCounters& counters(std::size_t i) const { return ch_.at(i).counters; }
	const ThermistorHealthSettings& settings() const { return settings_; }
	void reset();

   private:
	struct Channel
	{
		ThermistorState state = ThermistorState::Ok;
		bool has_accepted = false;
		double accepted_C = 0, accepted_t = 0;  // last accepted reading and its time
		double excursion_start_t = 0;  // start of the current spike excursion
		bool in_excursion = false;
		bool has_run = false;  // a constant run is being tracked
		double run_value_C = 0, run_start_t = 0;
		std::size_t run_samples = 0;  // readings in the current constant run
		std::vector<double> peer_at_run_start;  // peers' readings when the run started (NaN: none yet)
		bool stuck = false;
		ThermistorHealthCounters counters;
	};
	void startRun(std::size_t i, double t, double value, const double* raw);

	ThermistorHealthSettings settings_;
	std::vector<Channel> ch_;
	std::vector<double> raw_;
	bool first_ = true;
	double last_t_ = 0;
};

/** What screenThermistors() did, per thermistor (series order). */
struct ThermistorScreening
{
	std::vector<std::string> names;
	std::vector<ThermistorHealthCounters> counters;
	std::size_t rejected_readings = 0;  //!< OutOfRange + Spike + Stuck, all thermistors
};

/** Screens every thermistor column of a series in place, in time order (the same causal
 * screening the streaming class does). Throws std::invalid_argument on a series whose time is
 * not strictly increasing. */
ThermistorScreening screenThermistors(FogSeries& series, const ThermistorHealthSettings& settings = {});

}  // namespace mrpt_fog
