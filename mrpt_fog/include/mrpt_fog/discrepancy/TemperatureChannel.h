/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file TemperatureChannel.h
 * What the simulator workflow (analyseSimulatorDiscrepancy, SimulatorGap.h) reports on the
 * temperature channel: the heat-source test and its confirmation, and the thermal fit (how
 * well the calibrated thermal network reproduces the thermistors, and what would fix it).
 * How they are computed: docs/guide/model-gap-simulator.md. Public API.
 */

#include <mrpt_fog/obs/FogSeries.h>

#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct HeatSourceOptions
{
	double alpha = 0.005;  //!< significance level after the Sidak correction over the grid
	std::vector<double> tau_grid_s = {120, 300, 600, 1200, 2400, 4800};
	int lrv_max_lag = 30;
};

struct ThermistorHeatResponse
{
	ThermistorInfo info;
	double amplitude_C = 0;  //!< residual at full power relative to unpowered [degC]
	double se_C = 0;  //!< its standard error (long-run corrected)
};


struct HeatSourceResult
{
	bool tested = false;
	std::string untestable_reason;  //!< e.g. "the run has no power change"
	bool named = false;  //!< significant, positive and same sign on all thermistors
	bool significant = false;  //!< the common-mode test alone
	bool same_sign = false;
	double tau_s = 0;
	double amplitude_C = 0, ci_low_C = 0, ci_high_C = 0;  //!< common mode, 95 %
	double chi2 = 0, p = 1, p_adjusted = 1, delta_bic = 0, confidence = 0;
	double lrv_factor = 1;
	std::vector<ThermistorHeatResponse> thermistors;
	std::string nearest;  //!< thermistor with the largest amplitude
	std::string sentence;  //!< one readable sentence
};


/** Confirmation of a heat source on another run with tau fixed (confirmHeatSource): p-value of
 * the common-mode amplitude (one test, no grid) and whether it has the same (positive) sign. */
struct HeatSourceConfirm
{
	bool tested = false;
	bool confirmed = false;
	double p = 1, amplitude_C = 0;
};

enum class ThermalFix
{
	None,  //!< the fit is good (below the threshold)
	Lag,
	HeatSource,
	MissingNode
};
const char* toString(ThermalFix f);


struct ThermalFitOptions
{
	double misfit_rms_C = 0.1;  //!< see the file comment
	double min_explained_share = 0.5;
};


struct ThermalFit
{
	double rms_C = 0;  //!< all finite readings
	std::vector<std::string> names;
	std::vector<double> rms_per_C;  //!< per run thermistor
	std::string worst_thermistor;
	double worst_rms_C = 0;
	std::string max_abs_thermistor;  //!< where the largest |residual| is
	double max_abs_C = 0, max_abs_time_s = 0;
	double threshold_C = 0.1;
	bool misfit = false;
	ThermalFix fix = ThermalFix::None;
	double lag_share = 0, lag_tau_s = 0;  //!< variance share explained by -tau dT/dt, and tau
	double power_share = 0, power_tau_s = 0;  //!< by the lagged power, and its tau
	std::string sentence;  //!< one readable paragraph
};


}  // namespace mrpt_fog::discrepancy
