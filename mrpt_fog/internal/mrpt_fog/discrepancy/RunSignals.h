/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RunSignals.h
 * The physical signals the model-gap workflow reasons with, derived once from a FogSeries:
 * the bias to explain (gyro rate minus the applied table rate, deg/h), the mean, inner and
 * outer coil temperatures (degC), their smoothed time derivatives (degC/min), the radial
 * gradient Tin - Tout, the applied rate and field, power-on instants, and which samples are
 * usable (gyro powered, temperatures known) split into contiguous blocks (a time gap larger
 * than 3 median sample periods starts a new block; derivatives never cross a block edge).
 *
 * Thermistor dropouts (NaN) are bridged by linear interpolation inside a block when shorter
 * than `max_dropout_bridge_s`; longer dropouts make those samples unusable.
 */

#include <mrpt_fog/discrepancy/DiscrepancyOptions.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <cstddef>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct RunSignals
{
	std::vector<double> time_s;
	std::vector<double> bias_dph;  //!< rate - table rate [deg/h]
	std::vector<double> temp_mean_C;  //!< mean of all thermistors
	/** Coil temperature: mean of the thermistors on the coil (inner or outer side), leaving out
	 * those on neither side (housing, electronics); = temp_mean_C when every thermistor is on
	 * the coil or none is. */
	std::vector<double> temp_coil_C;
	std::vector<double> dtemp_coil_dt_Cpm;  //!< d(temp_coil)/dt [degC/min]
	std::vector<double> temp_inner_C;  //!< mean of inner thermistors (= mean when none)
	std::vector<double> temp_outer_C;  //!< mean of outer thermistors (= mean when none)
	std::vector<double> gradient_C;  //!< Tin - Tout
	/** Tout - Tother: mean outer minus mean of the thermistors on neither side (housing,
	 * electronics); empty unless has_inner_outer and has_other. A surface thermistor reads a
	 * mixture of coil layers and its mount, so the radial gradient of the coil is a combination
	 * of Tin - Tout and this difference with weights the run must tell. */
	std::vector<double> outer_other_C;
	std::vector<double> dtemp_dt_Cpm;  //!< d(temp_mean)/dt [degC/min]
	std::vector<double> dgradient_dt_Cpm;  //!< d(Tin - Tout)/dt [degC/min]
	/** Per thermistor (interpolated) temperature and its derivative [degC], [degC/min]. */
	std::vector<std::vector<double>> thermistor_C;
	std::vector<std::vector<double>> dthermistor_dt_Cpm;
	std::vector<double> table_rate_dph;  //!< zeros when absent
	std::vector<double> field_uT;  //!< zeros when absent
	std::vector<double> power;  //!< ones when absent
	bool has_inner_outer = false;  //!< at least one inner and one outer thermistor
	bool has_other = false;  //!< at least one thermistor on neither side (CoilSide::Other)
	bool has_table = false;  //!< table_rate column present and varying
	bool has_field = false;  //!< field column present and varying
	bool has_power = false;  //!< power column present
	std::vector<double> power_on_s;  //!< power-on instants (run start counts when powered)
	std::vector<unsigned char> usable;  //!< 1 = sample enters fits
	std::vector<int> block;  //!< contiguous block index per sample (-1 when unusable)
	double dt_s = 1.0;  //!< median sample period

	std::size_t size() const { return time_s.size(); }
	std::size_t usableCount() const;
};

/** Derives the signals from a run. Throws std::invalid_argument when the run has fewer than
 * 20 samples, no thermistor, or fails FogSeries::validate(). */
RunSignals computeRunSignals(const FogSeries& run, const RunSignalsOptions& opt = {});

/** Slope of a local least-squares line over +-window/2 around each sample, per block, in
 * units of y per minute. Samples outside any block (block < 0) get 0. */
std::vector<double> localSlopePerMin(const std::vector<double>& time_s, const std::vector<double>& y,
									 const std::vector<int>& block, double window_s);

}  // namespace mrpt_fog::discrepancy
