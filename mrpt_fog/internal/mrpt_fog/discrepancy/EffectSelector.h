/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file EffectSelector.h
 * Names the physical effect(s) a bias model is missing, by greedy forward selection over the
 * candidate library (CandidateEffect.h), strongest first:
 *  1. fit the model, flag outliers (robust 6-sigma on the ARMA-whitened residual);
 *  2. skip candidates the model already spans (projection residual of their columns onto the
 *     model's columns below `span_tolerance` of their own spread);
 *  3. every model compared (current model, model + one candidate, model + two...) is fitted
 *     by feasible GLS with its OWN noise model: ARMA(1,1) (Gauss-Markov bias + white noise)
 *     estimated by REML for that design (WhitenedRegression.h), exact start of each block; a
 *     candidate is judged by the Wald chi-square of its columns under the noise model of the
 *     model that contains it, deflated by the Bartlett long-run variance factor of what the
 *     whitening left. (A single noise model for all candidates was tried: from the current
 *     model's residual it swallows localized effects such as warm-up, power 1/30 at ratio 1;
 *     from model + all candidates, null chi-squares were ~1.5x too big.)
 *  4. per candidate: that chi-square, nonlinear parameters by profile search on the residual
 *     sum of squares whitened by the current model's noise model (Sidak-corrected over the
 *     grid; an OLS profile let the slow bias wander choose the grid value: on the lumped-coil
 *     generator the hysteresis width went to the grid's widest play, chi-square 11, where the
 *     whitened profile picks the one giving 50), BIC gain vs the model, Holm correction over
 *     the candidates;
 *     significant = adjusted p < alpha and BIC gain > 0;
 *  5. the best significant candidate (largest BIC gain) is named; identifiability check: a
 *     candidate c joins its alias group when its columns reproduce the best's fitted shape on
 *     this run (correlation of that shape with its projection on c's columns, after whitening
 *     and projecting out the model, >= alias_collinearity; for a one-column best this is the
 *     canonical correlation), or when c is significant and the data cannot show the best is needed
 *     beyond c (conditional test p > alias_alpha); the profile that would separate them is
 *     reported. Candidates the best explains are dropped; the best's columns are added and the
 *     search repeats until nothing is significant.
 * Confidence = BIC weight of the named id against its alias group and "no effect" (shared
 * equally inside a group with collinear members, whose BIC differences are not evidence).
 */

#include <mrpt_fog/discrepancy/BaseModelDesign.h>
#include <mrpt_fog/discrepancy/CandidateEffect.h>
#include <mrpt_fog/discrepancy/DiscrepancyOptions.h>
#include <mrpt_fog/discrepancy/SelectionResult.h>
#include <mrpt_fog/discrepancy/WhitenedRegression.h>

#include <limits>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
/** Context for candidate columns given base-column coefficients. */
CandidateContext makeCandidateContext(const RunSignals& sig, const BaseDesign& base, const Eigen::VectorXd& base_coef);

/** Runs the selection on one run. Throws std::invalid_argument when fewer usable samples than
 * 10 x the number of base columns. */
SelectionResult selectMissingEffects(const RunSignals& sig, const BaseDesign& base, const SelectionOptions& opt = {});

/** Re-tests each named effect (in order, theta fixed) on a second run: refit there, whitened
 * chi-square test at alias_alpha with the same coefficient sign. When the named id does not
 * confirm, its alias group's other members are tested the same way (their own theta and sign
 * from the analysed run), each at alias_alpha / group size (Bonferroni share: the group gets
 * at most about twice the single test's chances on a null): the group is named, so any member
 * may confirm it (confirmed_by says which). Fills confirm_* fields. */
void confirmOnRun(SelectionResult& result, const RunSignals& sig2, const BaseDesign& base2,
				  const SelectionOptions& opt = {});

/** The verdict rule when a confirmation run is given: an effect named on the analysed run but
 * tested and NOT confirmed on the confirmation run (confirmOnRun) is moved to not_confirmed,
 * and the augmented model is refitted on the analysed run (sig1/base1) with the confirmed
 * effects only (coef_after, residual_after). Effects that could not be tested on the second run
 * (e.g. it has no rate-table segment) stay named. A one-run analysis has nothing to confirm.
 * Why: on null trials every false naming seen was unconfirmed (docs/guide/model-gap.md). */
void keepConfirmedEffects(SelectionResult& result, const RunSignals& sig1, const BaseDesign& base1);

/** Least-squares coefficients of the run's bias on the design X, fitted on the rows where
 * `rows` is non-zero (a run's `usable` or a selection's `fit_rows`). */
Eigen::VectorXd coefficientsOnRows(const Eigen::MatrixXd& X, const RunSignals& sig, const std::vector<unsigned char>& rows);

/** Residuals on another run with coefficients fitted elsewhere, re-estimating only the
 * constant offset (turn-on to turn-on bias repeatability). Rows not usable give 0. */
Eigen::VectorXd residualWithCoefficients(const Eigen::MatrixXd& X, const RunSignals& sig, const Eigen::VectorXd& coef);

}  // namespace mrpt_fog::discrepancy
