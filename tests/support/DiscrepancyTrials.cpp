/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include "support/DiscrepancyTrials.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace mrpt_fog::discrepancy
{
namespace
{
/** "id{alias,alias};id..." of the named effects, or "none" (trial summaries). */
void writeNamedEffects(std::ostream& os, const std::vector<NamedEffect>& named)
{
	if (named.empty()) os << "none";
	for (std::size_t i = 0; i < named.size(); ++i)
	{
		os << (i ? ";" : "") << named[i].id;
		if (named[i].alias_group.size() > 1)
		{
			os << "{";
			for (std::size_t j = 1; j < named[i].alias_group.size(); ++j) os << (j > 1 ? "," : "") << named[i].alias_group[j];
			os << "}";
		}
	}
}

double rmsOn(const Eigen::VectorXd& r, const std::vector<unsigned char>& rows)
{
	double s = 0;
	std::size_t m = 0;
	for (std::size_t k = 0; k < rows.size(); ++k)
		if (rows[k])
		{
			s += r(static_cast<Eigen::Index>(k)) * r(static_cast<Eigen::Index>(k));
			++m;
		}
	return m ? std::sqrt(s / m) : 0.0;
}

bool inGroup(const NamedEffect& ne, const std::string& id, bool acceptAlias)
{
	if (ne.id == id) return true;
	return acceptAlias && std::find(ne.alias_group.begin(), ne.alias_group.end(), id) != ne.alias_group.end();
}
}  // namespace

TrialOutcome scoreTrial(const std::vector<std::string>& hidden, bool accept_alias, const SelectionResult& sel,
						const RunSignals& sig1, const BaseDesign& base1, const RunSignals& sig2, const BaseDesign& base2,
						const std::vector<std::vector<double>>& truth1, const std::vector<std::vector<double>>& truth2)
{
	TrialOutcome out;
	out.named = sel.named;
	if (hidden.empty())
	{
		out.false_naming = !sel.named.empty();
		out.named_ok = sel.named.empty();
		out.clean = out.named_ok;
	}
	else
	{
		bool ok = !sel.named.empty() && inGroup(sel.named[0], hidden[0], accept_alias);
		for (std::size_t i = 1; i < hidden.size() && ok; ++i)
		{
			bool found = false;
			for (std::size_t j = 1; j < sel.named.size(); ++j) found = found || inGroup(sel.named[j], hidden[i], accept_alias);
			// a weaker effect aliased with the first one counts when it is in the first group
			found = found || inGroup(sel.named[0], hidden[i], accept_alias);
			ok = found;
		}
		out.named_ok = ok;
		out.clean = ok && sel.named[0].id == hidden[0];
	}

	// gap on the confirmation run: coefficients from run 1, offset re-estimated
	const Eigen::MatrixXd X2after = sel.model.design(base2, sig2);
	const auto rBefore = residualWithCoefficients(base2.X, sig2, sel.coef_before);
	const auto rAfter = residualWithCoefficients(X2after, sig2, sel.coef_after);
	// oracle: base plus the true effect shapes as columns, fitted on run 1
	Eigen::MatrixXd O1 = base1.X, O2 = base2.X;
	for (std::size_t h = 0; h < truth1.size() && h < truth2.size(); ++h)
	{
		const auto& e1 = truth1[h];
		const auto& e2 = truth2[h];
		O1.conservativeResize(Eigen::NoChange, O1.cols() + 1);
		O2.conservativeResize(Eigen::NoChange, O2.cols() + 1);
		for (std::size_t k = 0; k < e1.size(); ++k) O1(static_cast<Eigen::Index>(k), O1.cols() - 1) = e1[k];
		for (std::size_t k = 0; k < e2.size(); ++k) O2(static_cast<Eigen::Index>(k), O2.cols() - 1) = e2[k];
	}
	std::vector<std::size_t> rows;
	for (std::size_t k = 0; k < sel.fit_rows.size(); ++k)
		if (sel.fit_rows[k]) rows.push_back(k);
	Eigen::MatrixXd O1r(rows.size(), O1.cols());
	Eigen::VectorXd y1(rows.size());
	for (std::size_t i = 0; i < rows.size(); ++i)
	{
		O1r.row(static_cast<Eigen::Index>(i)) = O1.row(static_cast<Eigen::Index>(rows[i]));
		y1(static_cast<Eigen::Index>(i)) = sig1.bias_dph[rows[i]];
	}
	const auto oracleFit = leastSquares(O1r, y1);
	const auto rOracle = residualWithCoefficients(O2, sig2, oracleFit.coef);
	out.rms_before_dph = rmsOn(rBefore, sig2.usable);
	out.rms_after_dph = rmsOn(rAfter, sig2.usable);
	out.rms_oracle_dph = rmsOn(rOracle, sig2.usable);
	out.gap_ok = hidden.empty() ||
				 (out.rms_before_dph - out.rms_after_dph) >= 0.5 * (out.rms_before_dph - out.rms_oracle_dph);

	std::ostringstream os;
	os << "named=";
	writeNamedEffects(os, sel.named);
	os << " rms2 before/after/oracle=" << out.rms_before_dph << "/" << out.rms_after_dph << "/" << out.rms_oracle_dph;
	out.summary = os.str();
	return out;
}

TrialOutcome runTrial(const TrialSpec& spec, const SelectionOptions& opt)
{
	SyntheticRunOptions g;
	g.profile = spec.profile;
	g.dt_s = spec.dt_s;
	g.thermistor_noise_C = spec.thermistor_noise_C;
	g.thermistor_quantum_C = spec.thermistor_quantum_C;
	for (std::size_t i = 0; i < spec.hidden.size(); ++i) g.hidden[spec.hidden[i]] = spec.ratios.at(i);
	SyntheticRunOptions g1 = g, g2 = g;
	g1.seed = 2 * spec.seed + 1;
	g1.gap = spec.gap;
	g1.outliers = spec.outliers;
	g2.seed = 2 * spec.seed + 2;
	g2.static_coef_error = spec.static_coef_error;
	const auto run1 = makeSyntheticChamberRun(g1);
	const auto run2 = makeSyntheticChamberRun(g2);

	const auto bspec = resolveBaseModel(spec.base_preset, run1.series);
	const auto sig1 = computeRunSignals(run1.series);
	const auto sig2 = computeRunSignals(run2.series);
	const auto base1 = buildBaseDesign(bspec, run1.series, sig1);
	const auto base2 = buildBaseDesign(bspec, run2.series, sig2);
	auto sel = selectMissingEffects(sig1, base1, opt);
	confirmOnRun(sel, sig2, base2, opt);
	keepConfirmedEffects(sel, sig1, base1);  // the verdict rule of analyseDiscrepancy

	std::vector<std::vector<double>> truth1, truth2;
	for (const auto& id : spec.hidden)
	{
		truth1.push_back(run1.effect_dph.at(id));
		truth2.push_back(run2.effect_dph.at(id));
	}
	TrialOutcome out = scoreTrial(spec.hidden, spec.accept_alias, sel, sig1, base1, sig2, base2, truth1, truth2);
	std::ostringstream os;
	os << "hidden=";
	for (std::size_t i = 0; i < spec.hidden.size(); ++i) os << (i ? "+" : "") << spec.hidden[i] << "@" << spec.ratios[i];
	if (spec.hidden.empty()) os << "none";
	os << " seed=" << spec.seed << " " << out.summary;
	out.summary = os.str();
	return out;
}

}  // namespace mrpt_fog::discrepancy
