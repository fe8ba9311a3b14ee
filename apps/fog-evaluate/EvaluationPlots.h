/* fog-evaluate: the PNG figures. */
#pragma once

/** \file EvaluationPlots.h
 * fog-evaluate's figures (plot/PlotCanvas.h), written atomically into a directory:
 *  - bias_vs_time.png: bias about its mean, tau-s averages (bold) and tau/10-s averages (thin;
 *    the samples when tau/10 is under 2 sample periods), raw and compensated;
 *    thermistor temperatures below on the same time axis; gyro-off intervals (power column 0)
 *    and gaps in the log (> 5 sample periods) shaded;
 *  - bias_vs_temperature.png: tau-s averaged bias (about its mean) against the tau-s averaged
 *    mean coil temperature, in time order (loops show heating/cooling hysteresis);
 *  - allan_deviation.png: overlapping Allan deviation, log-log, with the fitted IEEE 952 lines.
 * Each bias is drawn about its own mean so raw (which holds the vertical Earth rate and the
 * turn-on bias) and compensated output share one axis; the means are in the legend. */

#include "RateEvaluation.h"

#include <mrpt_fog/obs/FogRun.h>

#include <string>
#include <vector>

namespace mrpt_fog::evaluate
{
struct PlotInputs
{
	/** The log (times, thermistors, power), read in passes: the plots keep what they draw,
	 * not the log (a long log's traces are thinned to 4096 time buckets). */
	const FogRun* run = nullptr;
	/** Rows (time, raw bias [deg/h], compensated bias [deg/h] with --cal), as evaluateRate reads. */
	const RowSpill* rows = nullptr;
	const RateEvaluation* raw = nullptr;
	const RateEvaluation* comp = nullptr;  //!< nullptr without --cal
	double tau_s = 100.0;
};

/** Writes the figures into dir (created when missing). Returns the files written. Throws
 * std::runtime_error naming the file on a write failure. bias_vs_temperature.png is skipped
 * (not in the list) when the log has no thermistor. */
std::vector<std::string> writeEvaluationPlots(const std::string& dir, const PlotInputs& in);

}  // namespace mrpt_fog::evaluate
