/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file Segments.h
 * Where a model fails: the labelled segments of a run and their ranking by residual energy
 * (what analyseDiscrepancy reports; how runs are segmented: docs/guide/model-gap.md). Public API.
 */

#include <cstddef>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
enum class SegmentType
{
	RampUp,
	RampDown,
	Soak,
	Step,
	PowerOn,
	RateTable,
	Field,
	PowerOff
};
/** "ramp_up", "ramp_down", "soak", "step", "power_on", "rate_table", "field", "power_off". */
const char* toString(SegmentType t);

/** Which way the temperature moves over a segment (a closed set). */
enum class TemperatureDirection : unsigned char
{
	Steady,  //!< |mean rate| below SegmentationOptions::moving_rate_Cpm
	Heating,
	Cooling
};
/** "steady", "heating", "cooling" (the spelling in fog-discrepancy's JSON). */
const char* toString(TemperatureDirection d);


struct Segment
{
	SegmentType type = SegmentType::Soak;
	std::size_t begin = 0, end = 0;  //!< sample range [begin, end)
	double t_start_s = 0, t_end_s = 0;
	double mean_temp_C = 0;
	double mean_rate_Cpm = 0;
	std::string band;  //!< e.g. "below -20 C"
	TemperatureDirection direction = TemperatureDirection::Steady;
	// filled by rankSegments
	double rms_dph = 0;  //!< residual RMS over its usable samples
	double energy_share = 0;  //!< its share of the residual energy
	double time_share = 0;  //!< its share of the usable samples
	std::size_t usable = 0;
	/** "cooling ramp below -20 C", "power-on transient between 0 and 20 C"... */
	std::string describe() const;
};


/** A group of segments of one kind (type + direction + band) and its residual share. */
struct SegmentGroup
{
	std::string description;  //!< e.g. "cooling ramps below -20 C"
	double rms_dph = 0, energy_share = 0, time_share = 0;
	std::size_t segments = 0;
};


struct SegmentRanking
{
	std::vector<Segment> ranked;  //!< by residual energy, largest first
	std::vector<SegmentGroup> groups;  //!< by RMS, largest first
	double run_rms_dph = 0;
	/** e.g. "The residual is largest during cooling ramps below -20 C (RMS 0.031 deg/h, 2.1 x
	 * the run's 0.015 deg/h; 18 % of the residual energy in 8 % of the time)." */
	std::string sentence;
};


}  // namespace mrpt_fog::discrepancy
