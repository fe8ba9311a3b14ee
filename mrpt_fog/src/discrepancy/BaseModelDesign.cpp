/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/discrepancy/BaseModelDesign.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/model/ModelPreset.h>

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog::discrepancy
{
namespace
{
bool endsWith(const std::string& s, const std::string& suffix)
{
	return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}
double finiteOr0(double v) { return std::isfinite(v) ? v : 0.0; }
}  // namespace

BaseModelSpec resolveBaseModel(const std::string& text, const FogSeries& run)
{
	BaseModelSpec s;
	s.source = text;
	if (endsWith(text, ".yaml") || endsWith(text, ".yml"))
	{
		const Calibration cal = loadCalibrationYaml(text);
		s.terms = cal.model.features.terms();
		for (const auto& t : s.terms)
			if (!t.constant)
				for (const auto* name : {&t.signal.a, &t.signal.b})
					if (!name->empty() && run.thermistorIndex(*name) < 0)
						throw std::invalid_argument(text + ": term " + t.name() + " uses thermistor '" + *name +
													"', absent from the measured run");
		return s;
	}
	if (text.rfind("static:", 0) == 0)
	{
		std::stringstream ss(text.substr(7));
		std::string order, name;
		std::getline(ss, order, ':');
		std::getline(ss, name);
		try
		{
			std::size_t used = 0;
			s.static_order = std::stoi(order, &used);
			if (used != order.size() || s.static_order < 1 || s.static_order > 7) throw std::invalid_argument("");
		}
		catch (const std::exception&)
		{
			throw std::invalid_argument("model preset '" + text + "': static:P[:NAME] needs an order P in 1..7");
		}
		if (!name.empty())
		{
			if (run.thermistorIndex(name) < 0)
				throw std::invalid_argument("model preset '" + text + "': thermistor '" + name + "' is not in the run");
			s.static_name = name;
		}
		s.terms = {ThermalTerm::constantTerm()};
		return s;
	}
	const ModelPreset p = parseModelPreset(text, run.thermistors);
	s.terms = presetFeatures(p).terms();
	return s;
}

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
	auto thermistor = [&](const std::string& name) -> std::size_t
	{
		const int i = run.thermistorIndex(name);
		if (i < 0) throw std::invalid_argument("base model uses thermistor '" + name + "', absent from the run");
		return static_cast<std::size_t>(i);
	};
	add(std::vector<double>(n, 1.0), "1", false);
	if (spec.static_order > 0)
	{
		const auto& T = spec.static_name == "mean" ? sig.temp_mean_C : sig.thermistor_C[thermistor(spec.static_name)];
		for (int k = 1; k <= spec.static_order; ++k)
		{
			std::vector<double> c(n);
			for (std::size_t j = 0; j < n; ++j) c[j] = std::pow(scaledTemp(T[j]), k);
			add(std::move(c), "T(" + spec.static_name + ")^" + std::to_string(k), true);
		}
		d.max_static_order = spec.static_order;
		d.static_temp_C = T;
	}
	for (const auto& t : spec.terms)
	{
		if (t.constant) continue;
		const auto& sg = t.signal;
		const std::size_t a = thermistor(sg.a);
		std::vector<double> v(n);
		switch (sg.kind)
		{
			case SignalKind::Temp:
				for (std::size_t j = 0; j < n; ++j) v[j] = scaledTemp(sig.thermistor_C[a][j]);
				break;
			case SignalKind::Rate: v = sig.dthermistor_dt_Cpm[a]; break;
			case SignalKind::Diff:
			{
				const std::size_t b = thermistor(sg.b);
				for (std::size_t j = 0; j < n; ++j) v[j] = sig.thermistor_C[a][j] - sig.thermistor_C[b][j];
				break;
			}
			case SignalKind::DiffRate:
			{
				const std::size_t b = thermistor(sg.b);
				for (std::size_t j = 0; j < n; ++j) v[j] = sig.dthermistor_dt_Cpm[a][j] - sig.dthermistor_dt_Cpm[b][j];
				break;
			}
		}
		std::vector<double> c(n);
		for (std::size_t j = 0; j < n; ++j) c[j] = std::pow(finiteOr0(v[j]), t.power);
		const bool isStatic = sg.kind == SignalKind::Temp;
		add(std::move(c), t.name(), isStatic);
		if (isStatic)
		{
			if (d.static_temp_C.empty()) d.static_temp_C = sig.thermistor_C[a];
			d.max_static_order = std::max(d.max_static_order, t.power);
		}
	}
	if (d.static_temp_C.empty()) d.static_temp_C = sig.temp_mean_C;
	if (sig.has_table)
	{
		std::vector<double> c(sig.table_rate_dph);
		for (auto& v : c) v *= 1e-6;
		add(std::move(c), "table_rate*1e-6", false);
	}
	d.X.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(cols.size()));
	for (std::size_t c = 0; c < cols.size(); ++c)
		for (std::size_t j = 0; j < n; ++j)
			d.X(static_cast<Eigen::Index>(j), static_cast<Eigen::Index>(c)) = cols[c][j];
	return d;
}

}  // namespace mrpt_fog::discrepancy
