/* fog-evaluate: bias figures of one rate record (raw or compensated). */
#pragma once

/** \file RateEvaluation.h
 * Everything fog-evaluate reports for one rate record: the seed's tau-s bias stability and
 * range (metrics/BiasMetrics.h) and the overlapping Allan deviation with its IEEE 952 noise
 * terms (metrics/AllanNoiseTerms.h), and their JSON form. */

#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/common/RowSpill.h>
#include <mrpt_fog/metrics/AllanDeviation.h>
#include <mrpt_fog/metrics/AllanNoiseTerms.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::evaluate
{
struct RateEvaluation
{
	BiasStats stats;
	std::vector<AllanPoint> allan;  //!< overlapping ADEV [deg/h], octave taus with >= 4 clusters
	AllanNoiseTerms terms;
	double allan_period_s = 0;  //!< sample period of the uniform resample used for the ADEV [s]
	std::size_t allan_samples = 0;  //!< samples in that resample (longest gap-free segment)
	std::size_t allan_segments = 0;  //!< gap-free segments found in the record
};

/** Figures of column `col` (the bias [deg/h]) of (time, bias...) rows, read in passes: the same
 * numbers as evaluateRate() on the columns, with memory independent of the record's length. */
RateEvaluation evaluateRate(const RowSpill& rows, std::size_t col, double tau_s);

/** The gyro bias of a series: primary-axis rate minus the applied table rate (when the log has
 * that column), NaN while the gyro is powered off (power column 0). [deg/h] */
std::vector<double> biasOf(const FogSeries& series, std::vector<double> rate_dph);

/** Figures of one record. Throws std::invalid_argument (from biasStats) when tau_s does not fit
 * the record twice; the Allan part is left empty (terms NaN) for records too short for it. */
RateEvaluation evaluateRate(const std::vector<double>& time_s, const std::vector<double>& bias_dph, double tau_s);

/** JSON object: stability_dph, range_dph, raw_peak_to_peak_dph, mean_dph, window_count,
 * empty_window_count, dropped_tail_s, arw_dpsh, bias_instability_dph, rrw_dphsh,
 * quantization_arcsec (null when not identified), allan_tau_s / allan_adev_dph arrays. */
JsonValue toJson(const RateEvaluation& e);

}  // namespace mrpt_fog::evaluate
