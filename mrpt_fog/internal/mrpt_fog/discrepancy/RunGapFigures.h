/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file RunGapFigures.h
 * The gap figures of DiscrepancyReport (DiscrepancyAnalysis.h) from residuals: of one run, and
 * per segment (used by analyseDiscrepancy and by the simulator path, SimulatorGap.cpp).
 */

#include <mrpt_fog/discrepancy/DiscrepancyAnalysis.h>
#include <mrpt_fog/discrepancy/RunSegmenter.h>
#include <mrpt_fog/discrepancy/RunSignals.h>

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Residual figures of one run over rows. */
GapFigures gapFigures(const std::vector<double>& time_s, const Eigen::VectorXd& residual_dph,
					  const std::vector<unsigned char>& rows, double tau_s);

/** Gap figures of one run from two residuals (before / after) over rows, segments ranked by the
 * energy before (what analyseDiscrepancy reports; also used by the simulator path). */
RunGap runGapFromResiduals(const std::string& label, const RunSignals& sig, const std::vector<Segment>& segments,
						   const Eigen::VectorXd& before_dph, const Eigen::VectorXd& after_dph,
						   const std::vector<unsigned char>& rows, const DiscrepancyOptions& opt = {});

}  // namespace mrpt_fog::discrepancy
