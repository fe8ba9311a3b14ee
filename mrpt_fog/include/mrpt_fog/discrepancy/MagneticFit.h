/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file MagneticFit.h
 * The magnetic (Faraday) sensitivity of a calibration (MagneticModel.h) fitted on runs with an
 * applied axial field: the residual of the calibration through the compensator (gyro rate -
 * compensated bias, the calibration's own terms and scale factor applied) over the powered
 * samples with a finite field and no table rate, regressed by generalised least squares on
 * field_uT and a slow drift per run, piecewise linear in time with knots every shortest stretch
 * of constant field (what is left of the thermal model's error and the bias wander: a field
 * segment that runs during a thermal transient would otherwise put the slow residual across the
 * segments into the coefficient). Noise ARMA(1,1) by REML on [1, field_uT], whitened fit
 * (lags never cross a run), standard error times the Bartlett long-run variance factor of the
 * whitened residual. Used by fog-discrepancy --write-cal (CalibrationAugment.h) and
 * fog-calibrate --magnetic.
 */

#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationRecipe.h>
#include <mrpt_fog/model/MagneticModel.h>

#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** The runs cannot support the fit; what() says why (no field column, a constant field, a field
 * that cannot be told apart from the drift). */
class MagneticFitError : public std::invalid_argument
{
   public:
	using std::invalid_argument::invalid_argument;
};

/** At most this many drift knots over all runs (else one level per run: a field that changes
 * too often for a drift slower than its stretches to be told apart). */
constexpr std::size_t kMaxMagneticDriftKnots = 100;

/** True when some run has a field column whose value changes over its powered samples. */
bool hasFieldVariation(const std::vector<FogSeries>& runs);

/** Fits the sensitivity (see the file comment) of `cal` (its magnetic section, if any, ignored)
 * on `runs` (each with the calibration's layout). Throws MagneticFitError when the runs cannot
 * support it, std::invalid_argument on a layout mismatch (from the compensator). */
MagneticModel fitMagneticSensitivity(const Calibration& cal, const std::vector<FogSeries>& runs);

/** fitMagneticSensitivity() as the calibration recipe's fitter (CalibrationRecipe.h,
 * CalibrateOptions::magnetic_fit): nothing, with the reason, when no run's field changes over its
 * powered samples or the runs cannot support the fit. */
MagneticFitter magneticFitter();

}  // namespace mrpt_fog::discrepancy
