/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file CandidateEffect.h
 * The library of physical effects a model may be missing, each with a stable id, a physical
 * description, what excites it (the test profile that separates it from look-alikes) and the
 * regressor columns it adds to a bias model, built from RunSignals. Time constants (warm-up)
 * are nonlinear parameters found by profile search over `theta_grid`.
 *
 * One candidate per effect of the simulator's registry (sim/EffectRegistry.h) that a residual
 * identifies, with the registry's id and order: shupe_rate, radial_gradient, gradient_rate,
 * thermistor_lag, hysteresis, warmup, scale_factor_temp, magnetic, temp_poly_order (bias
 * channel) and heat_source (temperature channel, see ThermalResidualModel.h). An effect
 * without a hand-written candidate gets the one its simulator term per coefficient gives
 * (candidateFromTerm).
 */

#include <mrpt_fog/discrepancy/RunSignals.h>
#include <mrpt_fog/sim/EffectRegistry.h>

#include <Eigen/Dense>
#include <cmath>
#include <utility>
#include <functional>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** What a candidate needs from the current model to build its columns. */
struct CandidateContext
{
	const RunSignals* sig = nullptr;
	/** The static-temperature part of the fitted base model along the run [deg/h]
	 * (thermistor_lag differentiates it). */
	std::vector<double> base_static_dph;
	int base_static_order = 3;  //!< highest power of the base's static polynomial
	/** Temperature the base's static polynomial uses (mean when "mean"). */
	std::vector<double> static_temp_C;
};

enum class ResidualChannel
{
	Bias,
	Temperature
};

struct CandidateEffect
{
	std::string id;
	std::string description;  //!< the physics, one sentence
	std::string excited_by;  //!< which test profile segments excite/separate it
	std::string coefficient_unit;  //!< unit of the reported coefficient
	ResidualChannel channel = ResidualChannel::Bias;
	std::string theta_name;  //!< nonlinear parameter name ("" = none)
	std::vector<double> theta_grid;  //!< profile-search grid ({0} when none)
	/** The parameter is continuous: after the grid, the profile search refines it between the
	 * best grid value's neighbours of the same sign (golden section on log |theta|). The grid
	 * values must then be of one or two signs, each sign one shape family. */
	bool theta_continuous = false;
	/** With theta_continuous: the shape family of a grid value (refinement stays within one
	 * family); unset: the sign of theta. */
	std::function<int(double theta)> theta_family;
	/** Columns (n x q) for a nonlinear parameter value. */
	std::function<Eigen::MatrixXd(const CandidateContext&, double theta)> build;
	/** Reported coefficient = scale * fitted coefficient of the first column. Multi-column
	 * candidates (q > 1) report the RMS of their fitted contribution in deg/h instead. */
	double coefficient_scale = 1.0;
	/** Empty when testable on this run, else why not (e.g. "no table-rate segments"). */
	std::function<std::string(const RunSignals&)> untestable_reason;
	/** What a value of the nonlinear parameter means, in words (unset: "theta_name = value"). */
	std::function<std::string(double theta)> describe_theta;
};

/** The candidate an effect's simulator term per coefficient gives (EffectDescriptor::
 * bias_per_coefficient): one column, the term per coefficient on each sample of the run (time
 * since the last power-on at or before it, +inf before the first; the electronics temperature
 * is not measured: NaN, and a non-finite value counts as 0); its description, data and unit
 * are the descriptor's; untestable when the column is zero on every usable sample. Throws
 * std::invalid_argument when the effect has no such term. */
CandidateEffect candidateFromTerm(const sim::EffectDescriptor& effect);

/** The candidate library, in the registry's order. */
const std::vector<CandidateEffect>& candidateLibrary();

/** Candidate by id; throws std::invalid_argument for an unknown id. */
const CandidateEffect& candidateById(const std::string& id);

/** A smoothed sign of the temperature rate, tanh(rate / 0.05 C/min) (the former hysteresis
 * column; kept for callers that want the instantaneous heating/cooling sign). */
double heatingCoolingSign(double dtemp_dt_Cpm);

/** Hysteresis regressor (play-type, the form of the simulator's hysteresis): the branch state
 * h in [-1, 1], h <- s + (h - s) exp(-|dT| / span_C) with s = sign(dT), dT the change of the
 * smoothed coil temperature (RunSignals::temp_coil_C) over each sample (raw change across gaps and power-off);
 * it keeps its value through soaks. h = 0 at the run start. Throws for span_C <= 0. */
std::vector<double> hysteresisBranch(const RunSignals& sig, double span_C);

/** Hysteresis regressor of the play (backlash) type, the elementary operator of a
 * Prandtl-Ishlinskii model (adhesive and jacket stress in a wound coil sticks until the
 * temperature has moved by the half-width w): with x the coil temperature's change since the run
 * start (the per-sample changes of hysteresisBranch), p <- min(max(p, x - w), x + w) and
 * h = (x - p) / w in [-1, 1], linear in the temperature after a reversal until it saturates,
 * constant through soaks; h = 0 at the run start. Throws for half_width_C <= 0. */
std::vector<double> hysteresisPlay(const RunSignals& sig, double half_width_C);

/** Moving threshold of the coil temperature [C/min]: below it a run is at a soak (heating /
 * cooling coverage, the dead band of the rate-sign hysteresis shape). */
inline constexpr double kMovingRate_Cpm = 0.05;

/** Rate-dependent saturation (no memory): h = tanh(dTc/dt / width_Cpm), dTc/dt the smoothed coil
 * temperature rate (RunSignals::dtemp_coil_dt_Cpm, a non-finite rate counts as 0): an offset of
 * opposite sign while heating and while cooling that returns to 0 at soaks and saturates once the
 * rate is well above the width. Throws for width_Cpm <= 0. */
std::vector<double> hysteresisRateSaturation(const RunSignals& sig, double width_Cpm);

/** The sign of the coil temperature rate outside a dead band: +1 at dTc/dt >= dead_band_Cpm, -1 at
 * <= -dead_band_Cpm, 0 between (soaks). Throws for dead_band_Cpm <= 0. */
std::vector<double> hysteresisRateSign(const RunSignals& sig, double dead_band_Cpm);

/** The hysteresis candidate's family of shapes, carried by its one nonlinear parameter theta.
 * Encoding (the only place that knows it): exponential branch of span w C: theta = w; play of
 * half-width w C: theta = -w (0 < w < kHysteresisMaxWidth_C); rate saturation of width r C/min:
 * theta = kHysteresisRateThetaPerCpm r; rate sign with dead band r C/min: theta =
 * -kHysteresisRateThetaPerCpm r (r >= kHysteresisMinRateWidth_Cpm). The memory shapes (branch,
 * play) keep their value through soaks; the rate shapes return to 0 there. */
struct HysteresisShape
{
	enum class Kind
	{
		ExponentialBranch,
		Play,
		RateSaturation,
		RateSign
	};
	Kind kind = Kind::ExponentialBranch;
	/** span (branch) or half-width (play) [degC]; width or dead band (rate shapes) [degC/min] */
	double width = 1.0;
	bool ratesOnly() const { return kind == Kind::RateSaturation || kind == Kind::RateSign; }
};
inline constexpr double kHysteresisMaxWidth_C = 100.0;  //!< widest branch span / play half-width
inline constexpr double kHysteresisRateThetaPerCpm = 1.0e4;  //!< theta per C/min of a rate shape
inline constexpr double kHysteresisMinRateWidth_Cpm = kHysteresisMaxWidth_C / kHysteresisRateThetaPerCpm;
HysteresisShape hysteresisShapeOf(double theta);  //!< throws for theta 0 or not finite
double hysteresisTheta(HysteresisShape shape);  //!< throws for a width out of its kind's range
/** The column of the shape theta says (hysteresisBranch, hysteresisPlay,
 * hysteresisRateSaturation or hysteresisRateSign). */
std::vector<double> hysteresisColumn(const RunSignals& sig, double theta);
/** The grid searched: branch and play at widths 0.5, 1, 2, 5, 10, 20 C, rate saturation at widths
 * 0.02, 0.05, 0.1, 0.2, 0.5, 1 C/min (1-2-5 series), rate sign at the dead band kMovingRate_Cpm;
 * the data choose shape and width by the profile search of EffectSelector (continuous within a
 * shape: hysteresisFamily). */
std::vector<double> hysteresisThetaGrid();
/** The shape family of a theta (its Kind as an int): the profile search refines the width only
 * between grid values of the same family. */
int hysteresisFamily(double theta);
/** "play operator, half-width 2 C" / "exponential branch, span 5 C" / "rate saturation,
 * tanh(dT/dt / 0.2 C/min)" / "sign of the rate (dead band 0.05 C/min)". */
std::string describeHysteresisTheta(double theta);

/** Where a run heats and where it cools (usable samples, |d(mean T)/dt| >= moving_rate_Cpm). */
struct HeatingCoolingCoverage
{
	double heating_s = 0, cooling_s = 0;  //!< time spent heating / cooling [s]
	std::pair<double, double> heating_C{NAN, NAN}, cooling_C{NAN, NAN};  //!< temperature ranges [degC]
	double shared_span_C = 0;  //!< overlap of the two ranges [degC] (0 when one is missing)
};
HeatingCoolingCoverage heatingCoolingCoverage(const RunSignals& sig, double moving_rate_Cpm = kMovingRate_Cpm);

/** Why hysteresis cannot be identified on this run ("" when it can): it needs >= 600 s of both
 * heating and cooling over a shared temperature range of >= 1 C (a monotonic run, or heating and
 * cooling in disjoint bands, cannot tell a hysteresis from a static temperature term). The same
 * condition holds for every shape of the family. */
std::string hysteresisUntestableReason(const RunSignals& sig);

/** The advice (test profile) that would separate two candidates. */
std::string separationAdvice(const std::string& id_a, const std::string& id_b);

}  // namespace mrpt_fog::discrepancy
