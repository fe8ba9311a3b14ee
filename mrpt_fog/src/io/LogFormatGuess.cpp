/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/GzStream.h>
#include <mrpt_fog/io/LogFormat.h>
#include <mrpt_fog/io/NumberText.h>

#include <algorithm>
#include <cctype>
#include <optional>
#include <sstream>

namespace mrpt_fog
{
namespace
{
std::string lower(std::string s)
{
	for (auto& c : s) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
	return s;
}

std::string trimmed(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t\r");
	if (b == std::string::npos) return {};
	return s.substr(b, s.find_last_not_of(" \t\r") - b + 1);
}

/** Cells of a line (quotes removed), split at `d`. */
std::vector<std::string> cellsOf(const std::string& line, char d)
{
	std::vector<std::string> out;
	std::string cell;
	bool q = false;
	for (char c : line)
	{
		if (c == '"') q = !q;
		else if (c == d && !q)
		{
			out.push_back(trimmed(cell));
			cell.clear();
		}
		else
			cell += c;
	}
	out.push_back(trimmed(cell));
	return out;
}

char delimiterOf(const std::string& line)
{
	char best = ',';
	std::size_t best_n = 0;
	for (char d : {',', ';', '\t', '|'})
	{
		const auto n = cellsOf(line, d).size() - 1;
		if (n > best_n) best_n = n, best = d;
	}
	return best;
}

std::size_t numericCells(const std::vector<std::string>& cells)
{
	std::size_t n = 0;
	for (const auto& c : cells) n += io::parseNumber(c).has_value();
	return n;
}

/** The unit written in a column name: "[deg/s]", "(ms)", or a suffix "_dps". */
std::string unitText(const std::string& name, std::string& stem)
{
	stem = name;
	for (auto [open, close] : {std::pair{'[', ']'}, std::pair{'(', ')'}, std::pair{'{', '}'}})
	{
		const auto b = name.rfind(open), e = name.rfind(close);
		if (b != std::string::npos && e != std::string::npos && e > b)
		{
			stem = trimmed(name.substr(0, b) + name.substr(e + 1));
			return trimmed(name.substr(b + 1, e - b - 1));
		}
	}
	const auto u = name.find_last_of("_ ");
	if (u != std::string::npos && u + 1 < name.size())
	{
		stem = name.substr(0, u);
		return name.substr(u + 1);
	}
	return {};
}

std::optional<std::string> timeUnit(const std::string& u)
{
	const std::string l = lower(u);
	if (l == "s" || l == "sec" || l == "secs" || l == "seconds") return "s";
	if (l == "ms" || l == "msec" || l == "millis") return "ms";
	if (l == "us" || l == "\xc2\xb5s" || l == "usec" || l == "micros") return "us";
	if (l == "ns" || l == "nsec") return "ns";
	return std::nullopt;
}
std::optional<std::string> rateUnit(const std::string& u)
{
	std::string l;
	for (char c : lower(u))
		if (c != ' ' && c != '*' && c != '.') l += c;
	if (l.rfind("\xc2\xb0", 0) == 0) l = "deg" + l.substr(2);  // degree sign
	for (const char* per : {"s^-1", "s-1"})  // "rad s^-1", "deg.s-1"
		if (const auto k = l.find(per); k != std::string::npos && k + std::string(per).size() == l.size())
			l = l.substr(0, k) + "/s";
	for (const char* per : {"h^-1", "h-1"})
		if (const auto k = l.find(per); k != std::string::npos && k + std::string(per).size() == l.size())
			l = l.substr(0, k) + "/h";
	if (l == "deg/s" || l == "dps" || l == "deg/sec" || l == "degs") return "deg/s";
	if (l == "deg/h" || l == "dph" || l == "deg/hr" || l == "degh") return "deg/h";
	if (l == "rad/s" || l == "rps" || l == "rads" || l == "rad/sec") return "rad/s";
	if (l == "mdeg/s" || l == "mdps") return "mdeg/s";
	return std::nullopt;
}
std::optional<std::string> temperatureUnit(const std::string& u)
{
	std::string l = lower(u);
	if (l.rfind("\xc2\xb0", 0) == 0) l = l.substr(2);
	if (l == "c" || l == "degc" || l == "celsius") return "C";
	if (l == "k" || l == "kelvin") return "K";
	return std::nullopt;
}

/** x, y or z as a separate token of the name ("Gyro Z", "gyro_z", "wz", "GyrZ"). */
std::optional<int> axisOf(const std::string& stem)
{
	const std::string l = lower(stem);
	for (std::size_t i = 0; i < l.size(); i++)
	{
		if (l[i] < 'x' || l[i] > 'z') continue;
		const bool before = i == 0 || !std::isalpha(static_cast<unsigned char>(l[i - 1])) ||
							l.compare(0, i, "w") == 0 || l.compare(i >= 3 ? i - 3 : 0, 3, "gyr") == 0 ||
							l.compare(i >= 4 ? i - 4 : 0, 4, "gyro") == 0;
		const bool after = i + 1 == l.size() || !std::isalpha(static_cast<unsigned char>(l[i + 1]));
		if (before && after) return l[i] - 'x';
	}
	return std::nullopt;
}

bool has(const std::string& stem, std::initializer_list<const char*> words)
{
	const std::string l = lower(stem);
	for (const char* w : words)
		if (l.find(w) != std::string::npos) return true;
	return false;
}

std::string thermistorName(const std::string& stem, std::size_t k)
{
	std::string n;
	for (char c : stem)
		if (std::isalnum(static_cast<unsigned char>(c))) n += c;
		else if (!n.empty() && n.back() != '_') n += '_';
	while (!n.empty() && n.back() == '_') n.pop_back();
	if (n.empty() || std::isdigit(static_cast<unsigned char>(n[0]))) n = "T" + std::to_string(k + 1) + (n.empty() ? "" : "_" + n);
	return n;
}

std::string quoted(const std::string& s)
{
	std::string o = "\"";
	for (char c : s) o += (c == '"' || c == '\\') ? std::string("\\") + c : std::string(1, c);
	return o + "\"";
}
}  // namespace

std::string guessLogFormat(const std::string& path)
{
	io::GzReader in(path);
	std::vector<std::string> lines;
	std::string l;
	while (lines.size() < 200 && in.readLine(l, 1u << 20)) lines.push_back(l);
	// The header: the first line of >= 2 non-numeric cells followed by a line of numbers.
	std::optional<std::size_t> header;
	char d = ',';
	for (std::size_t i = 0; i + 1 < lines.size() && !header; i++)
	{
		std::string h = lines[i];
		if (i == 0 && h.rfind("\xEF\xBB\xBF", 0) == 0) h.erase(0, 3);
		d = delimiterOf(h);
		const auto hc = cellsOf(h, d), next = cellsOf(lines[i + 1], d);
		if (hc.size() >= 2 && numericCells(hc) == 0 && next.size() == hc.size() && numericCells(next) * 2 > next.size())
		{
			header = i;
			lines[i] = h;
		}
	}
	if (!header)
		throw FogIoError(path + ": no header line found in the first " + std::to_string(lines.size()) +
						 " lines (a line of column names followed by a line of numbers)");
	const auto names = cellsOf(lines[*header], d);

	std::ostringstream time, rates, therm, extra, ignored;
	bool have_time = false, have_rate = false;
	std::size_t n_therm = 0;
	const char* check = "   # CHECK";
	for (const auto& name : names)
	{
		std::string stem;
		const std::string u = unitText(name, stem);
		const auto tu = timeUnit(u), ru = rateUnit(u), ku = temperatureUnit(u);
		const auto axis = axisOf(stem);
		if (!have_time && (has(stem, {"time", "stamp"}) || lower(stem) == "t") && !ru)
		{
			time << "time: {column: " << quoted(name) << ", unit: " << tu.value_or("s") << "}"
				 << (tu ? check : "   # CHECK: no unit in the name, s assumed") << "\n";
			have_time = true;
		}
		else if (has(stem, {"table"}))
			extra << "table_rate: {column: " << quoted(name) << ", unit: " << ru.value_or("deg/s") << "}"
				  << (ru ? check : "   # CHECK: no unit in the name, deg/s assumed") << "\n";
		else if ((ru || has(stem, {"gyr", "rate", "omega"})) && axis)
		{
			rates << "  " << static_cast<char>('x' + *axis) << ": {column: " << quoted(name)
				  << ", unit: " << ru.value_or("deg/h") << "}" << (ru ? check : "   # CHECK: no unit in the name, deg/h assumed")
				  << "\n";
			have_rate = true;
		}
		else if (ku || has(stem, {"temp", "therm", "tmp"}))
			therm << "  " << thermistorName(stem, n_therm++) << ": {column: " << quoted(name) << ", unit: " << ku.value_or("C")
				  << ", side: other, angle_deg: 0}" << (ku ? "   # CHECK side and angle" : "   # CHECK: no unit, C assumed")
				  << "\n";
		else if (lower(u) == "ut" || lower(u) == "\xc2\xb5t" || has(stem, {"field"}))
			extra << "field: {column: " << quoted(name) << ", unit: uT}" << check << "\n";
		else if (has(stem, {"pwr", "power"}))
			extra << "power: {column: " << quoted(name) << "}" << check << " (1 on, 0 off)\n";
		else
			ignored << "#   " << quoted(name) << "\n";
	}
	std::ostringstream o;
	o << "# Draft format file for " << path << " (fog-convert --guess-format): check every line marked\n"
	  << "# CHECK, then read the log with --format this_file.yaml. Schema: docs/reference/format-files.md\n";
	o << "delimiter: " << (d == '\t' ? std::string("tab") : quoted(std::string(1, d))) << "\n";
	o << "skip_lines: " << *header << "\n";
	o << (have_time ? time.str() : "# time: {column: \"...\", unit: s}   # CHECK: no time column recognised\n");
	o << (have_rate ? "rates:\n" + rates.str() : "# rates:   # CHECK: no rate column recognised\n#   z: {column: \"...\", unit: deg/s}\n");
	if (n_therm) o << "thermistors:\n" << therm.str();
	o << extra.str();
	o << "metadata: {sensor: FOG}   # CHECK: add latitude_deg: <deg> where the gyro stood\n";
	if (!ignored.str().empty()) o << "# columns not recognised (ignored when read):\n" << ignored.str();
	return o.str();
}

}  // namespace mrpt_fog
