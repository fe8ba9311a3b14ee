/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/* Internal to the io room: the two streaming readers behind FogLogReader. */

#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/io/LogFormat.h>

#include <memory>

namespace mrpt_fog
{
class FogLogReader::Impl
{
   public:
	virtual ~Impl() = default;
	virtual bool next(FogSample& s) = 0;
	virtual std::size_t objectsRead() const { return 0; }
	virtual bool isRawlog() const = 0;
	virtual std::uint64_t fileBytesRead() const = 0;
	virtual std::uint64_t fileBytes() const = 0;
	virtual std::vector<std::string> notes() const { return {}; }
	FogSeries header;  // layout; optional columns present hold one NaN
	std::size_t samples = 0;
};

std::unique_ptr<FogLogReader::Impl> makeCsvReaderImpl(const std::string& path, const ReadLimits& limits,
														const LogFormat* format = nullptr);
std::unique_ptr<FogLogReader::Impl> makeRawlogReaderImpl(const std::string& path, const std::string& fog_label,
														 const ReadLimits& limits, FogLogReader::ObservationSink others);

/** The layout of a series as a writer's `layout` argument (optional columns: one NaN). */
FogSeries layoutOf(const FogSeries& s);
/** Sample k of a series into x (returned). */
FogSample sampleOf(const FogSeries& s, std::size_t k, FogSample& x);

namespace io::detail
{
/** A cell or value for an error message: at most 40 bytes (then "... (N bytes)"), bytes that
 * are not printable ASCII written as \xNN. */
std::string quoteForError(const char* data, std::size_t size);
}  // namespace io::detail
}  // namespace mrpt_fog
