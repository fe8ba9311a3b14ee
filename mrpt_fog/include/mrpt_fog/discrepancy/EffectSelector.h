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
 *  4. per candidate: that chi-square, nonlinear parameters by profile search (Sidak-corrected
 *     over the grid), BIC gain vs the model, Holm correction over the candidates;
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
#include <mrpt_fog/discrepancy/WhitenedRegression.h>

#include <limits>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct SelectionOptions
{
	/** Family-wise significance level (Holm over candidates). 0.005, not 0.01: with the noise
	 * model estimated from the same run the null chi-squares come out ~1.1-1.2x nominal, and at
	 * 0.01 the false-naming rate on 200 null trials was 2.5 % (target <= 2 %). */
	double alpha = 0.005;
	double alias_alpha = 0.01;  //!< conditional-test level for "distinguishable"
	/** Shape reproduction (whitened, model projected out; see step 5) at or above which a
	 * candidate is an alias of the named one whatever the significance. */
	double alias_collinearity = 0.95;
	int max_effects = 3;
	int max_ar_order = 3;
	double span_tolerance = 1e-3;  //!< relative projection residual below which "spanned"
	double outlier_sigma = 6.0;
	int lrv_max_lag = 30;  //!< Bartlett window of the long-run variance factor [samples]
	/** Candidate ids to consider (empty = every bias-channel candidate). */
	std::vector<std::string> candidates;
};

/** One added effect term (id + nonlinear parameter). */
struct EffectTerm
{
	std::string id;
	double theta = 0.0;
};

/** Base model plus named effect terms: what "add the effect and refit" means. */
struct AugmentedModel
{
	std::vector<EffectTerm> effects;
	/** Base-column coefficients used to build the thermistor_lag column (size = base columns). */
	Eigen::VectorXd lag_base_coef;
	/** Full design on a run: base columns then each effect's columns. */
	Eigen::MatrixXd design(const BaseDesign& base, const RunSignals& sig) const;
};

/** Context for candidate columns given base-column coefficients. */
CandidateContext makeCandidateContext(const RunSignals& sig, const BaseDesign& base, const Eigen::VectorXd& base_coef);

/** What became of a candidate in a selection round. */
enum class CandidateStatus
{
	Tested,  //!< fitted and judged (chi2, p, BIC below)
	Spanned,  //!< its columns lie in the model's span: nothing to add
	Untestable  //!< the run lacks what excites it (note says what)
};
/** "tested", "spanned", "untestable" (the JSON / text spelling). */
const char* toString(CandidateStatus s);

/** Status of one candidate in one selection round. */
struct CandidateTest
{
	std::string id;
	CandidateStatus status = CandidateStatus::Tested;
	std::string note;  //!< why untestable / by what explained
	double theta = 0.0;
	double chi2 = 0.0;
	int dof = 0;
	double p = 1.0;
	double p_adjusted = 1.0;
	double delta_bic = 0.0;
	bool significant = false;
	double collinearity_with_best = 0.0;  //!< shape reproduction of the named one (this round)
	/** In the round where nothing more was named: the smallest contribution of this candidate
	 * (RMS beyond what the model explains, deg/h, in its most favourable direction) whose
	 * expected whitened chi-square reaches the naming threshold (Bonferroni level over the
	 * candidates and the theta grid, and the BIC term), under the model's fitted noise (AR +
	 * long-run factor). Below it the run cannot tell the effect from the noise. NaN elsewhere. */
	double detectable_rms_dph = std::numeric_limits<double>::quiet_NaN();
};

struct NamedEffect
{
	std::string id;
	std::vector<std::string> alias_group;  //!< the id first, then look-alikes
	/** Per alias_group member: its nonlinear parameter on the analysed run, and the sign of its
	 * coefficient there when it has one column (0 otherwise); for confirming the group. */
	std::vector<double> alias_theta;
	std::vector<int> alias_sign;
	std::vector<std::string> separating_profiles;  //!< one per look-alike
	double confidence = 0.0;  //!< BIC weight of this id
	double group_confidence = 0.0;  //!< BIC weight of the alias group
	double coefficient = 0.0;
	double ci_low = 0.0, ci_high = 0.0;  //!< 95 %
	std::string coefficient_unit;
	std::string theta_name;
	double theta = 0.0;
	double chi2 = 0.0, p_adjusted = 1.0, delta_bic = 0.0;
	// confirmation run
	bool confirm_tested = false;
	bool confirmed = false;
	double confirm_p = 1.0;
	double confirm_coefficient = 0.0;
	/** The group member that confirmed: the id itself, or a look-alike when the named id did
	 * not confirm but a member of its alias group did (the data cannot tell them apart, so the
	 * group is what is named); empty when not confirmed. */
	std::string confirmed_by;
};

struct SelectionResult
{
	std::vector<NamedEffect> named;
	/** Named on the analysed run but not confirmed on the confirmation run (keepConfirmedEffects):
	 * reported, not added to the model. */
	std::vector<NamedEffect> not_confirmed;
	std::vector<std::vector<CandidateTest>> rounds;
	AugmentedModel model;
	std::vector<unsigned char> fit_rows;  //!< usable and not an outlier
	std::size_t outliers = 0;
	ArNoiseModel ar;  //!< noise model of the first round
	/** Noise model of the model with every named effect (the last named effect's GLS fit); empty
	 * when nothing was named. What is left after the named effects is what may wander. */
	ArNoiseModel ar_after;
	double lrv_factor = 1.0;
	Eigen::VectorXd coef_before;  //!< base fit
	Eigen::VectorXd coef_after;  //!< augmented fit
	Eigen::VectorXd residual_before;  //!< all samples (meaningful where fit_rows)
	Eigen::VectorXd residual_after;
};

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
 * Why: on null trials every false naming seen was unconfirmed (docs/discrepancy.md). */
void keepConfirmedEffects(SelectionResult& result, const RunSignals& sig1, const BaseDesign& base1);

/** Least-squares coefficients of the run's bias on the design X, fitted on the rows where
 * `rows` is non-zero (a run's `usable` or a selection's `fit_rows`). */
Eigen::VectorXd coefficientsOnRows(const Eigen::MatrixXd& X, const RunSignals& sig, const std::vector<unsigned char>& rows);

/** Residuals on another run with coefficients fitted elsewhere, re-estimating only the
 * constant offset (turn-on to turn-on bias repeatability). Rows not usable give 0. */
Eigen::VectorXd residualWithCoefficients(const Eigen::MatrixXd& X, const RunSignals& sig, const Eigen::VectorXd& coef);

}  // namespace mrpt_fog::discrepancy
