/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogSeries.h
 * A FOG log in columns: what a thermal-chamber or vehicle run records, in the units FOG
 * engineers use (time in s, rate in deg/h, temperature in degC). This is the form the model,
 * metrics and simulator work on; CObservationFOG is the per-sample MRPT form of the same data
 * (see obs/FogSeriesConversion.h). A NaN temperature is a missing reading (thermistor dropout),
 * never a real 0 degC. A power-off row (power 0) keeps its thermistor readings but may have no
 * gyro sample: its rate is NaN (only there); the row where power returns is a turn-on event.
 */

#include <array>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

namespace mrpt_fog
{
/** Where a thermistor sits on the fiber coil. */
enum class CoilSide : unsigned char
{
	Inner = 0,
	Outer = 1,
	Other = 2
};

/** "inner" / "outer" / "other". */
const char* toString(CoilSide side);
/** Parses "inner" / "outer" / "other" (case-insensitive); throws std::invalid_argument. */
CoilSide coilSideFromString(const std::string& text);

/** Metadata of one thermistor glued on the coil. */
struct ThermistorInfo
{
	std::string name;  //!< e.g. "Ti1"; letters, digits and '_' only (it becomes a CSV column)
	CoilSide side = CoilSide::Other;
	double angle_deg = 0.0;  //!< angular position on the coil [deg]

	bool operator==(const ThermistorInfo& o) const
	{
		return name == o.name && side == o.side && angle_deg == o.angle_deg;
	}
};

/** Gyro sensitive axes. */
enum class GyroAxis : unsigned char
{
	X = 0,
	Y = 1,
	Z = 2
};
/** 'x', 'y' or 'z'. */
char axisLetter(GyroAxis axis);

/** A FOG run in columns. All filled columns have size() samples. */
struct FogSeries
{
	std::string sensor_label = "FOG";
	/** UNIX time [s] of time_s == 0 (rawlog timestamps are epoch_s + time_s). */
	double epoch_s = 0.0;
	std::vector<ThermistorInfo> thermistors;
	/** Which sensitive axes are present (at least one). */
	std::array<bool, 3> has_axis{{false, false, true}};

	std::vector<double> time_s;  //!< strictly increasing [s]
	/** Gyro output per axis [deg/h]; rate_dph[a] is empty when axis a is absent. NaN only on
	 * a power-off row (power 0): no gyro sample there. */
	std::array<std::vector<double>, 3> rate_dph;
	/** temp_C[i][k]: thermistor i at sample k [degC]; NaN = dropout. */
	std::vector<std::vector<double>> temp_C;

	// Optional lab columns: empty when absent.
	std::vector<double> table_rate_dph;  //!< applied table rate about the sensitive axis [deg/h]
	std::vector<double> field_uT;  //!< applied axial magnetic field [uT]
	std::vector<double> power;  //!< 1 = gyro powered, 0 = off (rates may be NaN there)

	/** Free `key: value` metadata (CSV `# key: value` lines); unknown keys are kept. */
	std::vector<std::pair<std::string, std::string>> metadata;

	std::size_t size() const { return time_s.size(); }
	bool empty() const { return time_s.empty(); }
	std::size_t thermistorCount() const { return thermistors.size(); }

	/** Index of the thermistor with this name, or -1 when absent. */
	int thermistorIndex(const std::string& name) const;

	/** First present axis (the one single-axis tools use). Throws if none. */
	GyroAxis primaryAxis() const;
	/** Rate column of the primary axis [deg/h]. */
	const std::vector<double>& primaryRate_dph() const;

	/** True when the gyro is powered at sample k (no power column: always). */
	bool gyroOn(std::size_t k) const { return power.empty() || power[k] != 0.0; }
	/** Turn-on events: indices k > 0 where power is 1 after a 0 at k - 1 (a run that starts
	 * powered has no event at 0: when it was switched on is unknown). */
	std::vector<std::size_t> turnOnSamples() const;

	/** Metadata value for key, or `fallback` when absent. */
	std::string metadataValue(const std::string& key, const std::string& fallback = {}) const;
	/** Sets (replaces) a metadata value. */
	void setMetadata(const std::string& key, const std::string& value);

	/** Resizes every present column to n samples (new temperatures NaN, rates 0). */
	void resize(std::size_t n);

	/** Appends sample k of `other` (same layout) to this series. */
	void appendSampleFrom(const FogSeries& other, std::size_t k);

	/** Checks the invariants: at least one axis, column sizes, strictly increasing finite
	 * time, finite rates (NaN allowed only where power is 0), unique valid thermistor names. Throws std::invalid_argument naming
	 * the first violation (column and sample index). */
	void validate() const;

	/** Same layout (thermistor names/sides/angles and axes) as another series. */
	bool sameLayout(const FogSeries& other) const;
};

/** True when `name` is a valid thermistor name ([A-Za-z0-9_]+). */
bool isValidThermistorName(const std::string& name);

}  // namespace mrpt_fog
