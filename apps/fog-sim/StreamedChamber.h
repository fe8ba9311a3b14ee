/* fog-sim: physics simulation of a FOG with coil thermistors. */
#pragma once

/** \file StreamedChamber.h
 * A single-axis chamber run simulated and written sample by sample (issue 14): nothing of the
 * run is held, and --duration-s stops the simulation there instead of cutting a whole run. The
 * file is the one writeFogRawlog / writeFogCsv write from simulateChamber()'s series, byte for
 * byte (the same FogLogWriter, layout and values). The summary's 100 s bias figures come from
 * biasStats' pass form over a spill of the powered samples (the same numbers as the vector form). */

#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <string>
#include <vector>

namespace mrpt_fog::app
{
/** What fog-sim prints and writes to --json about a run. */
struct SimRunSummary
{
	std::size_t samples = 0;
	double last_time_s = 0;
	std::vector<ThermistorInfo> thermistors;
	std::vector<double> min_C, max_C;  //!< per thermistor
	bool has_stats = false;  //!< more than 2 powered samples over >= 200 s
	BiasStats stats;  //!< 100 s figures of the powered samples (table rate removed)
};

/** Simulates the chamber run up to max_time_s (infinity: the profile's end) into `path` (.rawlog,
 * .csv, .csv.gz; `extra_metadata` key/value pairs appended to the run's metadata) and returns the
 * summary. Throws std::invalid_argument when fewer than 2 samples result (nothing is written). */
SimRunSummary writeChamberStreamed(const std::string& path, const sim::ChamberProfile& profile,
								   const sim::FogDevice& device, const sim::SimSettings& settings, double max_time_s,
								   const std::vector<std::pair<std::string, std::string>>& extra_metadata);

}  // namespace mrpt_fog::app
