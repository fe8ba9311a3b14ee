/* mrpt_fog_heading: the heading pipeline of a vehicle with a FOG. */
#pragma once

/** \file PowerSpans.h
 * Stretches of a drive with the gyro off (the FOG's `power` column 0) and the powered spans
 * between them, for the evaluations of a whole drive against a truth (fog-drift, fog-localize).
 *
 * While the gyro is off there is no rate to integrate: what the vehicle turned then cannot be
 * known from the gyro. The evaluations therefore navigate each powered span as a drive of its
 * own, re-aligned from the truth at its start (the turn-on); HeadingPipeline.h, without a truth,
 * takes the wheels' heading change instead. The rule for a sample is obs/GyroPower.h's. */

#include <cstddef>
#include <limits>
#include <optional>
#include <utility>
#include <vector>

namespace mrpt_fog::heading
{
/** A stretch with the gyro off [absolute s]: from the last powered sample before it (or the
 * log's first sample when the log starts off) to the turn-on sample (or the log's last
 * sample when it ends off). */
struct GyroOffStretch
{
	double off_s = 0, on_s = 0;
	bool from_start = false;  //!< the log starts with the gyro off
	bool to_end = false;  //!< the log ends with the gyro off (no turn-on)
	std::size_t samples = 0;  //!< FOG samples with power 0 in it
	/** unwrapped truth heading change from off_s to on_s [deg]; NaN when the truth does not
	 * cover both ends */
	double truth_heading_change_deg = std::numeric_limits<double>::quiet_NaN();
	double duration_s() const { return on_s - off_s; }
};

/** A run of consecutive powered FOG samples [absolute s]. */
struct PoweredSpan
{
	double t0_s = 0, t1_s = 0;
	std::size_t samples = 0;
};

/** The gyro-off stretches and powered spans of a FOG stream, sample by sample, by the rule of
 * obs/GyroPower.h: a sample is off when its power is 0, and the first powered sample after off
 * ones is the turn-on (power 1 right after power 0). */
class PowerSpanBuilder
{
   public:
	/** power: the sample's power value (0 or 1; NaN when the log has no power column). */
	void add(double t_s, double power);
	/** Closes the last span or stretch. */
	void finish();
	const std::vector<PoweredSpan>& powered() const { return powered_; }
	std::vector<GyroOffStretch>& stretches() { return off_; }
	const std::vector<GyroOffStretch>& stretches() const { return off_; }

   private:
	std::vector<PoweredSpan> powered_;
	std::vector<GyroOffStretch> off_;
	bool any_ = false, on_ = false, finished_ = false;
	double last_t_ = 0;
};

/** The time window a gyro variant is navigated over within a powered span: the span clipped
 * to the variant's, the odometry's and the truth's time ranges; nullopt when empty. */
std::optional<std::pair<double, double>> navigationWindow(const PoweredSpan& span, double gyro_first_s,
														  double gyro_last_s, double odo_first_s, double odo_last_s,
														  double truth_first_s, double truth_last_s);

}  // namespace mrpt_fog::heading
