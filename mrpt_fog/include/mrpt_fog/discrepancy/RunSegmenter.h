/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RunSegmenter.h
 * Where a model fails: every sample of a run is labelled, from the data itself, by segment
 * type, temperature band and heating vs cooling, and the segments are ranked by the energy of
 * a residual, with a sentence such as "largest during cooling ramps below -20 C".
 *
 * Labels, by priority: power-off (power < 0.5), power-on transient (the first
 * `power_on_transient_s` after a power-on; only when the run has a power column), rate-table
 * (|table rate| > threshold), field (|field| > threshold), then from the mean thermistor
 * temperature rate: soak (|dT/dt| < `moving_rate_Cpm`), or a moving stretch of one sign that is
 * a ramp when it holds its rate (|rate| >= 0.8 x its peak without a break for at least `ramp_plateau_s`
 * and 30 % of the stretch, the coil's settling tail included) and a
 * step otherwise (the rate decays right after the peak; half-cycles of a sine sweep come out
 * as steps or ramps by the same rule). Segments are also cut where the mean temperature
 * crosses a band edge (bands: below -20, -20..0, 0..20, 20..40, above 40 C). Stretches shorter
 * than `min_segment_s` are merged into the previous segment.
 */

#include <mrpt_fog/discrepancy/RunSignals.h>

#include <Eigen/Dense>
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

struct SegmentationOptions
{
	double moving_rate_Cpm = 0.05;
	double ramp_plateau_s = 600.0;  //!< a ramp holds >= 0.8 x its peak rate this long
	double power_on_transient_s = 1800.0;
	double table_threshold_dph = 1.0;
	double field_threshold_uT = 1.0;
	double min_segment_s = 180.0;
};

struct Segment
{
	SegmentType type = SegmentType::Soak;
	std::size_t begin = 0, end = 0;  //!< sample range [begin, end)
	double t_start_s = 0, t_end_s = 0;
	double mean_temp_C = 0;
	double mean_rate_Cpm = 0;
	std::string band;  //!< e.g. "below -20 C"
	std::string direction;  //!< "heating", "cooling" or "steady"
	// filled by rankSegments
	double rms_dph = 0;  //!< residual RMS over its usable samples
	double energy_share = 0;  //!< its share of the residual energy
	double time_share = 0;  //!< its share of the usable samples
	std::size_t usable = 0;
	/** "cooling ramp below -20 C", "power-on transient between 0 and 20 C"... */
	std::string describe() const;
};

/** Segments in time order covering every sample. */
std::vector<Segment> segmentRun(const RunSignals& sig, const SegmentationOptions& opt = {});

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

/** Ranks segments by the energy of `residual_dph` over the samples where rows is 1. Groups
 * holding less than 2 % of the time are listed but never named in the sentence. */
SegmentRanking rankSegments(const std::vector<Segment>& segments, const Eigen::VectorXd& residual_dph,
							const std::vector<unsigned char>& rows);

}  // namespace mrpt_fog::discrepancy
