/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/FogSeriesLayout.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/io/GzFile.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/io/GzStream.h>
#include <mrpt_fog/io/LogFormat.h>
#include <mrpt_fog/io/NumberText.h>

#include "FogLogReaderImpl.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string_view>
#include <limits>
#include <map>
#include <optional>
#include <sstream>

namespace mrpt_fog
{
namespace
{
using mrpt_fog::units::kNaN;

std::string trim(const std::string& s)
{
	const auto b = s.find_first_not_of(" \t");
	if (b == std::string::npos) return {};
	const auto e = s.find_last_not_of(" \t");
	return s.substr(b, e - b + 1);
}

std::string_view trimView(std::string_view s)
{
	std::size_t b = 0, e = s.size();
	while (b < e && (s[b] == ' ' || s[b] == '\t')) b++;
	while (e > b && (s[e - 1] == ' ' || s[e - 1] == '\t')) e--;
	return s.substr(b, e - b);
}

/** Cells of a line split at `delim`; a cell in double quotes may hold the delimiter, and ""
 * inside quotes is one quote. Blanks around a cell are trimmed, the quotes removed. Returns
 * false on a malformed quoted cell (a quote not closed, or text after the closing quote). */
bool splitQuotedCells(std::string_view line, char delim, std::vector<std::string>& cells)
{
	cells.clear();
	std::string cell;
	bool quoted = false, was_quoted = false;
	for (std::size_t i = 0; i <= line.size(); i++)
	{
		const bool end = i == line.size();
		const char c = end ? delim : line[i];
		if (quoted)
		{
			if (end) return false;
			if (c == '"')
			{
				if (i + 1 < line.size() && line[i + 1] == '"')
				{
					cell += '"';
					i++;
				}
				else
					quoted = false;
			}
			else
				cell += c;
			continue;
		}
		if (c == delim)
		{
			cells.push_back(was_quoted ? cell : trim(cell));
			cell.clear();
			was_quoted = false;
			continue;
		}
		if (c == '"' && trimView(cell).empty())
		{
			quoted = was_quoted = true;
			cell.clear();
			continue;
		}
		if (was_quoted && c != ' ' && c != '\t') return false;  // text after the closing quote
		if (!was_quoted) cell += c;
	}
	return true;
}

/** The delimiter of a header line: the most frequent of ',', ';', tab and '|' outside quotes
 * (',' when none occurs). */
char detectDelimiter(std::string_view line)
{
	const char candidates[] = {',', ';', '\t', '|'};
	std::size_t best_n = 0;
	char best = ',';
	for (char d : candidates)
	{
		std::size_t n = 0;
		bool quoted = false;
		for (char c : line)
		{
			if (c == '"') quoted = !quoted;
			else if (!quoted && c == d) n++;
		}
		if (n > best_n)
		{
			best_n = n;
			best = d;
		}
	}
	return best;
}

/** compensated_rate_<a>_dph, a column of fog-compensate's CSV. */
bool isCompensatedRate(const std::string& n)
{
	return n.size() == 22 && n.rfind("compensated_rate_", 0) == 0 && n[17] >= 'x' && n[17] <= 'z' &&
		   n.compare(18, 4, "_dph") == 0;
}

/** raw_rate_<a>_dph, bias_<a>_dph, flags, flags_<a>: fog-compensate's other columns. */
bool isCompensationDetail(const std::string& n)
{
	const auto axisCol = [&](const char* prefix, std::size_t p) {
		return n.size() == p + 5 && n.rfind(prefix, 0) == 0 && n[p] >= 'x' && n[p] <= 'z' && n.compare(p + 1, 4, "_dph") == 0;
	};
	return axisCol("raw_rate_", 9) || axisCol("bias_", 5) || n == "flags" ||
		   (n.size() == 7 && n.rfind("flags_", 0) == 0 && n[6] >= 'x' && n[6] <= 'z');
}

/** A cell for an error message: cut to 40 bytes, binary bytes escaped. */
std::string shown(std::string_view cell) { return io::detail::quoteForError(cell.data(), cell.size()); }

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
		Power,
		Ignored  //!< a column the format file does not map
	} kind;
	int index = 0;  //!< axis (Rate) or thermistor index (Temp)
	std::string name;
	double scale = 1;  //!< value in the native unit = cell x scale / divisor + offset
	double divisor = 1;
	double offset = 0;
	double toNative(double v) const
	{
		if (scale == 1 && divisor == 1 && offset == 0) return v;  // native units: untouched (keeps -0)
		return v * scale / divisor + offset;
	}
};

/** Streaming CSV reader: metadata and header at construction, then one row per next(). */
class CsvReaderImpl : public FogLogReader::Impl
{
   public:
	CsvReaderImpl(const std::string& path, const ReadLimits& limits, const LogFormat* format)
		: path_(path), limits_(limits), format_(format), in_(path)
	{
		std::string l;
		bool any_content = false, first = true;
		std::size_t skipped = 0;
		for (;;)
		{
			if (!readLine(l))
			{
				if (!any_content) throw FogIoError(path_ + ": empty file (no metadata, header or data)");
				if (format_)
					throw FogIoError(path_ + ": no header line after the " + std::to_string(format_->skip_lines) +
									 " lines skipped (format " + format_->source + ", skip_lines)");
				throw FogIoError(path_ +
								 ": no header row after the '#' metadata lines (expected e.g. 'time_s,rate_z_dph,temp_Ti1_C')");
			}
			if (first && l.rfind("\xEF\xBB\xBF", 0) == 0) l.erase(0, 3);  // UTF-8 BOM
			first = false;
			if (format_ && skipped < format_->skip_lines)
			{
				skipped++;
				any_content = true;
				continue;
			}
			const std::string t = trim(l);
			if (t.empty()) continue;
			any_content = true;
			if (format_) break;
			if (t[0] != '#') break;
			parseMetadataLine(t, in_.lineNumber());
		}
		if (format_) parseFormattedHeader(l, in_.lineNumber());
		else parseHeader(l, in_.lineNumber());
		header = layoutHeaderOf(s_, has_table_, has_field_, has_power_);
	}

	std::vector<std::string> notes() const override { return notes_; }

	bool next(FogSample& x) override
	{
		for (;;)
		{
			if (!readLine(line_))
			{
				if (samples == 0) throw FogIoError(path_ + ": header but no data rows");
				return false;
			}
			if (!trimView(line_).empty()) break;
		}
		parseRow(line_, in_.lineNumber(), x);
		samples++;
		return true;
	}
	bool isRawlog() const override { return false; }
	std::uint64_t fileBytesRead() const override { return in_.fileBytesRead(); }
	std::uint64_t fileBytes() const override { return in_.fileBytes(); }

   private:
	bool readLine(std::string& l)
	{
		try
		{
			return in_.readLine(l, limits_.max_line_bytes);
		}
		catch (const FogIoError&)
		{
			throw;
		}
	}
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
			if (!v || !std::isfinite(*v)) fail(line, "epoch_s: cannot parse '" + shown(value) + "' as a number of seconds");
			s_.epoch_s = *v;
		}
		else
		{
			if (key == "latitude_deg")
			{
				const auto v = io::parseNumber(value);
				if (!v || !std::isfinite(*v) || std::abs(*v) > 90)
					fail(line, "latitude_deg: '" + shown(value) + "' is not a latitude in [-90, 90] deg");
			}
			s_.metadata.emplace_back(key, value);  // latitude_deg and unknown keys are kept
		}
	}

	void parseThermistor(const std::string& name, const std::string& value, std::size_t line)
	{
		if (!isValidThermistorName(name))
			fail(line, "thermistor name '" + shown(name) + "' is not valid (letters, digits and '_' only)");
		if (declared_.count(name)) fail(line, "thermistor '" + name + "' declared twice");
		if (declared_.size() >= limits_.max_thermistors)
			fail(line, "more than the limit of " + std::to_string(limits_.max_thermistors) + " thermistors declared");
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
					fail(line, "thermistor '" + name + "': side '" + shown(v) + "' is not inner, outer or other");
				}
			}
			else if (k == "angle_deg")
			{
				const auto a = io::parseNumber(v);
				if (!a || !std::isfinite(*a)) fail(line, "thermistor '" + name + "': cannot parse angle_deg '" + shown(v) + "'");
				info.angle_deg = *a;
			}
			else
				fail(line, "thermistor '" + name + "': unknown attribute '" + shown(tok) +
							   "' (expected side=inner|outer|other angle_deg=<deg>)");
		}
		declared_[name] = {info, line};
	}

	void parseHeader(const std::string& l, std::size_t line)
	{
		header_line_ = line;
		std::vector<std::string> cells;
		if (!splitQuotedCells(l, ',', cells)) fail(line, "header row: a quoted cell is malformed (a quote not closed, or text after its closing quote)");
		if (!cells.empty() && io::parseNumber(cells[0]))
			fail(line, "header row missing: the first non-'#' line starts with a number ('" + shown(cells[0]) +
						   "'); expected column names such as time_s,rate_z_dph,temp_Ti1_C");
		s_.has_axis = {false, false, false};
		std::map<std::string, std::size_t> seen;
		for (std::size_t c = 0; c < cells.size(); c++)
		{
			const std::string& n = cells[c];
			if (n.empty()) fail(line, "column " + std::to_string(c + 1) + " has an empty name");
			if (seen.count(n))
				fail(line, "column " + std::to_string(c + 1) + " '" + shown(n) + "' repeats column " + std::to_string(seen[n] + 1));
			seen[n] = c;
			Column col{Column::Kind::Time, 0, n};
			if (n == "time_s")
			{
				col.kind = Column::Kind::Time;
				time_col_ = c;
			}
			else if (n == "rate_x_dph" || n == "rate_y_dph" || n == "rate_z_dph")
			{
				col.kind = Column::Kind::Rate;
				col.index = n[5] - 'x';
				s_.has_axis[col.index] = true;
			}
			else if (isCompensatedRate(n))
			{
				// fog-compensate's CSV: its compensated rate is the log's rate
				col.kind = Column::Kind::Rate;
				col.index = n[17] - 'x';
				if (s_.has_axis[col.index])
					fail(line, "column " + std::to_string(c + 1) + " '" + shown(n) + "': a second rate column for axis " +
								   std::string(1, n[17]));
				s_.has_axis[col.index] = true;
				compensated_ = true;
			}
			else if (isCompensationDetail(n))
			{
				col.kind = Column::Kind::Ignored;
				compensation_details_ += (compensation_details_.empty() ? "" : ", ") + n;
			}
			else if (n == "table_rate_dph") col.kind = Column::Kind::TableRate;
			else if (n == "field_uT") col.kind = Column::Kind::Field;
			else if (n == "power") col.kind = Column::Kind::Power;
			else if (n.size() > 7 && n.rfind("temp_", 0) == 0 && n.compare(n.size() - 2, 2, "_C") == 0)
			{
				const std::string name = n.substr(5, n.size() - 7);
				if (!isValidThermistorName(name))
					fail(line, "column " + std::to_string(c + 1) + " '" + shown(n) + "': thermistor name '" + shown(name) +
								   "' is not valid");
				if (s_.thermistors.size() >= limits_.max_thermistors)
					fail(line, "column " + std::to_string(c + 1) + " '" + shown(n) + "': more than the limit of " +
								   std::to_string(limits_.max_thermistors) + " thermistor columns");
				col.kind = Column::Kind::Temp;
				col.index = static_cast<int>(s_.thermistors.size());
				ThermistorInfo info;
				info.name = name;
				if (auto it = declared_.find(name); it != declared_.end()) info = it->second.first;
				s_.thermistors.push_back(info);
			}
			else
				fail(line, "column " + std::to_string(c + 1) + " '" + shown(n) +
							   "' is not a known column (time_s, rate_x|y|z_dph, temp_<name>_C, table_rate_dph, field_uT, power)");
			columns_.push_back(col);
		}
		if (!seen.count("time_s")) fail(line, "missing required column 'time_s'");
		if (!s_.has_axis[0] && !s_.has_axis[1] && !s_.has_axis[2])
			fail(line, "missing required rate column (at least one of rate_x_dph, rate_y_dph, rate_z_dph)");
		for (const auto& [name, d] : declared_)
			if (s_.thermistorIndex(name) < 0)
				fail(d.second, "thermistor '" + name + "' is declared but the header has no column temp_" + name + "_C");
		if (seen.count("table_rate_dph")) has_table_ = true;
		if (seen.count("field_uT")) has_field_ = true;
		if (seen.count("power")) has_power_ = true;
		if (compensated_)
		{
			// fog-compensate leaves the compensated cells empty where the gyro was off: such a row
			// is a power-off row (power 0) of the log read back.
			power_from_empty_rate_ = !has_power_;
			has_power_ = true;
			notes_.push_back("fog-compensate's output: its compensated rates are read as the rates" +
							 (compensation_details_.empty() ? std::string() : " (" + compensation_details_ + " ignored)"));
		}
		cells_.resize(columns_.size());
	}

	/** The header of a logger CSV read through a format file: every mapped column must be in
	 * it once; other columns are ignored (one note names them). */
	void parseFormattedHeader(const std::string& l, std::size_t line)
	{
		const LogFormat& f = *format_;
		header_line_ = line;
		delim_ = f.delimiter ? *f.delimiter : detectDelimiter(l);
		std::vector<std::string> cells;
		if (!splitQuotedCells(l, delim_, cells)) fail(line, "header line: a quoted cell is malformed (a quote not closed, or text after its closing quote)");
		std::string listed;
		for (const auto& c : cells) listed += (listed.empty() ? "" : ", ") + ("\"" + shown(c) + "\"");
		const auto failFormat = [&](const std::string& key, const std::string& what) {
			throw FogIoError(f.source + ": " + key + ": " + what + " in " + path_ + ":" + std::to_string(line) +
							 " (delimiter '" + (delim_ == '\t' ? std::string("tab") : std::string(1, delim_)) +
							 "'; its columns: " + listed + ")");
		};
		std::map<std::string, std::size_t> where;
		for (std::size_t c = 0; c < cells.size(); c++)
		{
			if (auto [it, fresh] = where.emplace(cells[c], c); !fresh)
				for (const FormatColumn* m : f.columns())
					if (m->column == cells[c])
						failFormat(m->key + ".column", "column '" + shown(cells[c]) + "' appears twice (columns " +
															 std::to_string(it->second + 1) + " and " + std::to_string(c + 1) + ")");
		}
		const auto find = [&](const FormatColumn& m) {
			auto it = where.find(m.column);
			if (it == where.end()) failFormat(m.key + ".column", "no column '" + shown(m.column) + "'");
			return it->second;
		};
		columns_.assign(cells.size(), Column{Column::Kind::Ignored, 0, ""});
		for (std::size_t c = 0; c < cells.size(); c++) columns_[c].name = cells[c];
		const auto place = [&](const FormatColumn& m, Column::Kind kind, int index) -> Column& {
			Column& col = columns_[find(m)];
			col.kind = kind;
			col.index = index;
			return col;
		};
		place(f.time, Column::Kind::Time, 0).divisor = std::round(1 / secondsPer(f.time_unit));
		time_col_ = find(f.time);
		s_.has_axis = {false, false, false};
		for (int a = 0; a < 3; a++)
			if (f.rates[a])
			{
				place(*f.rates[a], Column::Kind::Rate, a).scale = degPerHourPer(f.rates[a]->unit);
				s_.has_axis[a] = true;
			}
		// Thermistors in the order of their columns, as the native CSV orders them (the fit's
		// term order follows it).
		std::vector<const ThermistorColumn*> th;
		for (const auto& t : f.thermistors) th.push_back(&t);
		std::sort(th.begin(), th.end(), [&](auto* a, auto* b) { return find(*a) < find(*b); });
		if (th.size() > limits_.max_thermistors)
			failFormat("thermistors", "more than the limit of " + std::to_string(limits_.max_thermistors) + " thermistors");
		for (const ThermistorColumn* t : th)
		{
			Column& col = place(*t, Column::Kind::Temp, static_cast<int>(s_.thermistors.size()));
			if (t->unit == TemperatureUnit::K) col.offset = -273.15;
			ThermistorInfo info;
			info.name = t->name;
			info.side = coilSideFromString(t->side);
			info.angle_deg = t->angle_deg;
			s_.thermistors.push_back(info);
		}
		if (f.table_rate)
		{
			place(*f.table_rate, Column::Kind::TableRate, 0).scale = degPerHourPer(f.table_rate->unit);
			has_table_ = true;
		}
		if (f.field)
		{
			place(*f.field, Column::Kind::Field, 0);
			has_field_ = true;
		}
		if (f.power)
		{
			place(*f.power, Column::Kind::Power, 0);
			has_power_ = true;
		}
		std::string ignored;
		std::size_t n_ignored = 0;
		for (const auto& col : columns_)
			if (col.kind == Column::Kind::Ignored)
			{
				ignored += (ignored.empty() ? "" : ", ") + ("\"" + shown(col.name) + "\"");
				n_ignored++;
			}
		if (n_ignored)
			notes_.push_back(std::to_string(n_ignored) + " column" + (n_ignored > 1 ? "s" : "") +
							 " not in the format " + f.source + ", ignored: " + ignored);
		for (const auto& [key, value] : f.metadata)
		{
			if (key == "sensor") s_.sensor_label = value;
			else if (key == "epoch_s") s_.epoch_s = *io::parseNumber(value);
			else s_.metadata.emplace_back(key, value);
		}
		cells_.resize(columns_.size());
	}

	double number(std::string_view cell, std::size_t line, std::size_t c) const
	{
		const auto v = io::parseNumber(cell);
		if (!v) failCell(line, c, "cannot parse '" + shown(cell) + "' as a number");
		return *v;
	}

	void parseRow(const std::string& l, std::size_t line, FogSample& x)
	{
		// Split in place (no allocation per cell); a line with quotes is split cell by cell.
		const char delim = delim_;
		std::size_t ncells = 1;
		if (l.find('"') != std::string::npos)
		{
			if (!splitQuotedCells(l, delim, quoted_cells_))
				fail(line, "a quoted cell is malformed (a quote not closed, or text after its closing quote)");
			ncells = quoted_cells_.size();
			if (ncells != columns_.size())
				fail(line, std::to_string(ncells) + " cells, but the header (line " + std::to_string(header_line_) +
							   ") has " + std::to_string(columns_.size()) + " columns");
			for (std::size_t c = 0; c < ncells; c++) cells_[c] = quoted_cells_[c];
		}
		else
		{
			for (const char* p = l.data(); (p = static_cast<const char*>(std::memchr(p, delim, l.data() + l.size() - p)));)
			{
				ncells++;
				p++;
			}
			if (ncells != columns_.size())
				fail(line, std::to_string(ncells) + " cells, but the header (line " + std::to_string(header_line_) +
							   ") has " + std::to_string(columns_.size()) + " columns");
			std::size_t start = 0;
			for (std::size_t c = 0; c < ncells; c++)
			{
				std::size_t comma = l.find(delim, start);
				if (comma == std::string::npos) comma = l.size();
				cells_[c] = trimView(std::string_view(l).substr(start, comma - start));
				start = comma + 1;
			}
		}
		x.table_rate_dph = x.field_uT = x.power = kNaN;
		x.rate_dph = {kNaN, kNaN, kNaN};
		double t = kNaN;
		int empty_rate_col = -1;  // first rate column with an empty cell (gyro off), -1 when none
		x.temp_C.assign(s_.thermistors.size(), kNaN);
		for (std::size_t c = 0; c < ncells; c++)
		{
			const Column& col = columns_[c];
			const std::string_view cell = cells_[c];
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
					const double v = col.toNative(number(cell, line, c));
					if (!std::isfinite(v)) failCell(line, c, "value '" + shown(cell) + "' is not finite");
					if (col.kind == Column::Kind::Rate && std::abs(v) > limits_.max_abs_rate_dph)
						failCell(line, c, "rate " + shown(cell) + " deg/h is beyond the limit of " +
											  io::formatNumber(limits_.max_abs_rate_dph) + " deg/h (no gyro measures that)");
					(col.kind == Column::Kind::Time ? t : x.rate_dph[col.index]) = v;
					break;
				}
				case Column::Kind::Temp:
				case Column::Kind::TableRate:
				case Column::Kind::Field:
				{
					double v = kNaN;  // empty = missing reading (dropout)
					if (!cell.empty())
					{
						v = col.toNative(number(cell, line, c));
						if (std::isinf(v)) failCell(line, c, "value '" + shown(cell) + "' is infinite");
						if (col.kind == Column::Kind::TableRate && std::abs(v) > limits_.max_abs_rate_dph)
							failCell(line, c, "table rate " + shown(cell) + " deg/h is beyond the limit of " +
												  io::formatNumber(limits_.max_abs_rate_dph) + " deg/h");
						if (col.kind == Column::Kind::Field && std::abs(v) > limits_.max_abs_field_uT)
							failCell(line, c, "applied field " + shown(cell) + " uT is beyond the limit of " +
												  io::formatNumber(limits_.max_abs_field_uT) +
												  " uT (no gyro test applies that)");
					}
					if (col.kind == Column::Kind::Temp) x.temp_C[col.index] = v;
					else (col.kind == Column::Kind::TableRate ? x.table_rate_dph : x.field_uT) = v;
					break;
				}
				case Column::Kind::Power:
				{
					if (cell.empty()) failCell(line, c, "empty cell (power must be 1 or 0)");
					const double v = number(cell, line, c);
					if (v != 0.0 && v != 1.0) failCell(line, c, "power must be 1 (on) or 0 (off), not '" + shown(cell) + "'");
					x.power = v;
					break;
				}
				case Column::Kind::Ignored: break;
			}
		}
		if (power_from_empty_rate_) x.power = empty_rate_col >= 0 ? 0.0 : 1.0;
		if (empty_rate_col >= 0 && x.power != 0.0)
			failCell(line, static_cast<std::size_t>(empty_rate_col),
					 has_power_ ? "empty cell with the gyro powered (a rate may be empty only where power is 0)"
								: "empty cell (only temperatures may be missing; a rate may be empty only on a "
								  "power-off row, power 0)");
		if (samples > 0 && !(t > last_t_))
		{
			const std::string prev = io::formatNumber(last_t_);
			fail(line, "column " + std::to_string(time_col_ + 1) + " (" + columns_[time_col_].name + "): time " + io::formatNumber(t) + " s " +
						   (t == last_t_ ? "duplicates the previous sample's time" : "goes backwards from the previous sample's") +
						   " (" + prev + " s); time_s must be strictly increasing");
		}
		last_t_ = t;
		x.time_s = t;
	}

	std::string path_;
	ReadLimits limits_;
	const LogFormat* format_ = nullptr;  // nullptr: the native CSV format
	io::GzReader in_;
	char delim_ = ',';
	std::vector<std::string> quoted_cells_;
	std::vector<std::string> notes_;
	std::size_t time_col_ = 0;
	std::string line_;
	std::map<std::string, std::pair<ThermistorInfo, std::size_t>> declared_;
	std::vector<Column> columns_;
	std::vector<std::string_view> cells_;
	std::size_t header_line_ = 0;
	bool has_table_ = false, has_field_ = false, has_power_ = false;
	bool compensated_ = false;  // fog-compensate's CSV
	bool power_from_empty_rate_ = false;  // its power column: 0 where the compensated rate is empty
	std::string compensation_details_;  // its raw, bias and flags columns (ignored)
	double last_t_ = 0;
	FogSeries s_;  // layout being built from the header
};

}  // namespace

std::unique_ptr<FogLogReader::Impl> makeCsvReaderImpl(const std::string& path, const ReadLimits& limits,
														const LogFormat* format)
{
	return std::make_unique<CsvReaderImpl>(path, limits, format);
}

FogSeries readFogCsv(const std::string& path)
{
	FogLogReader reader(path);
	return readAllSamples(reader);
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
	FogLogWriter w(path, layoutOf(series));
	FogSample x;
	for (std::size_t k = 0; k < series.size(); k++) w.write(sampleOf(series, k, x));
	w.close();
}

}  // namespace mrpt_fog
