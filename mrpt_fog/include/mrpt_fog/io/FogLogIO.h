/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogLogIO.h
 * Reading and writing FOG logs: MRPT rawlogs (gz-compressed, MRPT's format) of
 * CObservationFOG streams, and lab CSV files (format in README.md, "CSV format").
 *
 * Readers never stop silently: a truncated or partially unreadable file throws FogIoError
 * saying what was read, where it stopped and why. Writers are atomic (temporary file +
 * rename): on failure nothing is left under the requested name and a previous file there is
 * intact. */

#include <mrpt/obs/CObservation.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/obs/FogRun.h>
#include <mrpt_fog/obs/FogSeries.h>

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mrpt_fog
{
/** A read/write failure with a one-line message naming the file (and line/column or object
 * index where it applies). */
class FogIoError : public std::runtime_error
{
   public:
	using std::runtime_error::runtime_error;
};

/** What a rawlog holds: one FOG sensor's series plus every other observation, untouched. */
struct FogRawlogContents
{
	FogSeries fog;  //!< the CObservationFOG stream of the selected sensor label
	/** All other observations (odometry, IMU, ground truth, other FOG labels...) in file order. */
	std::vector<mrpt::obs::CObservation::Ptr> others;
	std::size_t objects_read = 0;  //!< total objects in the file
};

/** Reads a rawlog. fog_label selects the FOG sensor ("" = the only one present; throws if
 * several labels are present and none is selected, or if the label is absent). Observations
 * inside CSensoryFrame objects are unpacked; a CActionCollection (actions format) throws.
 * The sensor's metadata comment written by writeFogRawlog (see io/FogRawlogMetadata.h) gives
 * epoch_s and metadata; without it epoch_s is the first timestamp's whole second. time_s is
 * exact to MRPT's 100 ns tick. The whole file is checked: an unknown class, an object cut
 * short, a truncated/corrupt gzip stream or a FOG stream with non-increasing times throws
 * FogIoError saying how many objects were read, where it stopped (object index, byte offset)
 * and why. (The gyro's sensorPose is not part of FogSeries and is not returned.) */
FogRawlogContents readFogRawlog(const std::string& path, const std::string& fog_label = "");

/** Writes a rawlog (gz-compressed, observations-only format): a metadata CObservationComment,
 * then the FOG series as CObservationFOG objects merged by timestamp with `others` (which are
 * written untouched; on equal timestamps the FOG sample comes first). Timestamps are
 * epoch_s + time_s rounded to 100 ns. Atomic; an invalid series throws FogIoError. */
void writeFogRawlog(const std::string& path, const FogSeries& fog,
					const std::vector<mrpt::obs::CObservation::Ptr>& others = {});

/** Reads a lab CSV file (.csv, or gz-compressed .csv.gz; CRLF accepted). Format in
 * docs/io.md. `# sensor:` and `# epoch_s:` fill sensor_label and epoch_s; `# thermistor` lines
 * the thermistor metadata; every other `# key: value` line (latitude_deg, unknown keys) is kept
 * in FogSeries::metadata. Empty temperature/table_rate/field cells are NaN (dropouts). Any
 * defect throws FogIoError naming file, line and column (see docs/io.md for the list). */
FogSeries readFogCsv(const std::string& path);

/** Writes a lab CSV file (gz-compressed when the name ends in .gz). Numbers are printed in the
 * shortest form that reads back to the same double; NaN is an empty cell. Atomic; an invalid
 * series throws FogIoError. */
void writeFogCsv(const std::string& path, const FogSeries& series);

/** Reads by extension: .rawlog -> readFogRawlog(path, fog_label).fog; .csv/.csv.gz -> CSV; with
 * options.format every other file is read through the format file. options.notice gets the
 * notes and the unit findings (FogLogReader.h). */
FogSeries readFogLog(const std::string& path, const std::string& fog_label = "", const LogReadOptions& options = {});

/** Reads a log by extension into a FogRun spilled to an unlinked temporary file (obs/FogRun.h,
 * common/RowSpill.h): the same samples and checks as readFogLog() (the series' invariants are
 * checked chunk by chunk), with memory that does not grow with the log; observations of other
 * sensors are dropped. `each` (optional) sees, and may change, every sample before it is stored
 * (e.g. the thermistor screening); it receives the sample's time and its thermistor_count
 * temperatures. `progress` (optional) is called after every sample with the samples read, the
 * file bytes consumed and the file's size (0 when unknown), for a progress line. `options`: the
 * format file and the notices (FogLogReader.h). */
FogRun readFogRun(const std::string& path, const std::string& fog_label = "",
				  const std::function<void(double time_s, double* temp_C, std::size_t thermistor_count)>& each = {},
				  const std::function<void(std::uint64_t samples, std::uint64_t bytes_done, std::uint64_t bytes_total)>&
					  progress = {},
				  const LogReadOptions& options = {});

/** Writes by extension (.rawlog or .csv/.csv.gz). */
void writeFogLog(const std::string& path, const FogSeries& series);

// ---- Lower-level rawlog pieces (used by writeFogRawlog and by programs writing other layouts)

/** The objects writeFogRawlog() writes for a series: a metadata CObservationComment (see
 * io/FogRawlogMetadata.h) followed by one CObservationFOG per sample, timestamps exact to MRPT's
 * 100 ns tick (epoch_s + time_s). Throws std::invalid_argument if the series is invalid. */
std::vector<mrpt::obs::CObservation::Ptr> fogObservationsForRawlog(const FogSeries& fog);

/** Stock-MRPT form of a series, readable without the mrpt_fog plugin: per sample a
 * CObservationIMU (label = sensor label; rates in IMU_WX/WY/WZ [rad/s], mean valid temperature
 * in IMU_TEMPERATURE [degC]) followed by a CObservationRawDAQ ("<label>_THERMISTORS", one
 * AIN_double channel per thermistor [degC], NaN = dropout). */
std::vector<mrpt::obs::CObservation::Ptr> stockObservationsForRawlog(const FogSeries& fog);

/** Two time-ordered observation lists merged by timestamp (stable: on equal timestamps `a`
 * comes first; each list keeps its own order). */
std::vector<mrpt::obs::CObservation::Ptr> mergeByTimestamp(const std::vector<mrpt::obs::CObservation::Ptr>& a,
														   const std::vector<mrpt::obs::CObservation::Ptr>& b);

/** Writes observations in this order as a gz-compressed observations-only rawlog. Atomic;
 * throws FogIoError naming the file. */
void writeRawlogObservations(const std::string& path, const std::vector<mrpt::obs::CObservation::Ptr>& objs);

}  // namespace mrpt_fog
