/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SimulatorCalibration.h
 * Calibrates the simulator's free parameters (SimulatorConfig.h) to one measured run, in two
 * stages, because the temperatures drive the bias but not the other way round:
 *  1. temperature channel: thermal_time_scale and electronics_power_W by damped Gauss-Newton
 *     (finite-difference Jacobian through the full simulator) on the thermistor residuals, the
 *     thermistor offsets (when free) solved inside each evaluation as each thermistor's mean
 *     residual (variable projection); all samples with a finite reading count (powered or not);
 *  2. bias channel: every free bias parameter by damped Gauss-Newton on the bias residual over
 *     `bias_rows` (linear coefficients converge in one step; the winding asymmetry enters the
 *     Shupe weights nonlinearly).
 * Both damp by halving the step (from 1 down to 1/512) until the residual falls; a step that
 * takes a parameter outside the simulator's valid domain (it throws std::invalid_argument, e.g.
 * a midpoint offset beyond +-L/2) is halved the same way instead of ending the calibration.
 * The result holds the bias Jacobian at the optimum: the linearised calibrated model, which the
 * bias-channel selector (EffectSelector) uses as its base design.
 * 95 % intervals of the calibrated parameters: +-1.96 sqrt(diag(s2_LR (J^T J)^-1)), J the
 * Jacobian at the optimum (bias: bias_jacobian; temperatures: the stacked thermistor residual
 * with the offsets projected out), s2_LR the long-run residual variance by block averaging
 * (batch means over blocks of round(sqrt(m)) consecutive samples, per thermistor for the
 * temperatures), which covers autocorrelated noise and unmodelled structure alike. Approximate:
 * linearised, and the sandwich is reduced to s2_LR (J^T J)^-1 (columns slow against a block).
 */

#include <mrpt_fog/discrepancy/SimulatedRun.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct SimCalibration
{
	SimModel model;  //!< calibrated
	std::vector<ParamSlot> temp_slots, bias_slots;
	SimTrace trace;  //!< at the calibrated model
	/** n x bias_slots: d(simulated bias)/d(parameter) at the optimum (0 off bias_rows). */
	Eigen::MatrixXd bias_jacobian;
	double bias_rms_dph = 0;  //!< over bias_rows
	double temp_rms_C = 0;  //!< over every thermistor and finite sample
	/** 95 % half-widths, aligned with temp_slots / bias_slots (NaN: not estimable). */
	std::vector<double> temp_ci95_half, bias_ci95_half;
	int simulations = 0;  //!< simulator runs used
};

/** Bias residual measured - simulated [deg/h] (0 where rows is 0 or the simulation is NaN). */
Eigen::VectorXd biasResidual(const std::vector<double>& measured_bias_dph, const SimTrace& tr,
							 const std::vector<unsigned char>& rows);

/** Temperature residual measured - simulated per run thermistor [degC] (NaN where unknown). */
std::vector<std::vector<double>> temperatureResidual(const FogSeries& run, const SimTrace& tr);

/** RMS over every finite entry. */
double rmsOfFinite(const std::vector<std::vector<double>>& r);

/** Calibrates `start`'s free parameters (ids; see SimulatorConfig.h) on a run. */
SimCalibration calibrateSimulator(const SimModel& start, const std::vector<std::string>& free, const FogSeries& run,
								  const ChamberDrive& drive, const std::vector<double>& measured_bias_dph,
								  const std::vector<unsigned char>& bias_rows);

/** For a drive from the measured log (air reconstructed, ChamberReconstruction.h): the thermal
 * parameters by variable projection, since a free air absorbs what a fixed-air calibration of
 * the network would see (a wrong time scale becomes a different air). For each trial value the
 * air is reconstructed through that network (on knots 3x coarser, the regularisation weight
 * chosen once by GCV at the start) and the
 * thermistor residual, each thermistor's mean removed, is minimised: golden-section search on
 * log(thermal_time_scale) in [0.2, 5], then on electronics_power_W in [0.2, 3] x its start when
 * free and heat_source is on; two sweeps of 12 golden-section steps each. Parameters not free are left alone. Returns the model
 * and the drive reconstructed through it (with uncertainty). */
struct ProjectedThermal
{
	SimModel model;
	ChamberDrive drive;
	double temp_rms_C = 0;  //!< thermistor residual RMS (offsets removed) at the optimum
	int simulations = 0;
};
ProjectedThermal projectThermalOnLogDrive(const SimModel& start, const std::vector<std::string>& free,
										  const ChamberDrive& drive, const FogSeries& run);

/** Only the constant bias re-estimated (the confirmation run: turn-on bias repeatability). */
SimCalibration applyCalibration(const SimModel& calibrated, const std::vector<std::string>& free, const FogSeries& run,
								const ChamberDrive& drive, const std::vector<double>& measured_bias_dph,
								const std::vector<unsigned char>& bias_rows);

}  // namespace mrpt_fog::discrepancy
