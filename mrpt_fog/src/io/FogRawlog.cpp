/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/io/GzFile.h>
#include <mrpt_fog/io/NumberText.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <cmath>
#include <map>
#include <set>

namespace mrpt_fog
{
namespace
{
/** First line of an (MRPT, multi-line) exception message. */
std::string firstLine(const std::string& what)
{
	std::string s = what;
	const auto nl = s.find('\n');
	if (nl != std::string::npos) s = s.substr(0, nl);
	while (!s.empty() && (s.back() == ' ' || s.back() == '\r')) s.pop_back();
	return s;
}

/** The reason a deserialization failed, in words. */
std::string whyReadFailed(const std::string& what, bool at_end_of_data)
{
	const auto p = what.find("Stored object has class '");
	if (p != std::string::npos)
	{
		const auto b = p + 25;
		const auto e = what.find('\'', b);
		return "unknown class '" + what.substr(b, e - b) +
			   "' (not registered in MRPT's RTTI: a plugin library missing, or a corrupt class name)";
	}
	if (at_end_of_data) return "the file ends in the middle of this object (truncated)";
	return "corrupt object: " + firstLine(what);
}

std::string labelList(const std::map<std::string, std::size_t>& counts)
{
	std::string s;
	for (const auto& [label, n] : counts) s += (s.empty() ? "'" : ", '") + label + "' (" + std::to_string(n) + ")";
	return s;
}

int64_t ticksOf(mrpt::Clock::time_point t) { return t.time_since_epoch().count(); }
mrpt::Clock::time_point fromTicks(int64_t ticks) { return mrpt::Clock::time_point(mrpt::Clock::duration(ticks)); }
/** MRPT timestamps are 100 ns ticks. */
constexpr double kTicksPerSecond = 1e7;

}  // namespace

FogRawlogContents readFogRawlog(const std::string& path, const std::string& fog_label)
{
	registerAllClasses_mrpt_fog();
	const std::string bytes = io::readWholeFile(path);
	if (bytes.empty()) throw FogIoError(path + ": empty rawlog (0 objects)");

	// 1) Every object, observations unpacked from sensory frames, in file order.
	std::vector<mrpt::obs::CObservation::Ptr> all;
	std::size_t objects = 0;
	{
		mrpt::io::CMemoryStream mem;
		mem.assignMemoryNotOwn(bytes.data(), bytes.size());
		auto arch = mrpt::serialization::archiveFrom(mem);
		while (mem.getPosition() < bytes.size())
		{
			const uint64_t offset = mem.getPosition();
			mrpt::serialization::CSerializable::Ptr obj;
			try
			{
				obj = arch.ReadObject();
			}
			catch (const std::exception& e)
			{
				throw FogIoError(path + ": read " + std::to_string(objects) + " objects, then stopped at object #" +
								 std::to_string(objects) + " (byte offset " + std::to_string(offset) +
								 " of the decompressed data, " + std::to_string(bytes.size()) + " bytes in all): " +
								 whyReadFailed(e.what(), mem.getPosition() >= bytes.size()));
			}
			if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) all.push_back(o);
			else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
			{
				for (const auto& so : *sf) all.push_back(so);
			}
			else if (std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(obj))
				throw FogIoError(path + ": object #" + std::to_string(objects) + " (byte offset " + std::to_string(offset) +
								 ") is a CActionCollection: rawlogs with actions (sensory-frame format) are not supported; "
								 "use the observations-only format");
			else
				throw FogIoError(path + ": object #" + std::to_string(objects) + " (byte offset " + std::to_string(offset) +
								 ") is a " + (obj ? obj->GetRuntimeClass()->className : "null object") +
								 ", not an observation");
			objects++;
		}
	}

	// 2) Which FOG sensor.
	std::map<std::string, std::size_t> fog_counts;
	for (const auto& o : all)
		if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o)) fog_counts[f->sensorLabel]++;
	std::string label = fog_label;
	if (label.empty())
	{
		if (fog_counts.empty())
			throw FogIoError(path + ": no CObservationFOG in the file (" + std::to_string(objects) + " objects read)");
		if (fog_counts.size() > 1)
			throw FogIoError(path + ": several FOG sensors " + labelList(fog_counts) + "; choose one by its label (fog-convert --label L)");
		label = fog_counts.begin()->first;
	}
	else if (!fog_counts.count(label))
		throw FogIoError(path + ": no FOG sensor labelled '" + label + "'" +
						 (fog_counts.empty() ? std::string(" (the file has no CObservationFOG)")
											 : " (present: " + labelList(fog_counts) + ")"));

	// 3) Split: the selected FOG stream, its metadata, everything else untouched.
	FogRawlogContents out;
	out.objects_read = objects;
	std::vector<CObservationFOG::Ptr> fog;
	std::optional<io::FogRawlogMetadata> meta;
	for (const auto& o : all)
	{
		auto f = std::dynamic_pointer_cast<CObservationFOG>(o);
		if (f && f->sensorLabel == label)
		{
			fog.push_back(f);
			continue;
		}
		if (auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(o); c && !meta)
			if (auto m = io::parseFogRawlogMetadata(c->text); m && m->sensor_label == label)
			{
				meta = m;
				continue;
			}
		out.others.push_back(o);
	}
	try
	{
		out.fog = seriesFromObservations(fog);
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": sensor '" + label + "': " + e.what());
	}
	// Exact times from the 100 ns ticks (a double of UNIX seconds only resolves ~0.2 us).
	if (meta)
	{
		out.fog.epoch_s = meta->epoch_s;
		out.fog.metadata = meta->metadata;
	}
	const int64_t epoch_ticks = ticksOf(mrpt::Clock::fromDouble(out.fog.epoch_s));
	for (std::size_t k = 0; k < fog.size(); k++)
		out.fog.time_s[k] = static_cast<double>(ticksOf(fog[k]->timestamp) - epoch_ticks) / kTicksPerSecond;
	try
	{
		out.fog.validate();
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": sensor '" + label + "': " + e.what());
	}
	return out;
}

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
	std::vector<mrpt::obs::CObservation::Ptr> fog_objs;
	try
	{
		fog_objs = fogObservationsForRawlog(fog);
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": cannot write: " + firstLine(e.what()));
	}
	for (std::size_t i = 0; i < others.size(); i++)
		if (!others[i]) throw FogIoError(path + ": cannot write: other observation #" + std::to_string(i) + " is null");
	// The metadata comment heads the file; then FOG samples and the others merged by time.
	std::vector<mrpt::obs::CObservation::Ptr> samples(fog_objs.begin() + 1, fog_objs.end());
	std::vector<mrpt::obs::CObservation::Ptr> objs{fog_objs.front()};
	for (auto& o : mergeByTimestamp(samples, others)) objs.push_back(o);
	writeRawlogObservations(path, objs);
}

}  // namespace mrpt_fog
