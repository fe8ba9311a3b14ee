/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimulatorGap.h
 * The model-gap workflow when the model under test is a simulator configuration
 * (`fog-discrepancy --sim SIM.yaml`):
 *  1. drive the simulator with the run's chamber conditions (SimulatedRun.h) and calibrate its
 *     free parameters to the run (SimulatorCalibration.h): residuals of the bias and of every
 *     thermistor;
 *  2. temperature channel first (a wrong simulated temperature propagates into the simulated
 *     bias): test the thermistor residual for `heat_source` (HeatSourceCandidate.h) when the
 *     configuration has it off; if named, switch it on (electronics_power_W free) and recalibrate;
 *  2b. thermal fit (ThermalFit.h): thermistor residual RMS per thermistor and where it is largest;
 *     above the misfit threshold the thermal model is reported as the first disagreement (with
 *     what would fix it) and the bias channel is not searched: nothing is named on top of it;
 *  3. bias channel, simulator in the loop: the existing selector (EffectSelector.h) on the
 *     bias residual, with the calibrated simulator linearised (its Jacobian in the free bias
 *     parameters, plus a table-rate nuisance column when the run has a rate table) as the base
 *     design; candidates = the bias-channel library ids whose simulator effect is off
 *     (thermistor_lag excluded: in the simulator it is a sensor lag, seen in the temperatures).
 *     The strongest named effect is switched on IN THE SIMULATOR (its coefficient free; warm-up
 *     tau from the profile search), the simulator recalibrated and the selector asked again,
 *     until nothing is significant or max_effects effects are named;
 *  4. show the gap before/after (the configuration as given vs the one with every named effect
 *     on, both calibrated): bias residual (RMS, 100 s stability, range, per
 *     segment) and thermistor residual RMS, on the run and on the confirmation run (parameters
 *     from the first run, only the constant bias re-estimated).
 * Returns data only; fog-discrepancy shows it (report/SimDiscrepancyOutput.h).
 */

#include <mrpt_fog/discrepancy/DiscrepancyAnalysis.h>
#include <mrpt_fog/discrepancy/SimulatorConfig.h>
#include <mrpt_fog/discrepancy/TemperatureChannel.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct SimDiscrepancyOptions
{
	DiscrepancyOptions base;
	HeatSourceOptions heat;
	ThermalFitOptions thermal;
};

/** Thermistor residual RMS before/after [degC]. */
struct TemperatureGap
{
	std::string label;
	double rms_before_C = 0, rms_after_C = 0;
	std::vector<std::string> names;
	std::vector<double> rms_before_per_C, rms_after_per_C;
};

struct SimDiscrepancyReport
{
	DiscrepancyReport report;  //!< named_effects (heat_source first when named), segments, gap...
	std::string config_source;
	std::string drive, drive_confirm;  //!< how the driving input was obtained
	/** Reconstructed air (drive from the measured log; ci < 0: not reconstructed). */
	std::size_t drive_air_knots = 0;
	double drive_air_fit_rms_C = 0, drive_air_ci95_mean_C = -1, drive_air_ci95_max_C = -1;
	/** Drive from the measured log: share of the first-round bias residual energy explained by the
	 * thermal content the reconstructed air does not resolve (the thermistors' measured-minus-
	 * simulated rates and Tin - Tout, SimulatorGap.cpp); the bias candidates are tested with it
	 * taken out. < 0: not computed (drive from a profile, or the thermal fit failed). */
	double unresolved_share = -1;
	std::vector<std::string> effects_before, effects_after;
	std::vector<std::string> free_before, free_after;
	std::vector<std::pair<std::string, double>> calibrated_before, calibrated_after;
	/** 95 % half-widths of the calibrated parameters (SimulatorCalibration.h; thermistor
	 * offsets have none), keyed like calibrated_before / calibrated_after. */
	std::vector<std::pair<std::string, double>> calibrated_before_ci95_half, calibrated_after_ci95_half;
	HeatSourceResult heat;
	HeatSourceConfirm heat_confirm;
	ThermalFit thermal;  //!< the thermal fit after the temperature channel (step 2b)
	TemperatureGap temp_gap, temp_gap_confirm;
	int simulations = 0;
};

/** Runs the workflow on runs[0] (runs[1], optional, confirms). Throws std::invalid_argument on
 * bad input (no profile for a run, layouts differ, thermistor absent from the device...). */
SimDiscrepancyReport analyseSimulatorDiscrepancy(const std::vector<FogSeries>& runs,
												 const std::vector<std::string>& run_labels,
												 const SimulatorConfig& config, const SimDiscrepancyOptions& opt = {});

}  // namespace mrpt_fog::discrepancy
