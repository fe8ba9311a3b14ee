/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogRawlogMetadata.h>
#include <mrpt_fog/io/GzStream.h>
#include <mrpt_fog/io/NumberText.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/common/ErrorText.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <array>
#include <cmath>
#include <cstring>
#include <deque>
#include <map>
#include <optional>

#include "FogLogReaderImpl.h"
#include <mrpt_fog/obs/FogObservationDecode.h>
#include "RawlogCommon.h"

namespace mrpt_fog
{
namespace
{
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
		return "unknown class '" + io::detail::quoteForError(what.data() + b, e - b) +
			   "' (not registered in MRPT's RTTI: a plugin library missing, or a corrupt class name)";
	}
	if (at_end_of_data)
		return "the file ends in the middle of this object (truncated file, or a corrupt length field in the object)";
	return "corrupt object: " + oneLineErrorMessage(what);
}

/** An MRPT object header as it stands in the bytes: the class it names and how long it is. */
struct ObjectHeader
{
	const mrpt::rtti::TRuntimeClassId* cls = nullptr;  //!< null: cut, not a header, or no registered class
	std::string name;									//!< as MRPT reads it (up to the first NUL)
	bool old_format = false;							//!< pre-MRPT-0.5.5: 3 zero bytes and a 32-bit version
	std::size_t bytes = 0;								//!< header length, version included
	std::uint8_t version = 0;
};

/** Parses the header of the object at `p` (MRPT 2: 0x80 | name length, the name, a version byte;
 * the old format: name length, 3 zero bytes, the name, a 32-bit version). MRPT ends the name at its
 * first NUL and refuses names over 120 bytes. `cls` stays null when the header is cut, malformed or
 * names no registered class (CArchive then says why). */
ObjectHeader parseObjectHeader(const unsigned char* p, std::size_t n)
{
	ObjectHeader h;
	if (n < 1) return h;
	h.old_format = (p[0] & 0x80u) == 0;
	const std::size_t len = p[0] & 0x7Fu, name_at = h.old_format ? 4 : 1, version_bytes = h.old_format ? 4 : 1;
	if (len > 120 || n < name_at + len + version_bytes) return h;
	if (h.old_format && (p[1] || p[2] || p[3])) return h;
	const auto* name = reinterpret_cast<const char*>(p + name_at);
	h.name.assign(name, ::strnlen(name, len));
	h.bytes = name_at + len + version_bytes;
	const unsigned char* v = p + name_at + len;
	if (h.old_format && (v[1] || v[2] || v[3] || v[0] == 255)) return h;  // MRPT: 0 <= version < 255 (little endian)
	h.version = v[0];
	h.cls = h.name.empty() ? nullptr : mrpt::rtti::findRegisteredClass(h.name);
	return h;
}

/** The observation classes this reader lets MRPT deserialise: their MRPT readers size what they
 * allocate with std::vector or fixed members, so a corrupt length ends in std::bad_alloc, which is
 * reported. Other classes are refused unread: several (CObservation3DRangeScan's range image,
 * CObservation2DRangeScan's scan, CMatrixD) allocate through MRPT's aligned allocator, which returns
 * null on failure, and MRPT then writes through it: a corrupt size crashes the program (SIGSEGV,
 * found by fuzz_rawlog and by hand) instead of throwing. */
const std::vector<const mrpt::rtti::TRuntimeClassId*>& readableObservationClasses()
{
	static const std::vector<const mrpt::rtti::TRuntimeClassId*> classes{
		CLASS_ID(CObservationFOG),			   CLASS_ID(mrpt::obs::CObservationIMU),
		CLASS_ID(mrpt::obs::CObservationRawDAQ), CLASS_ID(mrpt::obs::CObservationOdometry),
		CLASS_ID(mrpt::obs::CObservationRobotPose), CLASS_ID(mrpt::obs::CObservationComment)};
	return classes;
}

std::string readableClassList()
{
	std::string s;
	for (const auto* c : readableObservationClasses()) s += (s.empty() ? "" : ", ") + std::string(c->className);
	return s;
}

/** Whether objects of `c` may stand at the top level of a rawlog (observations-only or
 * sensory-frame format), or inside a sensory frame (observations only). */
bool allowedClass(const mrpt::rtti::TRuntimeClassId* c, bool nested)
{
	for (const auto* r : readableObservationClasses())
		if (c == r) return true;
	return !nested && c == CLASS_ID(mrpt::obs::CSensoryFrame);
}

std::string labelList(const std::map<std::string, std::size_t>& counts)
{
	std::string s;
	for (const auto& [label, n] : counts) s += (s.empty() ? "'" : ", '") + label + "' (" + std::to_string(n) + ")";
	return s;
}

/** Streaming rawlog reader: objects are deserialised one at a time from a GzReader. */
class RawlogReaderImpl : public FogLogReader::Impl
{
   public:
	RawlogReaderImpl(const std::string& path, const std::string& label, const ReadLimits& limits,
					 FogLogReader::ObservationSink others)
		: path_(path), label_(label), limits_(limits), sink_(std::move(others)), in_(path), arch_(in_)
	{
		registerAllClasses_mrpt_fog();
		if (in_.atEnd()) throw FogIoError(path_ + ": empty rawlog (0 objects)");
		// Read up to the first sample of the sensor: its layout and metadata are the header.
		while (queue_.empty())
			if (!readObject()) break;
		if (!first_) failNoSensor();
		header = emptySeriesLike(seriesFromObservations({first_}));
		header.epoch_s = std::floor(mrpt::Clock::toDouble(first_->timestamp));
		if (auto m = metas_.find(chosen_); m != metas_.end())
		{
			header.epoch_s = m->second.epoch_s;
			header.metadata = m->second.metadata;
		}
		if (first_->hasTableRate) header.table_rate_dph.assign(1, NAN);
		if (first_->hasField) header.field_uT.assign(1, NAN);
		if (first_->hasPower) header.power.assign(1, NAN);
		epoch_ticks_ = ticksOf(mrpt::Clock::fromDouble(header.epoch_s));
		if (header.thermistors.size() > limits_.max_thermistors)
			throw FogIoError(path_ + ": sensor '" + chosen_ + "' has " + std::to_string(header.thermistors.size()) +
							 " thermistors, more than the limit of " + std::to_string(limits_.max_thermistors));
	}

	bool next(FogSample& x) override
	{
		while (queue_.empty())
			if (!readObject())
			{
				finish();
				return false;
			}
		CObservationFOG::Ptr o = std::move(queue_.front().first);
		const std::size_t index = queue_.front().second;
		queue_.pop_front();
		const int64_t ticks = ticksOf(o->timestamp);
		if (samples > 0 && ticks <= last_ticks_)
			throw FogIoError(path_ + ": object #" + std::to_string(index) + ": sensor '" + chosen_ + "': time " +
							 io::formatNumber(static_cast<double>(ticks - epoch_ticks_) / kTicksPerSecond) + " s " +
							 (ticks == last_ticks_ ? "duplicates the previous sample's time" : "goes backwards") +
							 "; times must be strictly increasing");
		last_ticks_ = ticks;
		x.time_s = static_cast<double>(ticks - epoch_ticks_) / kTicksPerSecond;
		const bool off = o->hasPower && !o->powerOn;
		for (int a = 0; a < 3; a++)
		{
			x.rate_dph[a] = o->hasAxis[a] ? o->rate_dph[a] : NAN;
			if (!o->hasAxis[a]) continue;
			const double r = x.rate_dph[a];
			if (!(std::isfinite(r) || (std::isnan(r) && off)) || std::abs(r) > limits_.max_abs_rate_dph)
				throw FogIoError(path_ + ": object #" + std::to_string(index) + ": sensor '" + chosen_ + "': rate_" +
								 axisLetter(static_cast<GyroAxis>(a)) + "_dph " + io::formatNumber(r) +
								 (std::isfinite(r) ? " deg/h is beyond the limit of " + io::formatNumber(limits_.max_abs_rate_dph) + " deg/h"
												   : " is not finite (a missing rate is allowed only where power is 0)"));
		}
		x.temp_C.resize(header.thermistors.size());
		for (std::size_t i = 0; i < x.temp_C.size(); i++)
		{
			x.temp_C[i] = o->temperature_C(i);
			if (std::isinf(x.temp_C[i]))
				throw FogIoError(path_ + ": object #" + std::to_string(index) + ": infinite temperature of thermistor '" +
								 header.thermistors[i].name + "'");
		}
		x.table_rate_dph = o->hasTableRate ? o->tableRate_dph : NAN;
		x.field_uT = o->hasField ? o->field_uT : NAN;
		if (std::isinf(x.table_rate_dph) || std::abs(x.table_rate_dph) > limits_.max_abs_rate_dph)
			throw FogIoError(path_ + ": object #" + std::to_string(index) + ": sensor '" + chosen_ + "': table rate " +
							 io::formatNumber(x.table_rate_dph) + " deg/h is beyond the limit of " +
							 io::formatNumber(limits_.max_abs_rate_dph) + " deg/h");
		if (std::isinf(x.field_uT) || std::abs(x.field_uT) > limits_.max_abs_field_uT)
			throw FogIoError(path_ + ": object #" + std::to_string(index) + ": sensor '" + chosen_ + "': field_uT " +
							 io::formatNumber(x.field_uT) + " uT is beyond the limit of " +
							 io::formatNumber(limits_.max_abs_field_uT) + " uT (no gyro test applies that)");
		x.power = o->hasPower ? (o->powerOn ? 1.0 : 0.0) : NAN;
		samples++;
		if (o.use_count() == 1 && spare_.size() < 4) spare_.push_back(o);  // reused by the fast path
		return true;
	}

	std::size_t objectsRead() const override { return objects_; }
	bool isRawlog() const override { return true; }
	std::uint64_t fileBytesRead() const override { return in_.fileBytesRead(); }
	std::uint64_t fileBytes() const override { return in_.fileBytes(); }

   private:
	/** Reads one object; false at the end of the data. */
	bool readObject()
	{
		if (in_.atEnd()) return false;
		if (readFogObservationFast()) return true;
		const uint64_t offset = in_.position();
		mrpt::serialization::CSerializable::Ptr obj;
		try
		{
			obj = readCheckedObject(false, offset);
		}
		catch (const FogIoError&)
		{
			throw;  // corrupt or truncated gzip data, or an object refused unread: says so itself
		}
		catch (const std::exception& e)
		{
			const bool at_end = in_.atEnd();
			throw FogIoError(path_ + ": read " + std::to_string(objects_) + " objects, then stopped at object #" +
							 std::to_string(objects_) + " (byte offset " + std::to_string(offset) +
							 " of the decompressed data, " + std::to_string(in_.position()) + " bytes in all" +
							 (at_end ? "" : " read") + "): " + whyReadFailed(e.what(), at_end));
		}
		if (auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(obj)) take(o, objects_);
		else if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(obj))
		{
			for (const auto& so : *sf) take(so, objects_);
		}
		else
			throw FogIoError(path_ + ": object #" + std::to_string(objects_) + " (byte offset " + std::to_string(offset) +
							 ") is a " + (obj ? obj->GetRuntimeClass()->className : "null object") + ", not an observation");
		objects_++;
		return true;
	}

	/** Reads the next object through CArchive after checking its header: a class that cannot stand
	 * here is refused unread (see allowedClass), and a sensory frame is read here, each of its
	 * observations checked the same way, because MRPT would read whatever class its list names.
	 * `offset`: where the top-level object starts (for messages). */
	mrpt::serialization::CSerializable::Ptr readCheckedObject(bool nested, uint64_t offset)
	{
		const unsigned char* p = nullptr;
		const std::size_t n = in_.peek(p, 4 + 127 + 4);
		const ObjectHeader h = parseObjectHeader(p, n);
		if (h.cls && !allowedClass(h.cls, nested))
		{
			const std::string where = path_ + ": object #" + std::to_string(objects_) + " (byte offset " + std::to_string(offset) + ")";
			if (h.cls->derivedFrom(CLASS_ID(mrpt::obs::CActionCollection)))
				throw FogIoError(where + " is a CActionCollection: rawlogs with actions (sensory-frame format) are not "
										 "supported; use the observations-only format (refused unread)");
			const std::string what = where + (nested ? ": the sensory frame holds a " : " is a ") + h.cls->className;
			if (!h.cls->derivedFrom(CLASS_ID(mrpt::obs::CObservation)))
				throw FogIoError(what + ", not an observation (refused unread: a rawlog holds observations" +
								 (nested ? ")" : " or sensory frames of observations)"));
			throw FogIoError(what + ": this reader lets MRPT read only " + readableClassList() +
							 " (MRPT's readers of other classes can crash on a corrupt size instead of failing); "
							 "keep the FOG's and those sensors' observations first, e.g. with MRPT's "
							 "`rawlog-edit --keep-label FOG,ODOMETRY -i in.rawlog -o out.rawlog` (refused unread)");
		}
		if (h.cls == CLASS_ID(mrpt::obs::CSensoryFrame))
		{
			in_.consume(h.bytes);
			return readSensoryFrameBody(h, offset);
		}
		return arch_.ReadObject();
	}

	/** The body of a CSensoryFrame (its header consumed), as CSensoryFrame::serializeFrom reads it
	 * (versions 0-2: [ID], [timestamp], count, the observations), then MRPT's end flag; each
	 * observation checked before it is read, the count bounded, nothing allocated ahead. */
	mrpt::serialization::CSerializable::Ptr readSensoryFrameBody(const ObjectHeader& h, uint64_t offset)
	{
		const std::string where = path_ + ": object #" + std::to_string(objects_) + " (byte offset " +
								  std::to_string(offset) + "), a sensory frame";
		if (h.version > 2)
			throw FogIoError(where + ": unknown serialization version " + std::to_string(h.version) + " (MRPT 2.5 writes 2)");
		uint32_t id = 0, count = 0;
		mrpt::system::TTimeStamp stamp = INVALID_TIMESTAMP;
		if (h.version < 2) arch_ >> id;
		if (h.version == 0) arch_.ReadBufferFixEndianness(&stamp, 1);
		arch_ >> count;
		if (count > kMaxFrameObservations)
			throw FogIoError(where + ": holds " + std::to_string(count) + " observations, more than the limit of " +
							 std::to_string(kMaxFrameObservations) + " (a corrupt count)");
		auto sf = mrpt::obs::CSensoryFrame::Create();
		for (uint32_t i = 0; i < count; i++)
		{
			auto o = std::dynamic_pointer_cast<mrpt::obs::CObservation>(readCheckedObject(true, offset));
			if (!o) throw FogIoError(where + ": its observation " + std::to_string(i) + " is a null object");
			if (h.version == 0) o->timestamp = stamp;
			sf->insert(o);
		}
		if (!h.old_format)
		{
			uint8_t end_flag = 0;
			arch_ >> end_flag;
			if (end_flag != 0x88)  // MRPT's SERIALIZATION_END_FLAG
				throw FogIoError(where + ": end-of-object mark missing after its " + std::to_string(count) +
								 " observations (corrupt object)");
		}
		return sf;
	}

	/** The common case, a CObservationFOG whose sensor pose is the last one read, decoded straight
	 * from the decompressed bytes into a reused object (3-4x faster than CArchive: no class lookup,
	 * allocation or stream call per field). Anything else (another class, a new pose, an object
	 * cut by the end of the buffer, a corrupt value) returns false having consumed nothing, and
	 * CArchive reads the object (and names what is wrong with it). */
	bool readFogObservationFast()
	{
		if (!pose_) return false;  // the first FOG observation goes through CArchive
		const unsigned char* p = nullptr;
		std::size_t n = in_.peek(p, 1);
		CObservationFOG::Ptr o;
		if (!spare_.empty())
		{
			o = std::move(spare_.back());
			spare_.pop_back();
		}
		else
			o = CObservationFOG::Create();
		std::size_t used = detail::decodeFogObservation(p, n, *pose_, *o);
		if (used == 0 && n < kFastPeekBytes)  // perhaps cut by the end of the buffer: look further
		{
			n = in_.peek(p, kFastPeekBytes);
			used = detail::decodeFogObservation(p, n, *pose_, *o);
		}
		if (used == 0)
		{
			spare_.push_back(std::move(o));
			return false;
		}
		in_.consume(used);
		takeFog(o, objects_);
		objects_++;
		return true;
	}

	void take(const mrpt::obs::CObservation::Ptr& o, std::size_t index)
	{
		if (takeStock(o, index)) return;
		if (auto f = std::dynamic_pointer_cast<CObservationFOG>(o))
		{
			fog_class_ = true;
			if (!pose_ || !(f->sensorPose == pose_->pose))  // the pose the fast path expects
				pose_ = detail::SerializedPose{f->sensorPose, detail::serializedPoseBytes(f->sensorPose)};
			takeFog(f, index);
			return;
		}
		else if (auto c = std::dynamic_pointer_cast<mrpt::obs::CObservationComment>(o))
		{
			if (auto m = io::parseFogRawlogMetadata(c->text); m && !metas_.count(m->sensor_label))
			{
				metas_[m->sensor_label] = *m;
				if (!label_.empty() && m->sensor_label == label_) return;  // the chosen sensor's own block
				if (label_.empty() && chosen_.empty())
				{
					pending_meta_.emplace_back(m->sensor_label, o);  // whose it is: known at the first FOG sample
					return;
				}
			}
		}
		if (sink_) sink_(o);
	}

	/** The stock form of a FOG stream (fog-compensate's rawlog, fog-convert --to-stock): a
	 * CObservationIMU followed by the CObservationRawDAQ '<label>_THERMISTORS' of the same time
	 * is one sample of sensor <label>. Used while no CObservationFOG has been chosen. Returns true
	 * when the object was taken (an IMU waits for its DAQ; an IMU without one goes to the sink). */
	bool takeStock(const mrpt::obs::CObservation::Ptr& o, std::size_t index)
	{
		if (auto imu = std::dynamic_pointer_cast<mrpt::obs::CObservationIMU>(o))
		{
			flushStock();
			const bool ours = label_.empty() ? (chosen_.empty() || chosen_ == imu->sensorLabel) : imu->sensorLabel == label_;
			if (fog_class_ || !ours) return false;
			pending_imu_ = imu;
			pending_index_ = index;
			return true;
		}
		auto daq = std::dynamic_pointer_cast<mrpt::obs::CObservationRawDAQ>(o);
		if (daq && pending_imu_ && daq->sensorLabel == pending_imu_->sensorLabel + "_THERMISTORS" &&
			daq->timestamp == pending_imu_->timestamp)
		{
			auto f = fogFromStock(*pending_imu_, *daq);
			pending_imu_.reset();
			stock_ = true;
			takeFog(f, pending_index_);
			return true;
		}
		flushStock();
		return false;
	}

	void flushStock()
	{
		if (!pending_imu_) return;
		auto imu = std::move(pending_imu_);
		pending_imu_.reset();
		if (sink_) sink_(imu);
	}

	/** One stock sample as a FOG observation: rates from IMU_WX/WY/WZ [rad/s] (absent: gyro off),
	 * temperatures from the DAQ's channels (NaN: dropout), named T1..Tn (the stock form carries no
	 * names). The axes are those of the first sample with a rate. */
	CObservationFOG::Ptr fogFromStock(const mrpt::obs::CObservationIMU& imu, const mrpt::obs::CObservationRawDAQ& daq)
	{
		auto f = CObservationFOG::Create();
		f->sensorLabel = imu.sensorLabel;
		f->timestamp = imu.timestamp;
		const mrpt::obs::TIMUDataIndex idx[3] = {mrpt::obs::IMU_WX, mrpt::obs::IMU_WY, mrpt::obs::IMU_WZ};
		bool any = false;
		for (int a = 0; a < 3; a++) any |= imu.has(idx[a]);
		if (any && !stock_axes_)
		{
			stock_axes_.emplace();
			for (int a = 0; a < 3; a++) (*stock_axes_)[a] = imu.has(idx[a]);
		}
		f->hasAxis = stock_axes_ ? *stock_axes_ : std::array<bool, 3>{{false, false, true}};
		for (int a = 0; a < 3; a++)
			f->rate_dph[a] = imu.has(idx[a]) ? imu.get(idx[a]) / units::kDegPerHourToRadPerSec : NAN;
		f->hasPower = true;
		f->powerOn = any;
		for (std::size_t i = 0; i < daq.AIN_double.size(); i++)
		{
			ThermistorInfo info;
			info.name = "T" + std::to_string(i + 1);
			f->addThermistor(info, daq.AIN_double[i], std::isfinite(daq.AIN_double[i]));
		}
		return f;
	}

	/** A FOG observation: queued when of the chosen sensor, else counted and passed to the sink. */
	void takeFog(const CObservationFOG::Ptr& f, std::size_t index)
	{
		if (chosen_.empty() && (label_.empty() || f->sensorLabel == label_))
		{
			chosen_ = f->sensorLabel;
			// Metadata blocks met before: the sensor's own is consumed, the others go on.
			for (auto& [l, c] : pending_meta_)
				if (l != chosen_ && sink_) sink_(c);
			pending_meta_.clear();
		}
		if (f->sensorLabel == chosen_)
		{
			if (!first_) first_ = f;
			else if (f->thermistors != first_->thermistors || f->hasAxis != first_->hasAxis ||
					 f->hasTableRate != first_->hasTableRate || f->hasField != first_->hasField ||
					 f->hasPower != first_->hasPower)
				throw FogIoError(path_ + ": object #" + std::to_string(index) + ": FOG observation of sensor '" +
								 f->sensorLabel + "' has another layout (thermistors, axes or optional fields) than its first one");
			queue_.emplace_back(f, index);
			return;
		}
		other_fog_[f->sensorLabel]++;
		if (label_.empty()) failSeveral();
		if (sink_) sink_(f);
	}

	/** Several FOG labels and none chosen: count them all (error path) and say so. */
	[[noreturn]] void failSeveral()
	{
		std::map<std::string, std::size_t> counts = other_fog_;
		counts[chosen_] += samples + queue_.size();
		try
		{
			while (!in_.atEnd())
			{
				auto obj = readCheckedObject(false, in_.position());
				if (auto f = std::dynamic_pointer_cast<CObservationFOG>(obj)) counts[f->sensorLabel]++;
			}
		}
		catch (const std::exception&)
		{
		}
		throw FogIoError(path_ + ": several FOG sensors " + labelList(counts) +
						 "; choose one by its label (fog-convert --label L)");
	}

	[[noreturn]] void failNoSensor() const
	{
		if (label_.empty())
			throw FogIoError(path_ + ": no CObservationFOG in the file (" + std::to_string(objects_) + " objects read)");
		throw FogIoError(path_ + ": no FOG sensor labelled '" + label_ + "'" +
						 (other_fog_.empty() ? std::string(" (the file has no CObservationFOG)")
											 : " (present: " + labelList(other_fog_) + ")"));
	}

	void finish() { flushStock(); }

	std::vector<std::string> notes() const override
	{
		if (!stock_) return {};
		return {"sensor '" + chosen_ + "' read from stock MRPT observations (CObservationIMU + CObservationRawDAQ '" +
				chosen_ + "_THERMISTORS'): thermistors named T1..T" + std::to_string(header.thermistors.size()) +
				" (the stock form has no names), no table rate or field"};
	}

	std::string path_, label_;
	ReadLimits limits_;
	FogLogReader::ObservationSink sink_;
	io::GzReader in_;
	mrpt::serialization::CArchiveStreamBase<mrpt::io::CStream> arch_;
	std::string chosen_;
	CObservationFOG::Ptr first_;
	std::deque<std::pair<CObservationFOG::Ptr, std::size_t>> queue_;
	std::map<std::string, io::FogRawlogMetadata> metas_;
	std::map<std::string, std::size_t> other_fog_;
	std::vector<std::pair<std::string, mrpt::obs::CObservation::Ptr>> pending_meta_;
	std::size_t objects_ = 0;
	int64_t epoch_ticks_ = 0, last_ticks_ = 0;
	std::optional<detail::SerializedPose> pose_;  // of the last FOG observation read by CArchive
	std::vector<CObservationFOG::Ptr> spare_;  // consumed observations, reused by the fast path
	bool fog_class_ = false;  // a CObservationFOG was met: the stock form is not read
	bool stock_ = false;  // the chosen sensor is read from its stock form
	mrpt::obs::CObservationIMU::Ptr pending_imu_;  // a stock IMU waiting for its DAQ
	std::size_t pending_index_ = 0;
	std::optional<std::array<bool, 3>> stock_axes_;
	static constexpr uint32_t kMaxFrameObservations = 1u << 20;  // observations in one sensory frame
	static constexpr std::size_t kFastPeekBytes = 64 * 1024;  // a FOG object of 255 named thermistors fits
};
}  // namespace

std::unique_ptr<FogLogReader::Impl> makeRawlogReaderImpl(const std::string& path, const std::string& fog_label,
														 const ReadLimits& limits, FogLogReader::ObservationSink others)
{
	return std::make_unique<RawlogReaderImpl>(path, fog_label, limits, std::move(others));
}

FogRawlogContents readFogRawlog(const std::string& path, const std::string& fog_label)
{
	FogRawlogContents out;
	FogLogReader reader(path, fog_label, ReadLimits{},
						[&](const mrpt::obs::CObservation::Ptr& o) { out.others.push_back(o); });
	out.fog = readAllSamples(reader);
	out.objects_read = reader.objectsRead();
	try
	{
		out.fog.validate();
	}
	catch (const std::exception& e)
	{
		throw FogIoError(path + ": sensor '" + out.fog.sensor_label + "': " + e.what());
	}
	return out;
}

}  // namespace mrpt_fog
