/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file SelectionResult.h
 * What the selection of missing effects returns (analyseDiscrepancy's DiscrepancyReport holds
 * it): the named effects with their alias groups, confidence and interval, every candidate's
 * test per round, the noise model, and the fits before/after. Public API.
 */

#include <Eigen/Dense>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace mrpt_fog::discrepancy
{
struct BaseDesign;  // the base model as a design (internal)
struct RunSignals;  // a run's derived signals (internal)

/** ARMA(p,1) noise model: e_k = sum_j phi_j e_{k-j} + a_k - theta a_{k-1}. */
struct ArNoiseModel
{
	std::vector<double> phi;
	double theta = 0.0;  //!< MA(1) coefficient in [0, 1)
	double innovation_sd = 0.0;
	int order() const { return static_cast<int>(phi.size()); }
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
	/** p-value of "the effect's columns are all zero" (Wald test, one degree of freedom per
	 * column) in the fit that set coefficient and interval. With one column p < 0.05 exactly when
	 * the 95 % interval excludes zero; with several it is the test of the effect (an interval on
	 * the RMS of its terms, which cannot be below zero, is not one). */
	double zero_p = 1.0;
	std::string coefficient_unit;
	std::string theta_name;
	double theta = 0.0;
	std::string theta_meaning;  //!< the value in words when the candidate says more ("play operator, half-width 2 C")
	double chi2 = 0.0, p_adjusted = 1.0, delta_bic = 0.0;
	// confirmation run
	/** false: not tested there; confirm_cannot_tell then says why when the run was given
	 * (nothing to excite the effect, or too little data to show it at the coefficient named):
	 * the effect stays named, as with a single run. */
	bool confirm_tested = false;
	std::string confirm_cannot_tell;
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


/** The physics of a candidate effect id, one sentence (the candidate library's description).
 * Throws std::invalid_argument for an unknown id. */
const std::string& candidateDescription(const std::string& id);

}  // namespace mrpt_fog::discrepancy
