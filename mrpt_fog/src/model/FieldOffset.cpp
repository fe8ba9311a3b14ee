/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/containers/yaml.h>
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/common/YamlGuard.h>
#include <mrpt_fog/model/FieldOffset.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace mrpt_fog
{
namespace
{
constexpr double kSecondsPerDay = 86400.0;
constexpr double kMaxOffset_dph = 1e4;  // a FOG's bias offset beyond this is no offset
const char* const kSection = "field_offset:";

double number(const mrpt::containers::yaml& n, const std::string& key, const std::string& where)
{
	if (!n.has(key)) throw std::invalid_argument(where + "." + key + ": missing");
	double v = 0;
	try
	{
		v = n[key].as<double>();
	}
	catch (const std::exception&)
	{
		throw std::invalid_argument(where + "." + key + ": expected a number");
	}
	if (!std::isfinite(v)) throw std::invalid_argument(where + "." + key + ": must be finite");
	return v;
}

std::string quoted(const std::string& s)
{
	std::string o = "\"";
	for (char c : s)
	{
		if (c == '"' || c == '\\') o += '\\';
		o += c;
	}
	return o + "\"";
}
}  // namespace

double FieldOffset::offsetAt_dph(double t_unix_s) const
{
	return offset_dph + aging_dph_per_day * (t_unix_s - reference_unix_s) / kSecondsPerDay;
}

double FieldOffset::sigmaAt_dph(double t_unix_s) const
{
	return std::hypot(sigma_dph, aging_sigma_dph_per_day * (t_unix_s - reference_unix_s) / kSecondsPerDay);
}

std::optional<FieldOffset> fieldOffsetFromYaml(const std::string& text, const std::string& source)
{
	requireSafeYamlText(text, source);
	mrpt::containers::yaml root;
	try
	{
		root = mrpt::containers::yaml::FromText(text);
	}
	catch (const std::exception&)
	{
		throw std::invalid_argument(source + ": not valid YAML");
	}
	if (!root.isMap() || !root.has("field_offset")) return std::nullopt;
	const auto n = root["field_offset"];
	const std::string w = source + ": field_offset";
	if (!n.isMap()) throw std::invalid_argument(w + ": expected a map");
	FieldOffset f;
	f.offset_dph = number(n, "offset_dph", w);
	f.sigma_dph = number(n, "sigma_dph", w);
	f.aging_dph_per_day = number(n, "aging_dph_per_day", w);
	f.aging_sigma_dph_per_day = number(n, "aging_sigma_dph_per_day", w);
	f.reference_unix_s = number(n, "reference_unix_s", w);
	const double rev = number(n, "revision", w);
	if (!(std::abs(f.offset_dph) <= kMaxOffset_dph)) throw std::invalid_argument(w + ".offset_dph: beyond +-1e4 deg/h");
	if (!(f.sigma_dph >= 0) || !(f.aging_sigma_dph_per_day >= 0)) throw std::invalid_argument(w + ": sigmas must be >= 0");
	if (rev != std::floor(rev) || rev < 1 || rev > 1e6) throw std::invalid_argument(w + ".revision: expected an integer >= 1");
	f.revision = static_cast<int>(rev);
	if (n.has("previous") && !n["previous"].isNullNode()) f.previous = n["previous"].as<std::string>();
	if (n.has("logs") && n["logs"].isSequence())
		for (const auto& l : n["logs"].asSequence()) f.logs.push_back(mrpt::containers::yaml(l).as<std::string>());
	return f;
}

std::optional<FieldOffset> loadFieldOffset(const std::string& path)
{
	std::ifstream in(path, std::ios::binary);
	if (!in) throw std::runtime_error(path + ": cannot open");
	std::ostringstream ss;
	ss << in.rdbuf();
	return fieldOffsetFromYaml(ss.str(), path);
}

std::string withFieldOffset(const std::string& text, const FieldOffset& f)
{
	std::string base = text;
	const std::string marker = std::string("\n") + kSection;
	if (base.rfind(kSection, 0) == 0) base.clear();
	else if (const auto p = base.find(marker); p != std::string::npos) base.erase(p + 1);
	if (!base.empty() && base.back() != '\n') base += '\n';
	std::ostringstream o;
	o << base << kSection << "  # learned in the field by fog-refine (model/FieldOffset.h); revision " << f.revision << "\n";
	o << "  offset_dph: " << formatValue("%.17g", f.offset_dph) << "  # at reference_unix_s, added to the thermal bias [deg/h]\n";
	o << "  sigma_dph: " << formatValue("%.17g", f.sigma_dph) << "  # 1-sigma; each turn-on's own draw comes on top [deg/h]\n";
	o << "  aging_dph_per_day: " << formatValue("%.17g", f.aging_dph_per_day) << "  # trend [deg/h per day]\n";
	o << "  aging_sigma_dph_per_day: " << formatValue("%.17g", f.aging_sigma_dph_per_day) << "\n";
	o << "  reference_unix_s: " << formatValue("%.17g", f.reference_unix_s) << "\n";
	o << "  revision: " << f.revision << "\n";
	o << "  previous: " << quoted(f.previous) << "  # kept, never overwritten\n";
	o << "  logs: [";
	for (std::size_t i = 0; i < f.logs.size(); i++) o << (i ? ", " : "") << quoted(f.logs[i]);
	o << "]\n";
	return o.str();
}

}  // namespace mrpt_fog
