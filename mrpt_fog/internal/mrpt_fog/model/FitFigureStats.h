/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/Calibration.h>

namespace mrpt_fog
{
/** The figures of a compensated record and its raw counterpart, both read in passes (time [s],
 * rate [deg/h]), into `f` (label left as it is): tau_s; samples and rms_dph over the finite
 * compensated values (RMS about their mean); stability and range of the tau-s averages of both
 * (biasStats) and valid = true, or, for a run shorter than 2 tau, those four NaN and valid =
 * false. With no finite compensated value only tau_s is set. The one definition behind
 * evaluateCalibration's figures and the discrepancy workflow's figures through the compensator. */
void fitFiguresOfPasses(FitFigures& f, const RecordPass& comp, const RecordPass& raw, double tau_s);
}  // namespace mrpt_fog
