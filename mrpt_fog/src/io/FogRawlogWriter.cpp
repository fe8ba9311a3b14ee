/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogWriter.h>
#include <mrpt_fog/io/GzStream.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/common/ErrorText.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>

#include <cmath>

#include "FogLogReaderImpl.h"
#include "RawlogCommon.h"

namespace mrpt_fog
{
using io::detail::fromTicks;
using io::detail::kTicksPerSecond;
using io::detail::ticksOf;

std::vector<mrpt::obs::CObservation::Ptr> fogObservationsForRawlog(const FogSeries& fog)
{
	std::vector<mrpt::obs::CObservation::Ptr> out;
	out.reserve(fog.size() + 1);
	const int64_t epoch_ticks = ticksOf(mrpt::Clock::fromDouble(fog.epoch_s));
	auto comment = mrpt::obs::CObservationComment::Create();
	comment->sensorLabel = fog.sensor_label + "_METADATA";
	comment->text = io::formatFogRawlogMetadata(fog);
	out.push_back(comment);
	for (auto& o : observationsFromSeries(fog))
	{
		out.push_back(o);
	}
	for (std::size_t k = 0; k < fog.size(); k++)
		out[k + 1]->timestamp = fromTicks(epoch_ticks + std::llround(fog.time_s[k] * kTicksPerSecond));
	comment->timestamp = fog.empty() ? fromTicks(epoch_ticks) : out[1]->timestamp;
	return out;
}

void writeRawlogObservations(const std::string& path, const std::vector<mrpt::obs::CObservation::Ptr>& objs)
{
	try
	{
		AtomicOutput out(path);
		io::GzWriter gz(out.writePath(), true, 1, path);
		auto arch = mrpt::serialization::archiveFrom(static_cast<mrpt::io::CStream&>(gz));
		for (const auto& o : objs) arch << *o;
		gz.close();
		out.commit();
	}
	catch (const FogIoError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + oneLineErrorMessage(e.what()));
	}
}

std::vector<mrpt::obs::CObservation::Ptr> mergeByTimestamp(const std::vector<mrpt::obs::CObservation::Ptr>& a,
														   const std::vector<mrpt::obs::CObservation::Ptr>& b)
{
	std::vector<mrpt::obs::CObservation::Ptr> out;
	out.reserve(a.size() + b.size());
	std::size_t i = 0, j = 0;
	while (i < a.size() || j < b.size())
	{
		if (j == b.size() || (i < a.size() && !(b[j]->timestamp < a[i]->timestamp))) out.push_back(a[i++]);
		else out.push_back(b[j++]);
	}
	return out;
}

FogSeries layoutOf(const FogSeries& s)
{
	FogSeries h = emptySeriesLike(s);
	if (!s.table_rate_dph.empty()) h.table_rate_dph.assign(1, NAN);
	if (!s.field_uT.empty()) h.field_uT.assign(1, NAN);
	if (!s.power.empty()) h.power.assign(1, NAN);
	return h;
}

FogSample sampleOf(const FogSeries& s, std::size_t k, FogSample& x)
{
	x.time_s = s.time_s[k];
	for (int a = 0; a < 3; a++) x.rate_dph[a] = s.has_axis[a] ? s.rate_dph[a][k] : NAN;
	x.temp_C.resize(s.temp_C.size());
	for (std::size_t i = 0; i < s.temp_C.size(); i++) x.temp_C[i] = s.temp_C[i][k];
	x.table_rate_dph = s.table_rate_dph.empty() ? NAN : s.table_rate_dph[k];
	x.field_uT = s.field_uT.empty() ? NAN : s.field_uT[k];
	x.power = s.power.empty() ? NAN : s.power[k];
	return x;
}

void writeFogRawlog(const std::string& path, const FogSeries& fog, const std::vector<mrpt::obs::CObservation::Ptr>& others)
{
	try
	{
		fog.validate();
		io::requireOneLineMetadata(fog);
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + oneLineErrorMessage(e.what()));
	}
	for (std::size_t i = 0; i < others.size(); i++)
		if (!others[i]) throw FogIoError(path + ": cannot write: other observation #" + std::to_string(i) + " is null");
	// The metadata comment heads the file; then FOG samples (one at a time: memory stays flat
	// for long runs) and the others merged by time, FOG first on equal timestamps.
	const int64_t epoch_ticks = ticksOf(mrpt::Clock::fromDouble(fog.epoch_s));
	auto fogTime = [&](std::size_t k) { return fromTicks(epoch_ticks + std::llround(fog.time_s[k] * kTicksPerSecond)); };
	FogLogWriter w(path, layoutOf(fog));
	FogSample x;
	std::size_t k = 0, j = 0;
	while (k < fog.size() || j < others.size())
	{
		if (j == others.size() || (k < fog.size() && !(others[j]->timestamp < fogTime(k))))
			w.write(sampleOf(fog, k++, x));
		else
			w.writeOther(*others[j++]);
	}
	w.close();
}

}  // namespace mrpt_fog
