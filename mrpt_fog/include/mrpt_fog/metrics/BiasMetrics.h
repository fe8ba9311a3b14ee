/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file BiasMetrics.h
 * The seed paper's figures of merit for a gyro bias record:
 *  - bias stability = standard deviation of non-overlapping tau-second averages (tau = 100 s in
 *    the seed; cf. IEEE Std 952-1997, "bias stability" as the spread of averaged bias);
 *  - full-temperature range = max - min of the same tau-second averages;
 *  - raw peak-to-peak = max - min of the unaveraged samples (labelled separately: it is
 *    dominated by sample noise and is NOT the seed's "range").
 *
 * Windows are defined in TIME, not in sample counts, so irregular sampling and gaps are handled:
 * window k covers [t0 + k tau, t0 + (k+1) tau), t0 = first timestamp; its average is the plain
 * mean of the finite samples inside it (NaN samples are skipped). A window without any finite
 * sample (a gap) is skipped and counted in empty_window_count. The run is taken to cover
 * [t0, t_last + dt), dt = median sample interval (each sample stands for one interval), and the
 * incomplete last window (the tail shorter than tau) is dropped: its length is dropped_tail_s.
 *
 * Standard deviation uses N-1 (Bessel's correction): the mean of the window averages is itself
 * estimated from the same averages, and it is what MATLAB's std() (used by the FOG literature
 * the seed follows) computes. With N windows the N-1 form is larger than the N form by
 * sqrt(N/(N-1)) (2.6 % for N = 20).
 *
 * A constant offset (e.g. the vertical Earth-rate component of a static gyro) changes mean_dph
 * only; stability, range and peak-to-peak measure spread and are unaffected.
 */

#include <cstddef>
#include <functional>
#include <vector>

namespace mrpt_fog
{
/** Bias figures of one rate record (all rates in deg/h). */
struct BiasStats
{
	double tau_s = 100.0;  //!< averaging time used [s]
	double stability_dph = 0.0;  //!< std (N-1) of the tau-s window averages [deg/h]
	double range_dph = 0.0;  //!< max - min of the tau-s window averages [deg/h]
	double raw_peak_to_peak_dph = 0.0;  //!< max - min of all finite raw samples [deg/h]
	double mean_dph = 0.0;  //!< mean of the window averages [deg/h]
	std::size_t window_count = 0;  //!< windows with at least one finite sample (N)
	std::size_t empty_window_count = 0;  //!< complete windows skipped: no finite sample (gaps)
	std::size_t samples_used = 0;  //!< finite samples inside the counted windows
	double dropped_tail_s = 0.0;  //!< length of the incomplete last window left out [s]
	std::vector<double> window_center_s;  //!< centre time of each counted window [s]
	std::vector<double> window_mean_dph;  //!< average of each counted window [deg/h]
};

/** Bias figures of a rate record from its non-overlapping tau_s window averages (see the file
 * comment). O(samples) whatever tau_s is (runs of empty windows are skipped in one step).
 * Throws std::invalid_argument when: sizes differ, tau_s <= 0 or not finite, a timestamp is not
 * finite or not strictly increasing (names the sample index), or fewer than 2 windows with data
 * fit in the run ("tau longer than the run"): stability needs at least 2 averages. */
BiasStats biasStats(const std::vector<double>& time_s, const std::vector<double>& rate_dph, double tau_s = 100.0);

/** A record read in passes (logs longer than memory): each call of a RecordPass calls
 * the visitor with (time [s], value) for every sample, in order, the same values each time. */
using RecordVisitor = std::function<void(double time_s, double value)>;
using RecordPass = std::function<void(const RecordVisitor&)>;

/** biasStats() of a record read in passes (four to seven passes; memory: the window averages and
 * 65 536 counters). The same numbers, bit for bit, as the vector form, which calls it. */
BiasStats biasStats(const RecordPass& pass, double tau_s = 100.0);

/** medianSampleInterval_s() of a record read in passes (five passes, exact). */
double medianSampleInterval_s(const RecordPass& pass);

/** Median of the positive sample intervals [s] (the nominal sampling period of an irregular
 * record). Throws std::invalid_argument with fewer than 2 samples. */
double medianSampleInterval_s(const std::vector<double>& time_s);

}  // namespace mrpt_fog
