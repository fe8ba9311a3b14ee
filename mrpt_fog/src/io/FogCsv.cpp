/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/io/GzFile.h>
#include <mrpt_fog/io/NumberText.h>

#include <cmath>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace mrpt_fog
{
namespace
{
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t");
	return s.substr(b, e - b + 1);
}

std::vector<std::string> splitCells(const std::string& line)
{
	std::vector<std::string> cells;
	std::string::size_type start = 0;
	for (;;)
	{
		const auto comma = line.find(',', start);
		cells.push_back(trim(line.substr(start, comma == std::string::npos ? std::string::npos : comma - start)));
		if (comma == std::string::npos) break;
		start = comma + 1;
	}
	return cells;
}

/** What a header column holds. */
struct Column
{
	enum class Kind
	{
		Time,
		Rate,
		Temp,
		TableRate,
		Field,
		Power
	} kind;
	int index = 0;  //!< axis (Rate) or thermistor index (Temp)
	std::string name;
};

/** Splits the text into lines (LF or CRLF), keeping 1-based line numbers. */
std::vector<std::string> splitLines(const std::string& text)
{
	std::vector<std::string> lines;
	std::string::size_type start = 0;
	while (start < text.size())
	{
		auto nl = text.find('\n', start);
		if (nl == std::string::npos) nl = text.size();
		std::string line = text.substr(start, nl - start);
		if (!line.empty() && line.back() == '\r') line.pop_back();
		lines.push_back(std::move(line));
		start = nl + 1;
	}
	return lines;
}

class CsvParser
{
   public:
	explicit CsvParser(const std::string& path) : path_(path) {}

	FogSeries parse(const std::string& text)
	{
		lines_ = splitLines(text);
		if (!lines_.empty() && lines_[0].rfind("\xEF\xBB\xBF", 0) == 0) lines_[0].erase(0, 3);  // UTF-8 BOM
		bool any_content = false;
		for (const auto& l : lines_)
			if (!trim(l).empty()) any_content = true;
		if (!any_content) throw FogIoError(path_ + ": empty file (no metadata, header or data)");

		std::size_t i = 0;
		for (; i < lines_.size(); i++)
		{
			const std::string l = trim(lines_[i]);
			if (l.empty()) continue;
			if (l[0] != '#') break;
			parseMetadataLine(l, i + 1);
		}
		if (i == lines_.size())
			throw FogIoError(path_ + ": no header row after the '#' metadata lines (expected e.g. 'time_s,rate_z_dph,temp_Ti1_C')");
		parseHeader(lines_[i], i + 1);
		for (i++; i < lines_.size(); i++)
		{
			if (trim(lines_[i]).empty()) continue;
			parseRow(lines_[i], i + 1);
		}
		if (s_.empty()) throw FogIoError(path_ + ": header but no data rows");
		return std::move(s_);
	}

   private:
	[[noreturn]] void fail(std::size_t line, const std::string& what) const
	{
		throw FogIoError(path_ + ":" + std::to_string(line) + ": " + what);
	}
	[[noreturn]] void failCell(std::size_t line, std::size_t col, const std::string& what) const
	{
		fail(line, "column " + std::to_string(col + 1) + " (" + columns_[col].name + "): " + what);
	}

	void parseMetadataLine(const std::string& l, std::size_t line)
	{
		const std::string body = trim(l.substr(1));
		const auto colon = body.find(':');
		if (colon == std::string::npos)
		{
			s_.metadata.emplace_back("", body);  // free comment, kept
			return;
		}
		const std::string key = trim(body.substr(0, colon));
		const std::string value = trim(body.substr(colon + 1));
		if (key.rfind("thermistor ", 0) == 0)
			parseThermistor(trim(key.substr(11)), value, line);
		else if (key == "sensor")
		{
			if (value.empty()) fail(line, "'# sensor:' has no label");
			s_.sensor_label = value;
		}
		else if (key == "epoch_s")
		{
			const auto v = io::parseNumber(value);
			if (!v || !std::isfinite(*v)) fail(line, "epoch_s: cannot parse '" + value + "' as a number of seconds");
			s_.epoch_s = *v;
		}
		else
		{
			if (key == "latitude_deg")
			{
				const auto v = io::parseNumber(value);
				if (!v || !std::isfinite(*v) || std::abs(*v) > 90)
					fail(line, "latitude_deg: '" + value + "' is not a latitude in [-90, 90] deg");
			}
			s_.metadata.emplace_back(key, value);  // latitude_deg and unknown keys are kept
		}
	}

	void parseThermistor(const std::string& name, const std::string& value, std::size_t line)
	{
		if (!isValidThermistorName(name))
			fail(line, "thermistor name '" + name + "' is not valid (letters, digits and '_' only)");
		if (declared_.count(name)) fail(line, "thermistor '" + name + "' declared twice");
		ThermistorInfo info;
		info.name = name;
		std::istringstream tokens(value);
		std::string tok;
		while (tokens >> tok)
		{
			const auto eq = tok.find('=');
			const std::string k = tok.substr(0, eq);
			const std::string v = eq == std::string::npos ? std::string() : tok.substr(eq + 1);
			if (k == "side")
			{
				try
				{
					info.side = coilSideFromString(v);
				}
				catch (const std::exception&)
				{
					fail(line, "thermistor '" + name + "': side '" + v + "' is not inner, outer or other");
				}
			}
			else if (k == "angle_deg")
			{
				const auto a = io::parseNumber(v);
				if (!a || !std::isfinite(*a)) fail(line, "thermistor '" + name + "': cannot parse angle_deg '" + v + "'");
				info.angle_deg = *a;
			}
			else
				fail(line, "thermistor '" + name + "': unknown attribute '" + tok + "' (expected side=inner|outer|other angle_deg=<deg>)");
		}
		declared_[name] = {info, line};
	}

	void parseHeader(const std::string& l, std::size_t line)
	{
		header_line_ = line;
		const auto cells = splitCells(l);
		if (!cells.empty() && io::parseNumber(cells[0]))
			fail(line, "header row missing: the first non-'#' line starts with a number ('" + cells[0] +
						   "'); expected column names such as time_s,rate_z_dph,temp_Ti1_C");
		s_.has_axis = {false, false, false};
		std::map<std::string, std::size_t> seen;
		for (std::size_t c = 0; c < cells.size(); c++)
		{
			const std::string& n = cells[c];
			if (n.empty()) fail(line, "column " + std::to_string(c + 1) + " has an empty name");
			if (seen.count(n))
				fail(line, "column " + std::to_string(c + 1) + " '" + n + "' repeats column " + std::to_string(seen[n] + 1));
			seen[n] = c;
			Column col{Column::Kind::Time, 0, n};
			if (n == "time_s") col.kind = Column::Kind::Time;
			else if (n == "rate_x_dph" || n == "rate_y_dph" || n == "rate_z_dph")
			{
				col.kind = Column::Kind::Rate;
				col.index = n[5] - 'x';
				s_.has_axis[col.index] = true;
			}
			else if (n == "table_rate_dph") col.kind = Column::Kind::TableRate;
			else if (n == "field_uT") col.kind = Column::Kind::Field;
			else if (n == "power") col.kind = Column::Kind::Power;
			else if (n.size() > 7 && n.rfind("temp_", 0) == 0 && n.compare(n.size() - 2, 2, "_C") == 0)
			{
				const std::string name = n.substr(5, n.size() - 7);
				if (!isValidThermistorName(name))
					fail(line, "column " + std::to_string(c + 1) + " '" + n + "': thermistor name '" + name + "' is not valid");
				col.kind = Column::Kind::Temp;
				col.index = static_cast<int>(s_.thermistors.size());
				ThermistorInfo info;
				info.name = name;
				if (auto it = declared_.find(name); it != declared_.end()) info = it->second.first;
				s_.thermistors.push_back(info);
			}
			else
				fail(line, "column " + std::to_string(c + 1) + " '" + n +
							   "' is not a known column (time_s, rate_x|y|z_dph, temp_<name>_C, table_rate_dph, field_uT, power)");
			columns_.push_back(col);
		}
		if (!seen.count("time_s")) fail(line, "missing required column 'time_s'");
		if (!s_.has_axis[0] && !s_.has_axis[1] && !s_.has_axis[2])
			fail(line, "missing required rate column (at least one of rate_x_dph, rate_y_dph, rate_z_dph)");
		for (const auto& [name, d] : declared_)
			if (s_.thermistorIndex(name) < 0)
				fail(d.second, "thermistor '" + name + "' is declared but the header has no column temp_" + name + "_C");
		s_.temp_C.assign(s_.thermistors.size(), {});
		if (seen.count("table_rate_dph")) has_table_ = true;
		if (seen.count("field_uT")) has_field_ = true;
		if (seen.count("power")) has_power_ = true;
	}

	double number(const std::string& cell, std::size_t line, std::size_t c) const
	{
		const auto v = io::parseNumber(cell);
		if (!v) failCell(line, c, "cannot parse '" + cell + "' as a number");
		return *v;
	}

	void parseRow(const std::string& l, std::size_t line)
	{
		const auto cells = splitCells(l);
		if (cells.size() != columns_.size())
			fail(line, std::to_string(cells.size()) + " cells, but the header (line " + std::to_string(header_line_) +
						   ") has " + std::to_string(columns_.size()) + " columns");
		double table = kNaN, field = kNaN, power = kNaN;
		std::array<double, 3> rate{kNaN, kNaN, kNaN};
		double t = kNaN;
		int empty_rate_col = -1;  // first rate column with an empty cell (gyro off), -1 when none
		std::vector<double> temps(s_.thermistors.size(), kNaN);
		for (std::size_t c = 0; c < cells.size(); c++)
		{
			const Column& col = columns_[c];
			const std::string& cell = cells[c];
			switch (col.kind)
			{
				case Column::Kind::Time:
				case Column::Kind::Rate:
				{
					if (cell.empty() && col.kind == Column::Kind::Rate)
					{
						if (empty_rate_col < 0) empty_rate_col = static_cast<int>(c);  // power-off rows only: checked below
						break;
					}
					if (cell.empty()) failCell(line, c, "empty cell (only temperatures may be missing)");
					const double v = number(cell, line, c);
					if (!std::isfinite(v)) failCell(line, c, "value '" + cell + "' is not finite");
					(col.kind == Column::Kind::Time ? t : rate[col.index]) = v;
					break;
				}
				case Column::Kind::Temp:
				case Column::Kind::TableRate:
				case Column::Kind::Field:
				{
					double v = kNaN;  // empty = missing reading (dropout)
					if (!cell.empty())
					{
						v = number(cell, line, c);
						if (std::isinf(v)) failCell(line, c, "value '" + cell + "' is infinite");
					}
					if (col.kind == Column::Kind::Temp) temps[col.index] = v;
					else (col.kind == Column::Kind::TableRate ? table : field) = v;
					break;
				}
				case Column::Kind::Power:
				{
					if (cell.empty()) failCell(line, c, "empty cell (power must be 1 or 0)");
					const double v = number(cell, line, c);
					if (v != 0.0 && v != 1.0) failCell(line, c, "power must be 1 (on) or 0 (off), not '" + cell + "'");
					power = v;
					break;
				}
			}
		}
		if (empty_rate_col >= 0 && power != 0.0)
			failCell(line, static_cast<std::size_t>(empty_rate_col),
					 has_power_ ? "empty cell with the gyro powered (a rate may be empty only where power is 0)"
								: "empty cell (only temperatures may be missing; a rate may be empty only on a "
								  "power-off row, power 0)");
		if (!s_.time_s.empty() && !(t > s_.time_s.back()))
		{
			const std::string prev = io::formatNumber(s_.time_s.back());
			fail(line, "column 1 (time_s): time " + io::formatNumber(t) + " s " +
						   (t == s_.time_s.back() ? "duplicates the previous sample's time" : "goes backwards from the previous sample's") +
						   " (" + prev + " s); time_s must be strictly increasing");
		}
		s_.time_s.push_back(t);
		for (int a = 0; a < 3; a++)
			if (s_.has_axis[a]) s_.rate_dph[a].push_back(rate[a]);
		for (std::size_t i = 0; i < temps.size(); i++) s_.temp_C[i].push_back(temps[i]);
		if (has_table_) s_.table_rate_dph.push_back(table);
		if (has_field_) s_.field_uT.push_back(field);
		if (has_power_) s_.power.push_back(power);
	}

	std::string path_;
	std::vector<std::string> lines_;
	std::map<std::string, std::pair<ThermistorInfo, std::size_t>> declared_;
	std::vector<Column> columns_;
	std::size_t header_line_ = 0;
	bool has_table_ = false, has_field_ = false, has_power_ = false;
	FogSeries s_;
};

std::string csvText(const FogSeries& s)
{
	std::string out;
	out += "# sensor: " + s.sensor_label + "\n";
	out += "# epoch_s: " + io::formatNumber(s.epoch_s) + "\n";
	for (const auto& t : s.thermistors)
		out += "# thermistor " + t.name + ": side=" + toString(t.side) + " angle_deg=" + io::formatNumber(t.angle_deg) + "\n";
	for (const auto& [k, v] : s.metadata)
	{
		if (k == "sensor" || k == "epoch_s" || k.rfind("thermistor ", 0) == 0) continue;  // written above
		out += k.empty() ? "# " + v + "\n" : "# " + k + ": " + v + "\n";
	}
	out += "time_s";
	const char* rates[3] = {"rate_x_dph", "rate_y_dph", "rate_z_dph"};
	for (int a = 0; a < 3; a++)
		if (s.has_axis[a]) out += std::string(",") + rates[a];
	for (const auto& t : s.thermistors) out += ",temp_" + t.name + "_C";
	if (!s.table_rate_dph.empty()) out += ",table_rate_dph";
	if (!s.field_uT.empty()) out += ",field_uT";
	if (!s.power.empty()) out += ",power";
	out += "\n";
	auto cell = [&](double v) {
		out += ',';
		if (!std::isnan(v)) out += io::formatNumber(v);  // NaN = missing reading: empty cell
	};
	for (std::size_t k = 0; k < s.size(); k++)
	{
		out += io::formatNumber(s.time_s[k]);
		for (int a = 0; a < 3; a++)
			if (s.has_axis[a]) cell(s.rate_dph[a][k]);
		for (const auto& col : s.temp_C) cell(col[k]);
		if (!s.table_rate_dph.empty()) cell(s.table_rate_dph[k]);
		if (!s.field_uT.empty()) cell(s.field_uT[k]);
		if (!s.power.empty()) cell(s.power[k]);
		out += '\n';
	}
	return out;
}

}  // namespace

FogSeries readFogCsv(const std::string& path)
{
	const std::string text = io::readWholeFile(path);
	return CsvParser(path).parse(text);
}

void writeFogCsv(const std::string& path, const FogSeries& series)
{
	try
	{
		series.validate();
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + e.what());
	}
	for (const auto& p : series.power)
		if (p != 0.0 && p != 1.0) throw FogIoError(path + ": cannot write: power column holds a value other than 0/1");
	try
	{
		io::requireOneLineMetadata(series);
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + e.what());
	}
	const std::string ext = fileExtension(path);
	io::writeWholeFileAtomically(path, csvText(series), ext.size() >= 3 && ext.compare(ext.size() - 3, 3, ".gz") == 0);
}

}  // namespace mrpt_fog
