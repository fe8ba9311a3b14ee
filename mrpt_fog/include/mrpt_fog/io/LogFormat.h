/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file LogFormat.h
 * A log format file: how a logger's own CSV (its delimiter, column names and units) maps onto a
 * FOG log, so that the file is read as it is, without renaming or converting by hand. The
 * schema (docs/reference/format-files.md):
 *
 *   delimiter: ";"                                   # optional: detected from the header line
 *   skip_lines: 0                                    # optional: lines before the header
 *   time: {column: "Time [ms]", unit: ms}            # s | ms | us | ns
 *   rates:                                           # any of x, y, z
 *     z: {column: "Gyro Z [deg/s]", unit: deg/s}     # deg/h | deg/s | rad/s | mdeg/s
 *   thermistors:                                     # your names -> columns
 *     Ti1: {column: "T coil in 1 [degC]", unit: C, side: inner, angle_deg: 0}   # C | K
 *   table_rate: {column: "Table [deg/s]", unit: deg/s}
 *   field: {column: "B [uT]", unit: uT}
 *   power: {column: "PWR"}                           # 1 on, 0 off
 *   metadata: {sensor: FOG_Z, latitude_deg: 0.0}     # what the native CSV's '#' lines carry
 *
 * Every value read through a format is converted to the native units (s, deg/h, degC, uT) as
 * it is read. A format is used by FogLogReader (and everything built on it) for every log that
 * is not a rawlog. */

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog
{
enum class TimeUnit
{
	s,
	ms,
	us,
	ns
};
enum class RateUnit
{
	deg_per_h,
	deg_per_s,
	rad_per_s,
	mdeg_per_s
};
enum class TemperatureUnit
{
	C,
	K
};

/** Spellings as in format files: "s", "ms", "us", "ns"; "deg/h", "deg/s", "rad/s", "mdeg/s";
 * "C", "K". fromString throws std::invalid_argument listing the choices. */
std::string toString(TimeUnit u);
std::string toString(RateUnit u);
std::string toString(TemperatureUnit u);
TimeUnit timeUnitFromString(const std::string& text);
RateUnit rateUnitFromString(const std::string& text);
TemperatureUnit temperatureUnitFromString(const std::string& text);

/** Seconds per unit (1, 1e-3, 1e-6, 1e-9). */
double secondsPer(TimeUnit u);
/** deg/h per unit (1, 3600, 3600 x 180/pi, 3.6). */
double degPerHourPer(RateUnit u);

/** One mapped column: its name in the file's header and the key of the format file that maps
 * it (e.g. "rates.z"), for messages. */
struct FormatColumn
{
	std::string column;
	std::string key;
};

struct RateColumn : FormatColumn
{
	RateUnit unit = RateUnit::deg_per_h;
};

struct ThermistorColumn : FormatColumn
{
	std::string name;  //!< the thermistor's name in the log (the format file's key)
	TemperatureUnit unit = TemperatureUnit::C;
	std::string side = "other";  //!< inner | outer | other
	double angle_deg = 0;
};

/** A parsed format file. */
struct LogFormat
{
	std::string source;  //!< the format file's path (or a name given to parseLogFormat), for messages
	std::optional<char> delimiter;  //!< absent: detected from the header line (',', ';', tab or '|')
	std::size_t skip_lines = 0;  //!< lines before the header line
	FormatColumn time;
	TimeUnit time_unit = TimeUnit::s;
	std::array<std::optional<RateColumn>, 3> rates;  //!< x, y, z
	std::vector<ThermistorColumn> thermistors;  //!< sorted by name; a log orders them by column
	std::optional<RateColumn> table_rate;
	std::optional<FormatColumn> field;  //!< uT
	std::optional<FormatColumn> power;  //!< 1 / 0
	/** metadata: key -> value as text ("sensor" -> the sensor label, "epoch_s", "latitude_deg",
	 * any other key kept in the log's metadata). */
	std::vector<std::pair<std::string, std::string>> metadata;

	/** Every mapped column in the format file's order (time, rates, thermistors, table, field,
	 * power). */
	std::vector<const FormatColumn*> columns() const;
};

/** Parses a format file's text. Throws std::invalid_argument "<source>: <key>: <what>" on an
 * unknown key, a missing column or unit, an unknown unit (the choices listed), a column
 * mapped twice (both keys named), an invalid thermistor name, side or number. */
LogFormat parseLogFormat(const std::string& yaml_text, const std::string& source);

/** Reads and parses a format file (size and nesting limited before parsing). Throws
 * std::invalid_argument naming the file. */
LogFormat readLogFormat(const std::string& path);

/** A draft format file for a logger CSV, from its header line: the delimiter, the lines before
 * the header, and each column's role and unit guessed from its name (bracketed units such as
 * "Gyro Z [deg/s]", "(ms)", suffixes such as "_dps", "_C"). Every guess is marked for the user
 * to check; columns it cannot place are listed as comments. Throws FogIoError when the file
 * cannot be read or has no header line. */
std::string guessLogFormat(const std::string& csv_path);

}  // namespace mrpt_fog
