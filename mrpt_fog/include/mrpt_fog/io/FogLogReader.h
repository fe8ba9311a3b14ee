/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogLogReader.h
 * Streaming reader of a FOG log (.rawlog, .csv, .csv.gz), sample by sample: memory does not
 * grow with the log (readFogLog() builds on it to return a whole FogSeries). The same checks as
 * the whole-file readers: every defect throws FogIoError naming the file and line (CSV) or
 * object index (rawlog), an early stop (truncated gzip, object cut short, unknown class) says
 * how many objects were read; times must be strictly increasing.
 *
 * Input limits (ReadLimits), each failing early with the limit named: line length, thermistor
 * count (so the number of columns), and plausible numbers: |rate| and |table rate| <=
 * max_abs_rate_dph, |applied field| <= max_abs_field_uT (a cell beyond is refused, naming the file,
 * line or object and the column). Temperatures: infinite is refused; implausible finite
 * readings are left to the thermistor screening (ThermistorHealth.h: dropout) and the
 * out-of-calibrated-range warning of the programs.
 *
 * Rawlog: the FOG sensor is `fog_label`, or the first FOG label met when empty (a second FOG
 * label is then an error asking for --label). Every other observation (other sensors, other FOG
 * labels when a label is chosen, comments) goes to the `others` callback in file order, or is
 * dropped when none is set. The sensor's metadata comment (io/FogRawlogMetadata.h) must come
 * before its first sample to be used (writeFogRawlog puts it first); without it epoch_s is the
 * whole second of the first timestamp. */

#include <mrpt/obs/CObservation.h>
#include <mrpt_fog/obs/FogSeriesLayout.h>  // FogSeries, emptySeriesLike
#include <mrpt_fog/obs/Units.h>

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** Limits on what a reader accepts. */
struct ReadLimits
{
	std::size_t max_line_bytes = 1u << 20;  //!< a CSV line (metadata, header or row)
	std::size_t max_thermistors = 64;  //!< per sensor (screening costs n^2 per sample)
	/** |gyro rate| [deg/h]: 1e8 deg/h = 27 800 deg/s, beyond any gyro's range. */
	double max_abs_rate_dph = 1e8;
	/** |applied axial field| [uT] (units::kMaxAbsField_uT, 10 mT; MagneticModel.h bounds a
	 * magnetic term's contribution with it). */
	double max_abs_field_uT = units::kMaxAbsField_uT;
};

/** One sample of a FOG log, in the reader's layout (FogLogReader::header()). */
struct FogSample
{
	double time_s = 0;
	std::array<double, 3> rate_dph{{0, 0, 0}};  //!< NaN for absent axes and power-off samples
	std::vector<double> temp_C;  //!< header().thermistors order; NaN = dropout
	double table_rate_dph = std::numeric_limits<double>::quiet_NaN();  //!< NaN when absent
	double field_uT = std::numeric_limits<double>::quiet_NaN();
	double power = std::numeric_limits<double>::quiet_NaN();  //!< 1 / 0; NaN when absent
};

struct LogFormat;
struct UnitFinding;

/** What a reader reports besides samples: a note (columns a format file leaves unmapped) or a
 * unit finding (io/UnitPlausibility.h), with the log's path. */
struct LogNotice
{
	enum class Kind
	{
		Note,
		UnitWarning
	} kind = Kind::Note;
	std::string path;
	std::string message;  //!< one line, without the path
};

/** How logs are read. */
struct LogReadOptions
{
	/** Logs that are not rawlogs are read through this format file (io/LogFormat.h), whatever
	 * their extension; nullptr: the native CSV format (.csv, .csv.gz). */
	std::shared_ptr<const LogFormat> format;
	/** Gets every notice: notes when the header is read, unit findings when the log has been
	 * read to its end (at the first next() that returns false). Unset: notices are dropped. */
	std::function<void(const LogNotice&)> notice;
};

class FogLogReader
{
   public:
	using ObservationSink = std::function<void(const mrpt::obs::CObservation::Ptr&)>;

	/** Opens the log and reads up to its first sample (metadata, header). Throws FogIoError. */
	explicit FogLogReader(const std::string& path, const std::string& fog_label = "", const ReadLimits& limits = {},
						  ObservationSink others = nullptr, const LogReadOptions& options = {});
	~FogLogReader();
	FogLogReader(const FogLogReader&) = delete;
	FogLogReader& operator=(const FogLogReader&) = delete;

	/** Layout and metadata of the log: sensor_label, epoch_s, thermistors, has_axis, metadata;
	 * the optional columns present have one element (NaN) so that !table_rate_dph.empty() etc.
	 * say which are present. No samples. */
	const FogSeries& header() const;
	bool hasTableRate() const;
	bool hasField() const;
	bool hasPower() const;

	/** The next sample; false at the (checked) end of the log. */
	bool next(FogSample& sample);

	/** Notes on the header (columns a format file does not map). */
	std::vector<std::string> notes() const;
	/** Findings on the units of the samples read so far (io/UnitPlausibility.h). */
	std::vector<UnitFinding> unitFindings() const;

	std::size_t samplesRead() const;
	std::size_t objectsRead() const;  //!< rawlog objects so far (0 for CSV)
	bool isRawlog() const;
	/** Progress: bytes of the file consumed so far, and its size (0 when unknown, e.g. a pipe). */
	std::uint64_t fileBytesRead() const;
	std::uint64_t fileBytes() const;

	class Impl;

   private:
	std::unique_ptr<Impl> impl_;
	std::string path_;
	LogReadOptions options_;
	struct Judge;
	std::unique_ptr<Judge> judge_;
	bool ended_ = false;
};

/** Appends a sample read by `reader` to a series of the reader's layout (emptySeriesLike). */
void appendSample(FogSeries& series, const FogSample& sample, const FogLogReader& reader);

/** Every remaining sample of the reader as a series (columns of exact size; peak memory about
 * the series plus one column). */
FogSeries readAllSamples(FogLogReader& reader);

}  // namespace mrpt_fog
