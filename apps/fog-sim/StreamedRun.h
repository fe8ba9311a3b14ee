/* fog-sim: physics simulation of a FOG with coil thermistors. */
#pragma once

/** \file StreamedRun.h
 * A single-axis chamber run or vehicle drive simulated and written sample by sample:
 * nothing of the run is held. The file is the one writeFogRawlog / writeFogCsv write from
 * simulateChamber()'s / simulateDrive()'s series and observations, byte for byte (the same
 * FogLogWriter, layout, values and merge order). The summary's 100 s bias figures come from
 * biasStats' pass form over a spill of the powered samples (the same numbers as the vector form).
 *  - chamber: --duration-s stops the simulation there instead of cutting a whole run;
 *  - drive: the metadata holds the coil's thermal transient over the whole drive, so the drive
 *    is simulated twice (the transient, then the samples). */

#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/obs/FogSeries.h>
#include <mrpt_fog/sim/ChamberProfile.h>
#include <mrpt_fog/sim/ChamberRun.h>
#include <mrpt_fog/sim/DriveRun.h>
#include <mrpt_fog/sim/FogDevice.h>

#include <cmath>
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
	BiasStats stats;  //!< 100 s figures of the powered samples (table rate removed; drive: FOG - FOG_IDEAL)
	double coil_transient_C = NAN;  //!< drive only
};

/** Simulates the chamber run up to max_time_s (infinity: the profile's end) into `path` (.rawlog,
 * .csv, .csv.gz; `extra_metadata` key/value pairs appended to the run's metadata) and returns the
 * summary. Throws std::invalid_argument when fewer than 2 samples result (nothing is written). */
SimRunSummary writeChamberStreamed(const std::string& path, const sim::ChamberProfile& profile,
								   const sim::FogDevice& device, const sim::SimSettings& settings, double max_time_s,
								   const std::vector<std::pair<std::string, std::string>>& extra_metadata);

/** The same for a single-axis vehicle drive into a .rawlog (FOG, FOG_IDEAL, ODOMETRY,
 * GROUND_TRUTH) or CSV (the FOG alone); max_time_s as fog-sim --duration-s. */
SimRunSummary writeDriveStreamed(const std::string& path, const sim::ChamberProfile& cabin, const sim::FogDevice& device,
								 const sim::SimSettings& settings, double max_time_s,
								 const std::vector<std::pair<std::string, std::string>>& extra_metadata);

}  // namespace mrpt_fog::app
