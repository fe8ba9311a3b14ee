/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/BaseModelDesign.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
std::vector<std::string> splitList(const std::string& text, char sep)
{
	std::vector<std::string> out;
	std::stringstream ss(text);
	std::string item;
	while (std::getline(ss, item, sep))
		if (!item.empty()) out.push_back(item);
	return out;
}

int parseOrder(const std::string& text, const std::string& preset)
{
	try
	{
		std::size_t used = 0;
		const int v = std::stoi(text, &used);
		if (used != text.size() || v < 1 || v > 9) throw std::invalid_argument("range");
		return v;
	}
	catch (const std::exception&)
	{
		throw std::invalid_argument("model preset '" + preset + "': bad order '" + text + "' (1..9 expected)");
	}
}
}  // namespace

BaseModelSpec parseBasePreset(const std::string& preset)
{
	BaseModelSpec s;
	s.preset = preset;
	const auto colon = preset.find(':');
	const std::string head = preset.substr(0, colon);
	const std::string arg = colon == std::string::npos ? "" : preset.substr(colon + 1);
	if (head == "static")
	{
		const auto parts = splitList(arg, ':');
		if (parts.empty()) throw std::invalid_argument("model preset '" + preset + "': static:P[:NAME] needs P");
		s.static_order = parseOrder(parts[0], preset);
		s.static_temps = {parts.size() > 1 ? parts[1] : "mean"};
	}
	else if (head == "M1" || head == "M2")
	{
		s.static_temps = {arg.empty() ? "mean" : arg};
		if (head == "M2") s.rate_temps = s.static_temps;
	}
	else if (head == "M3" || head == "M4")
	{
		const auto names = splitList(arg, ',');
		if (!names.empty() && names.size() != 2)
			throw std::invalid_argument("model preset '" + preset + "': expected " + head + ":IN,OUT");
		if (names.size() == 2)
		{
			s.diff_in = names[0];
			s.diff_out = names[1];
		}
		s.diff_order = 3;
		if (head == "M3")
		{
			s.static_temps = {"mean"};
			s.rate_temps = {"mean"};
		}
		else
			s.diff_rate_order = 3;
	}
	else if (head == "multipoint")
	{
		s.static_temps = arg.empty() ? std::vector<std::string>{"*"} : splitList(arg, ',');
		s.rate_temps = s.static_temps;
	}
	else if (head == "points")
	{
		const int k = parseOrder(arg, preset);
		s.static_temps = {"#" + std::to_string(k)};
		s.rate_temps = s.static_temps;
	}
	else
		throw std::invalid_argument("unknown model preset '" + preset +
									"' (expected static:P[:NAME], M1..M4[:...], multipoint[:...], points:K)");
	return s;
}

namespace
{
/** Expands "*" (all) and "#K" (first K) into thermistor names. */
std::vector<std::string> expandNames(const std::vector<std::string>& names, const FogSeries& run)
{
	std::vector<std::string> out;
	for (const auto& n : names)
	{
		if (n == "*")
			for (const auto& th : run.thermistors) out.push_back(th.name);
		else if (!n.empty() && n[0] == '#')
		{
			const std::size_t k = std::stoul(n.substr(1));
			if (k > run.thermistorCount())
				throw std::invalid_argument("preset asks for " + std::to_string(k) + " points; run has " +
											std::to_string(run.thermistorCount()) + " thermistors");
			for (std::size_t i = 0; i < k; ++i) out.push_back(run.thermistors[i].name);
		}
		else
			out.push_back(n);
	}
	return out;
}

const std::vector<double>& tempColumn(const std::string& name, const FogSeries& run, const RunSignals& sig,
									  bool rate)
{
	if (name == "mean") return rate ? sig.dtemp_dt_Cpm : sig.temp_mean_C;
	const int i = run.thermistorIndex(name);
	if (i < 0) throw std::invalid_argument("model preset names thermistor '" + name + "', absent from the run");
	return rate ? sig.dthermistor_dt_Cpm[i] : sig.thermistor_C[i];
}

double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }
}  // namespace

BaseDesign buildBaseDesign(const BaseModelSpec& spec, const FogSeries& run, const RunSignals& sig)
{
	const std::size_t n = sig.size();
	std::vector<std::vector<double>> cols;
	BaseDesign d;
	auto add = [&](std::vector<double> c, std::string name, bool isStatic)
	{
		for (auto& v : c) v = finiteOr0(v);
		cols.push_back(std::move(c));
		d.names.push_back(std::move(name));
		d.is_static_temp.push_back(isStatic ? 1 : 0);
	};
	add(std::vector<double>(n, 1.0), "1", false);
	const auto statics = expandNames(spec.static_temps, run);
	if (!statics.empty()) d.static_temp_name = statics.front();
	for (const auto& name : statics)
	{
		const auto& T = tempColumn(name, run, sig, false);
		for (int k = 1; k <= spec.static_order; ++k)
		{
			std::vector<double> c(n);
			for (std::size_t j = 0; j < n; ++j) c[j] = std::pow(scaledTemp(T[j]), k);
			add(std::move(c), "T(" + name + ")^" + std::to_string(k), true);
		}
		d.max_static_order = std::max(d.max_static_order, spec.static_order);
	}
	for (const auto& name : expandNames(spec.rate_temps, run))
	{
		const auto& R = tempColumn(name, run, sig, true);
		for (int k = 1; k <= spec.rate_order; ++k)
		{
			std::vector<double> c(n);
			for (std::size_t j = 0; j < n; ++j) c[j] = std::pow(R[j], k);
			add(std::move(c), "dT/dt(" + name + ")^" + std::to_string(k), false);
		}
	}
	if (spec.diff_order > 0 || spec.diff_rate_order > 0)
	{
		std::vector<double> g(n), gr;
		std::string label;
		if (spec.diff_in.empty())
		{
			if (!sig.has_inner_outer)
				throw std::invalid_argument("preset '" + spec.preset + "' needs inner and outer thermistors");
			g = sig.gradient_C;
			gr = sig.dgradient_dt_Cpm;
			label = "Tin-Tout";
		}
		else
		{
			const auto& a = tempColumn(spec.diff_in, run, sig, false);
			const auto& b = tempColumn(spec.diff_out, run, sig, false);
			const auto& ar = tempColumn(spec.diff_in, run, sig, true);
			const auto& br = tempColumn(spec.diff_out, run, sig, true);
			gr.resize(n);
			for (std::size_t j = 0; j < n; ++j)
			{
				g[j] = a[j] - b[j];
				gr[j] = ar[j] - br[j];
			}
			label = spec.diff_in + "-" + spec.diff_out;
		}
		for (int k = 1; k <= spec.diff_order; ++k)
		{
			std::vector<double> c(n);
			for (std::size_t j = 0; j < n; ++j) c[j] = std::pow(g[j], k);
			add(std::move(c), "d(" + label + ")^" + std::to_string(k), false);
		}
		for (int k = 1; k <= spec.diff_rate_order; ++k)
		{
			std::vector<double> c(n);
			for (std::size_t j = 0; j < n; ++j) c[j] = std::pow(gr[j], k);
			add(std::move(c), "dd/dt(" + label + ")^" + std::to_string(k), false);
		}
	}
	if (sig.has_table)
	{
		std::vector<double> c(sig.table_rate_dph);
		for (auto& v : c) v *= 1e-6;
		add(std::move(c), "table_rate*1e-6", false);
	}
	d.X.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cols.size()));
	for (std::size_t c = 0; c < cols.size(); ++c)
		for (std::size_t j = 0; j < n; ++j) d.X(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(c)) = cols[c][j];
	return d;
}

}  // namespace mrpt_fog::discrepancy
