/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file FogLogWriter.h
 * Streaming writer of a FOG log, sample by sample (memory does not grow with the log), by the
 * output's extension: .csv / .csv.gz (lab CSV) or .rawlog (metadata comment, then one
 * CObservationFOG per sample; or, with RawlogForm::Stock, a CObservationIMU +
 * CObservationRawDAQ per sample, readable without the plugin). Atomic (common/AtomicFile.h):
 * nothing appears under the output's name before close(); an exception, or destruction without
 * close(), leaves a previous file intact. Write errors keep their reason (e.g. "No space left on
 * device"). A sample that breaks the series' invariants (time not strictly increasing, or, in a
 * rawlog, less than MRPT's 100 ns tick after the previous one; non-finite rate with the power
 * on; infinite temperature) throws FogIoError naming the output and the sample. */

#include <mrpt/obs/CObservation.h>
#include <mrpt_fog/io/FogLogReader.h>

#include <memory>
#include <string>

namespace mrpt_fog
{
enum class RawlogForm
{
	Fog,  //!< mrpt_fog::CObservationFOG per sample (after a metadata CObservationComment)
	Stock  //!< CObservationIMU + CObservationRawDAQ per sample (stock MRPT classes)
};

class FogLogWriter
{
   public:
	/** `layout`: sensor_label, epoch_s, thermistors, has_axis, metadata; an optional column
	 * (table_rate_dph, field_uT, power) is written when non-empty in `layout` (see
	 * FogLogReader::header()). Throws FogIoError (unknown extension, metadata that does not fit
	 * one line, output not creatable). */
	FogLogWriter(const std::string& path, const FogSeries& layout, RawlogForm form = RawlogForm::Fog);
	~FogLogWriter();
	FogLogWriter(const FogLogWriter&) = delete;
	FogLogWriter& operator=(const FogLogWriter&) = delete;

	void write(const FogSample& sample);
	/** Rawlog only: writes another observation as it is, here (the caller keeps file order). */
	void writeOther(const mrpt::obs::CObservation& obs);
	/** Finishes the file and renames it into place. */
	void close();

	std::size_t samplesWritten() const;
	std::size_t objectsWritten() const;  //!< rawlog objects (metadata comment included)

	class Impl;

   private:
	std::unique_ptr<Impl> impl_;
};

}  // namespace mrpt_fog
