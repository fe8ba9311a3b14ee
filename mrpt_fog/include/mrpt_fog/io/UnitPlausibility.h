/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file UnitPlausibility.h
 * Whether a log's numbers fit the units it declares: a unit slip (deg/s under a deg/h column,
 * rad/s under deg/s, milliseconds under seconds, kelvin under Celsius) gives a calibration that
 * looks fine and is wrong by a constant factor, so it must never pass silently. Each check
 * compares the numbers with what any gyro or lab can produce, after conversion to the native
 * units (deg/h, s, degC):
 *  - rate noise: the per-sample noise (robust spread of sample-to-sample differences) as an
 *    angle random walk N = sigma x sqrt(dt) / 60 [deg/sqrt(h)]. Below 2e-5 deg/sqrt(h) no gyro
 *    made is that quiet (the best strategic-grade FOGs are near 1e-4); above 30 deg/sqrt(h) no
 *    gyro is that noisy (consumer MEMS are near 1);
 *  - rate table: the gyro's rate against the table's (least squares over the samples where the
 *    table turns at >= 100 deg/h) must have a slope of magnitude 0.5..2;
 *  - Earth rate: a three-axis gyro at rest sees Earth's 15.04 deg/h; a mean rate vector below
 *    0.15 deg/h over a log without table motion is too small for any unit-correct triad;
 *  - time: a median sample interval above 30 s or below 20 us is not a gyro log's;
 *  - temperature: a median thermistor reading above 150 degC (kelvin read as Celsius) or below
 *    -150 degC (Celsius read as kelvin).
 * A finding names the likely unit when a unit of the same quantity brings the numbers into the
 * plausible range (the smallest such change first, the other candidates listed), and says it
 * cannot tell otherwise. The checks look at the first 100 000 samples (noise, interval,
 * temperature) and at every sample (table, Earth rate); memory is bounded. */

#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/LogFormat.h>

#include <array>
#include <string>
#include <vector>

namespace mrpt_fog
{
enum class UnitQuantity
{
	Rate,
	Time,
	Temperature
};

/** One unit that the numbers contradict. */
struct UnitFinding
{
	UnitQuantity quantity = UnitQuantity::Rate;
	std::string column;  //!< the column as the log names it ("rate_z_dph", "Gyro Z [deg/s]")
	std::string declared_unit;  //!< "deg/h", "s", "C"
	std::string likely_unit;  //!< the likeliest unit, "" when no unit of the list fits
	std::vector<std::string> other_candidates;  //!< other units that would also fit
	std::string evidence;  //!< what the numbers show, one line
	/** One line: "<column>: declared <unit>, but <evidence>: likely <unit> (or ...)". */
	std::string message() const;
};

/** The units a log declares for its columns, and the columns' names (for messages). */
struct DeclaredUnits
{
	std::array<RateUnit, 3> rate{{RateUnit::deg_per_h, RateUnit::deg_per_h, RateUnit::deg_per_h}};
	std::array<std::string, 3> rate_column{{"rate_x_dph", "rate_y_dph", "rate_z_dph"}};
	RateUnit table_rate = RateUnit::deg_per_h;
	TimeUnit time = TimeUnit::s;
	std::string time_column = "time_s";
	TemperatureUnit temperature = TemperatureUnit::C;
	std::string temperature_column = "temp_<name>_C";

	/** The native units (deg/h, s, C) under the native column names. */
	static DeclaredUnits native() { return {}; }
	/** The units and column names of a format file. */
	static DeclaredUnits of(const LogFormat& format);
};

/** Accumulates samples (in native units) and judges them; see the file comment. */
class UnitPlausibility
{
   public:
	explicit UnitPlausibility(DeclaredUnits declared = DeclaredUnits::native());
	/** One sample; gyro_on false (a power-off row): its rates are left out. */
	void add(const FogSample& x, bool gyro_on = true);
	std::vector<UnitFinding> findings() const;

	static constexpr std::size_t kSampledRows = 100000;

   private:
	DeclaredUnits declared_;
	std::size_t rows_ = 0;
	double last_t_ = 0;
	std::array<double, 3> last_rate_{};
	std::array<bool, 3> has_last_{};
	std::array<std::vector<double>, 3> abs_diff_;  // |rate[k] - rate[k-1]|, first kSampledRows
	std::vector<double> dt_s_;
	std::vector<double> temp_C_;
	// Table regression per axis: sums over samples with |table| >= 100 deg/h.
	std::array<double, 3> n_{}, sx_{}, sy_{}, sxx_{}, sxy_{}, syy_{};
	// Mean rate vector over samples with the table at rest (or no table).
	std::array<double, 3> rest_sum_{};
	std::size_t rest_n_ = 0;
	std::array<bool, 3> seen_axis_{};
};

/** The findings on a whole series. */
std::vector<UnitFinding> judgeUnits(const FogSeries& series, const DeclaredUnits& declared = DeclaredUnits::native());

}  // namespace mrpt_fog
