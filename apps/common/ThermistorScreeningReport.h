/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file ThermistorScreeningReport.h
 * What the programs that compensate (fog-compensate, fog-drift) print and write about the
 * thermistor screening (mrpt_fog/model/ThermistorHealth.h) they run before the Compensator:
 * stuck, spiking or out-of-range readings become dropouts, so the fallback model takes over. */

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/model/ThermistorHealth.h>
#include <mrpt_fog/obs/FogRun.h>

#include <functional>
#include <memory>
#include <string>

namespace mrpt_fog::app
{
/** Screens a copy of the series' thermistors (the caller's data is kept as read) and returns
 * it with the counts. With `enabled` false the copy is returned unscreened (all counts 0). */
FogSeries screenedForCompensation(const FogSeries& in, bool enabled, ThermistorScreening& screening);

/** Screens the series' thermistors in place (rejected readings become NaN dropouts) when
 * enabled; returns the counts (all 0 when disabled). For the programs that fit or evaluate
 * (fog-calibrate, fog-evaluate, fog-discrepancy): the same screening fog-compensate runs, so that
 * one log gives the same figures through every program. */
ThermistorScreening screenInPlace(FogSeries& series, bool enabled);

/** The same screening sample by sample, for a log read as a stream (readFogRun's `each`):
 *   StreamScreening sc(enabled);
 *   FogRun run = readFogRun(path, label, sc.hook());
 *   ThermistorScreening counts = sc.result();                   // all 0 when disabled */
class StreamScreening
{
   public:
	explicit StreamScreening(bool enabled) : enabled_(enabled) {}
	std::function<void(double, double*, std::size_t)> hook();
	/** The counts, named after the run's thermistors (call after reading). */
	ThermistorScreening result(const FogRun& run) const;

   private:
	bool enabled_;
	std::unique_ptr<ThermistorHealth> health_;
};

/** One line per thermistor with a rejected reading ("  thermistor T3: stuck 412 samples (1
 * event), spike 0, out of range 0"); "  thermistor screening: all readings accepted" when
 * none; "  thermistor screening: off" when disabled. */
std::string screeningText(const ThermistorScreening& s, bool enabled);

/** {"enabled": bool, "rejected_readings": n, "thermistors": {name: {stuck, stuck_events,
 * spike, out_of_range, dropout, level_changes}}}. */
JsonValue screeningJson(const ThermistorScreening& s, bool enabled);

}  // namespace mrpt_fog::app
