/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>

#include <cmath>

#include "RawlogCommon.h"

namespace mrpt_fog
{
using io::detail::firstLine;
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
		writeFileAtomically(path, [&](const std::string& tmp) {
			mrpt::io::CFileGZOutputStream out;
			std::string why;
			if (!out.open(tmp, 1, why)) throw FogIoError(path + ": cannot create: " + why);
			auto arch = mrpt::serialization::archiveFrom(out);
			for (const auto& o : objs) arch << *o;
			out.close();
		});
	}
	catch (const FogIoError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + firstLine(e.what()));
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

void writeFogRawlog(const std::string& path, const FogSeries& fog, const std::vector<mrpt::obs::CObservation::Ptr>& others)
{
	try
	{
		fog.validate();
		io::requireOneLineMetadata(fog);
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + firstLine(e.what()));
	}
	for (std::size_t i = 0; i < others.size(); i++)
		if (!others[i]) throw FogIoError(path + ": cannot write: other observation #" + std::to_string(i) + " is null");
	// The metadata comment heads the file; then FOG samples (made one at a time: memory stays
	// flat for long runs) and the others merged by time, FOG first on equal timestamps.
	const int64_t epoch_ticks = ticksOf(mrpt::Clock::fromDouble(fog.epoch_s));
	auto fogTime = [&](std::size_t k) { return fromTicks(epoch_ticks + std::llround(fog.time_s[k] * kTicksPerSecond)); };
	auto comment = mrpt::obs::CObservationComment::Create();
	comment->sensorLabel = fog.sensor_label + "_METADATA";
	comment->text = io::formatFogRawlogMetadata(fog);
	comment->timestamp = fog.empty() ? fromTicks(epoch_ticks) : fogTime(0);
	try
	{
		writeFileAtomically(path, [&](const std::string& tmp) {
			mrpt::io::CFileGZOutputStream out;
			std::string why;
			if (!out.open(tmp, 1, why)) throw FogIoError(path + ": cannot create: " + why);
			auto arch = mrpt::serialization::archiveFrom(out);
			arch << *comment;
			std::size_t k = 0, j = 0;
			while (k < fog.size() || j < others.size())
			{
				if (j == others.size() || (k < fog.size() && !(others[j]->timestamp < fogTime(k))))
				{
					auto o = observationFromSeries(fog, k);
					o->timestamp = fogTime(k++);
					arch << *o;
				}
				else
					arch << *others[j++];
			}
			out.close();
		});
	}
	catch (const FogIoError&)
	{
		throw;
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + firstLine(e.what()));
	}
}

}  // namespace mrpt_fog
