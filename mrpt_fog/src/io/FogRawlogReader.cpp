/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/io/GzFile.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <algorithm>
#include <cmath>
#include <map>

#include "RawlogCommon.h"

namespace mrpt_fog
{
namespace
{
using io::detail::firstLine;
using io::detail::fromTicks;
using io::detail::kTicksPerSecond;
using io::detail::ticksOf;

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
	if (at_end_of_data)
		return "the file ends in the middle of this object (truncated file, or a corrupt length field in the object)";
	return "corrupt object: " + firstLine(what);
}

std::string labelList(const std::map<std::string, std::size_t>& counts)
{
	std::string s;
	for (const auto& [label, n] : counts) s += (s.empty() ? "'" : ", '") + label + "' (" + std::to_string(n) + ")";
	return s;
}

/** Builds one sensor's FogSeries sample by sample (times kept as ticks until the epoch is known). */
class FogAccumulator
{
   public:
	FogSeries series;
	std::vector<int64_t> ticks;

	std::size_t size() const { return ticks.size(); }

	/** Appends an observation; throws std::invalid_argument if its layout differs from the first. */
	void add(const CObservationFOG::Ptr& o)
	{
		if (!first_)
		{
			first_ = o;
			series = seriesFromObservations({o});
			ticks.push_back(ticksOf(o->timestamp));
			return;
		}
		const CObservationFOG& f = *first_;
		if (o->thermistors != f.thermistors || o->hasAxis != f.hasAxis || o->hasTableRate != f.hasTableRate ||
			o->hasField != f.hasField || o->hasPower != f.hasPower)
			throw std::invalid_argument("FOG observation of sensor '" + o->sensorLabel +
										"' has another layout (thermistors, axes or optional fields) than its first one");
		ticks.push_back(ticksOf(o->timestamp));
		series.time_s.push_back(0.0);  // set from the ticks at the end
		for (int a = 0; a < 3; a++)
			if (series.has_axis[a]) series.rate_dph[a].push_back(o->rate_dph[a]);
		for (std::size_t i = 0; i < series.temp_C.size(); i++) series.temp_C[i].push_back(o->temperature_C(i));
		if (f.hasTableRate) series.table_rate_dph.push_back(o->tableRate_dph);
		if (f.hasField) series.field_uT.push_back(o->field_uT);
		if (f.hasPower) series.power.push_back(o->powerOn ? 1.0 : 0.0);
	}

   private:
	CObservationFOG::Ptr first_;
};
}  // namespace

FogRawlogContents readFogRawlog(const std::string& path, const std::string& fog_label)
{
	registerAllClasses_mrpt_fog();

	// FOG samples go straight into columns (a CObservationFOG object weighs ~1 kB, its columns
	// ~50 B): all labels when none is chosen (several is then an error anyway), else the chosen
	// one. Everything else is kept as objects, in file order.
	std::map<std::string, FogAccumulator> fogs;
	std::map<std::string, std::pair<io::FogRawlogMetadata, mrpt::obs::CObservation::Ptr>> metas;
	FogRawlogContents out;
	std::size_t objects = 0;
	auto take = [&](const mrpt::obs::CObservation::Ptr& o, std::size_t index) {
		if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o); f && (fog_label.empty() || f->sensorLabel == fog_label))
		{
			try
			{
				fogs[f->sensorLabel].add(f);
			}
			catch (const std::exception& e)
			{
				throw FogIoError(path + ": object #" + std::to_string(index) + ": " + e.what());
			}
			return;
		}
		if (auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(o))
			if (auto m = io::parseFogRawlogMetadata(c->text); m && !metas.count(m->sensor_label))
				metas[m->sensor_label] = {*m, o};
		out.others.push_back(o);
	};
	{
		const std::string bytes = io::readWholeFile(path);
		if (bytes.empty()) throw FogIoError(path + ": empty rawlog (0 objects)");
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
			if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) take(o, objects);
			else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
			{
				for (const auto& so : *sf) take(so, objects);
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
	out.objects_read = objects;

	// Which FOG sensor.
	std::map<std::string, std::size_t> fog_counts;
	for (const auto& [label, acc] : fogs) fog_counts[label] = acc.size();
	for (const auto& o : out.others)
		if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o)) fog_counts[f->sensorLabel]++;
	if (fog_label.empty())
	{
		if (fog_counts.empty())
			throw FogIoError(path + ": no CObservationFOG in the file (" + std::to_string(objects) + " objects read)");
		if (fog_counts.size() > 1)
			throw FogIoError(path + ": several FOG sensors " + labelList(fog_counts) +
							 "; choose one by its label (fog-convert --label L)");
	}
	else if (!fogs.count(fog_label))
		throw FogIoError(path + ": no FOG sensor labelled '" + fog_label + "'" +
						 (fog_counts.empty() ? std::string(" (the file has no CObservationFOG)")
											 : " (present: " + labelList(fog_counts) + ")"));
	const std::string label = fogs.begin()->first;
	FogAccumulator& acc = fogs.begin()->second;

	// Its metadata block leaves `others`; exact times from the 100 ns ticks (a double of UNIX
	// seconds resolves only ~0.2 us today).
	out.fog = std::move(acc.series);
	out.fog.epoch_s = std::floor(mrpt::Clock::toDouble(fromTicks(acc.ticks.front())));
	if (auto m = metas.find(label); m != metas.end())
	{
		out.fog.epoch_s = m->second.first.epoch_s;
		out.fog.metadata = m->second.first.metadata;
		out.others.erase(std::find(out.others.begin(), out.others.end(), m->second.second));
	}
	const int64_t epoch_ticks = ticksOf(mrpt::Clock::fromDouble(out.fog.epoch_s));
	for (std::size_t k = 0; k < acc.ticks.size(); k++)
		out.fog.time_s[k] = static_cast<double>(acc.ticks[k] - epoch_ticks) / kTicksPerSecond;
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

}  // namespace mrpt_fog
