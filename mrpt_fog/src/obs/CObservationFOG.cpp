/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt/core/bits_math.h>
#include <mrpt/core/format.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt/serialization/stl_serialization.h>
#include <mrpt/system/datetime.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/FogObservationDecode.h>

#include <charconv>
#include <cmath>
#include <cstring>
#include <limits>
#include <ostream>
#include <sstream>
#include <stdexcept>

using namespace mrpt_fog;

IMPLEMENTS_SERIALIZABLE(CObservationFOG, CObservation, mrpt_fog)

namespace
{
constexpr uint8_t kFlagTableRate = 1, kFlagField = 2, kFlagPower = 4, kFlagPowerOn = 8;
}

uint8_t CObservationFOG::serializeGetVersion() const { return 0; }

void CObservationFOG::serializeTo(mrpt::serialization::CArchive& out) const
{
	validate();
	out << timestamp << sensorLabel << sensorPose;
	uint8_t axes = 0;
	for (int a = 0; a < 3; a++)
		if (hasAxis[a]) axes |= static_cast<uint8_t>(1u << a);
	out << axes << rate_dph[0] << rate_dph[1] << rate_dph[2];
	out.WriteAs<uint16_t>(thermistors.size());
	for (std::size_t i = 0; i < thermistors.size(); i++)
	{
		out << thermistors[i].name;
		out.WriteAs<uint8_t>(static_cast<uint8_t>(thermistors[i].side));
		out << thermistors[i].angle_deg << temp_C[i];
		out.WriteAs<uint8_t>(tempValid[i] ? 1 : 0);
	}
	uint8_t flags = 0;
	if (hasTableRate) flags |= kFlagTableRate;
	if (hasField) flags |= kFlagField;
	if (hasPower) flags |= kFlagPower;
	if (powerOn) flags |= kFlagPowerOn;
	out << flags << tableRate_dph << field_uT;
}

void CObservationFOG::serializeFrom(mrpt::serialization::CArchive& in, uint8_t version)
{
	switch (version)
	{
		case 0:
		{
			in >> timestamp >> sensorLabel >> sensorPose;
			uint8_t axes = 0;
			in >> axes >> rate_dph[0] >> rate_dph[1] >> rate_dph[2];
			if (axes == 0 || axes > 7)
				throw std::runtime_error(mrpt::format("CObservationFOG: corrupt axis mask %u", axes));
			for (int a = 0; a < 3; a++) hasAxis[a] = (axes >> a) & 1u;
			const auto n = in.ReadAs<uint16_t>();
			thermistors.assign(n, ThermistorInfo());
			temp_C.assign(n, 0.0);
			tempValid.assign(n, false);
			for (std::size_t i = 0; i < n; i++)
			{
				in >> thermistors[i].name;
				const auto side = in.ReadAs<uint8_t>();
				if (side > 2) throw std::runtime_error(mrpt::format("CObservationFOG: corrupt coil side %u", side));
				thermistors[i].side = static_cast<CoilSide>(side);
				in >> thermistors[i].angle_deg >> temp_C[i];
				// A NaN angle would make the layout unequal to itself (found by fuzz_rawlog).
				if (!std::isfinite(thermistors[i].angle_deg))
					throw std::runtime_error("CObservationFOG: corrupt thermistor angle (not finite)");
				tempValid[i] = in.ReadAs<uint8_t>() != 0;
			}
			uint8_t flags = 0;
			in >> flags >> tableRate_dph >> field_uT;
			hasTableRate = flags & kFlagTableRate;
			hasField = flags & kFlagField;
			hasPower = flags & kFlagPower;
			powerOn = flags & kFlagPowerOn;
		}
		break;
		default: MRPT_THROW_UNKNOWN_SERIALIZATION_VERSION(version);
	};
}

namespace mrpt_fog::detail
{
std::string serializedPoseBytes(const mrpt::poses::CPose3D& pose)
{
	mrpt::io::CMemoryStream mem;
	auto arch = mrpt::serialization::archiveFrom(mem);
	arch << pose;
	return std::string(static_cast<const char*>(mem.getRawBufferData()), mem.getTotalBytesCount());
}

namespace
{
/** Bounds-checked little-endian reads from contiguous bytes (what CArchive reads on x86/ARM). */
struct ByteCursor
{
	const unsigned char* p;
	std::size_t n, at = 0;
	bool ok = true;
	bool has(std::size_t k)
	{
		ok = ok && k <= n - at;
		return ok;
	}
	template <typename T>
	T get()
	{
		T v{};
		if (has(sizeof(T)))
		{
			std::memcpy(&v, p + at, sizeof(T));
			at += sizeof(T);
		}
		return v;
	}
	bool string(std::string& s)
	{
		const auto len = get<uint32_t>();
		if (!has(len)) return false;
		s.assign(reinterpret_cast<const char*>(p + at), len);
		at += len;
		return true;
	}
	bool bytesEqual(const std::string& b)
	{
		if (!has(b.size()) || std::memcmp(p + at, b.data(), b.size()) != 0) return ok = false;
		at += b.size();
		return true;
	}
};
constexpr char kFogClassName[] = "mrpt_fog::CObservationFOG";
constexpr uint8_t kEndOfObject = 0x88;  // MRPT's SERIALIZATION_END_FLAG
}  // namespace

std::size_t decodeFogObservation(const unsigned char* p, std::size_t n, const SerializedPose& pose, CObservationFOG& o)
{
	static_assert(sizeof(double) == 8 && sizeof(mrpt::Clock::rep) == 8, "CArchive's 8-byte fields");
	constexpr std::size_t name_len = sizeof(kFogClassName) - 1;
	ByteCursor c{p, n};
	// MRPT object header: 0x80 | name length, the class name, the version byte.
	if (c.get<uint8_t>() != (0x80u | name_len) || !c.has(name_len) || std::memcmp(p + c.at, kFogClassName, name_len) != 0)
		return 0;
	c.at += name_len;
	if (c.get<uint8_t>() != 0 || !c.ok) return 0;  // version 0 only
	o.timestamp = mrpt::Clock::time_point(mrpt::Clock::duration(c.get<mrpt::Clock::rep>()));
	if (!c.string(o.sensorLabel) || !c.bytesEqual(pose.bytes)) return 0;
	o.sensorPose = pose.pose;
	const auto axes = c.get<uint8_t>();
	if (axes == 0 || axes > 7) return 0;
	for (int a = 0; a < 3; a++)
	{
		o.hasAxis[a] = (axes >> a) & 1u;
		o.rate_dph[a] = c.get<double>();
	}
	const auto count = c.get<uint16_t>();
	if (!c.ok) return 0;
	o.thermistors.resize(count);
	o.temp_C.resize(count);
	o.tempValid.resize(count);
	for (std::size_t i = 0; i < count; i++)
	{
		if (!c.string(o.thermistors[i].name)) return 0;
		const auto side = c.get<uint8_t>();
		if (side > 2) return 0;
		o.thermistors[i].side = static_cast<CoilSide>(side);
		o.thermistors[i].angle_deg = c.get<double>();
		o.temp_C[i] = c.get<double>();
		if (!std::isfinite(o.thermistors[i].angle_deg)) return 0;
		o.tempValid[i] = c.get<uint8_t>() != 0;
	}
	const auto flags = c.get<uint8_t>();
	o.tableRate_dph = c.get<double>();
	o.field_uT = c.get<double>();
	o.hasTableRate = flags & kFlagTableRate;
	o.hasField = flags & kFlagField;
	o.hasPower = flags & kFlagPower;
	o.powerOn = flags & kFlagPowerOn;
	if (c.get<uint8_t>() != kEndOfObject || !c.ok) return 0;
	return c.at;
}
}  // namespace mrpt_fog::detail

double CObservationFOG::rateOf_dph(GyroAxis axis) const
{
	const int a = static_cast<int>(axis);
	if (!hasAxis[a])
		throw std::out_of_range(std::string("CObservationFOG: axis ") + axisLetter(axis) + " not present");
	return rate_dph[a];
}

double CObservationFOG::rate_rad_s(GyroAxis axis) const { return rateOf_dph(axis) * units::kDegPerHourToRadPerSec; }

void CObservationFOG::setRate_dph(GyroAxis axis, double value_dph)
{
	const int a = static_cast<int>(axis);
	hasAxis[a] = true;
	rate_dph[a] = value_dph;
}

double CObservationFOG::temperature_C(std::size_t i) const
{
	if (i >= temp_C.size()) throw std::out_of_range("CObservationFOG: thermistor index out of range");
	return tempValid[i] ? temp_C[i] : std::numeric_limits<double>::quiet_NaN();
}

void CObservationFOG::addThermistor(const ThermistorInfo& info, double value_C, bool valid)
{
	thermistors.push_back(info);
	const bool ok = valid && std::isfinite(value_C);
	temp_C.push_back(ok ? value_C : std::numeric_limits<double>::quiet_NaN());
	tempValid.push_back(ok);
}

double CObservationFOG::meanTemperature_C() const
{
	double sum = 0;
	int n = 0;
	for (std::size_t i = 0; i < temp_C.size(); i++)
		if (tempValid[i])
		{
			sum += temp_C[i];
			n++;
		}
	return n ? sum / n : std::numeric_limits<double>::quiet_NaN();
}

void CObservationFOG::validate() const
{
	if (!hasAxis[0] && !hasAxis[1] && !hasAxis[2]) throw std::invalid_argument("CObservationFOG: no sensitive axis present");
	if (thermistors.size() != temp_C.size() || temp_C.size() != tempValid.size())
		throw std::invalid_argument("CObservationFOG: thermistors, temp_C and tempValid differ in size");
	if (thermistors.size() > 65535) throw std::invalid_argument("CObservationFOG: too many thermistors");
	for (int a = 0; a < 3; a++)
		if (hasAxis[a] && !std::isfinite(rate_dph[a]) && !(std::isnan(rate_dph[a]) && hasPower && !powerOn))
			throw std::invalid_argument(std::string("CObservationFOG: non-finite rate on axis ") +
										axisLetter(static_cast<GyroAxis>(a)));
}

mrpt::obs::CObservationIMU::Ptr CObservationFOG::toIMU() const
{
	auto imu = mrpt::obs::CObservationIMU::Create();
	imu->timestamp = timestamp;
	imu->sensorLabel = sensorLabel;
	imu->sensorPose = sensorPose;
	const mrpt::obs::TIMUDataIndex idx[3] = {mrpt::obs::IMU_WX, mrpt::obs::IMU_WY, mrpt::obs::IMU_WZ};
	for (int a = 0; a < 3; a++)
		if (hasAxis[a] && !std::isnan(rate_dph[a]))  // NaN: gyro off, no rate sample (left absent)
			imu->set(idx[a], rate_dph[a] * units::kDegPerHourToRadPerSec);
	const double t = meanTemperature_C();
	if (std::isfinite(t)) imu->set(mrpt::obs::IMU_TEMPERATURE, t);
	return imu;
}

mrpt::obs::CObservationRawDAQ::Ptr CObservationFOG::toRawDAQ() const
{
	auto daq = mrpt::obs::CObservationRawDAQ::Create();
	daq->timestamp = timestamp;
	daq->sensorLabel = sensorLabel + "_THERMISTORS";
	if (temp_C.size() > 65535)  // CObservationRawDAQ counts channels in 16 bits (66 000 wrapped to 464)
		throw std::invalid_argument("sensor '" + sensorLabel + "': " + std::to_string(temp_C.size()) +
									" thermistors exceed the 65535 channels of a CObservationRawDAQ");
	daq->AIN_channel_count = static_cast<uint16_t>(temp_C.size());
	daq->AIN_interleaved = true;
	for (std::size_t i = 0; i < temp_C.size(); i++) daq->AIN_double.push_back(temperature_C(i));
	return daq;
}

void CObservationFOG::getDescriptionAsText(std::ostream& o) const
{
	CObservation::getDescriptionAsText(o);
	o << "Sensor pose on the robot: " << sensorPose << "\n";
	o << "Gyro rates (raw output, bias included):\n";
	for (int a = 0; a < 3; a++)
		if (hasAxis[a])
			o << mrpt::format("  %c: %14.6f deg/h  (%.6e rad/s)\n", axisLetter(static_cast<GyroAxis>(a)),
							  rate_dph[a], rate_dph[a] * units::kDegPerHourToRadPerSec);
	o << "Thermistors (" << thermistors.size() << "):\n";
	for (std::size_t i = 0; i < thermistors.size(); i++)
	{
		const auto& t = thermistors[i];
		o << mrpt::format("  %-8s side=%-5s angle=%7.2f deg  ", t.name.c_str(), toString(t.side), t.angle_deg);
		if (tempValid[i]) o << mrpt::format("%9.3f degC\n", temp_C[i]);
		else o << "DROPOUT (no reading)\n";
	}
	if (hasTableRate) o << mrpt::format("Applied table rate: %.6f deg/h\n", tableRate_dph);
	if (hasField) o << mrpt::format("Axial magnetic field: %.3f uT\n", field_uT);
	if (hasPower) o << "Power: " << (powerOn ? "on" : "off") << "\n";
}

std::string CObservationFOG::exportTxtHeader() const
{
	std::string h = "rate_x_dph rate_y_dph rate_z_dph";
	for (const auto& t : thermistors) h += " temp_" + t.name + "_C";
	h += " table_rate_dph field_uT power";
	return h;
}

std::string CObservationFOG::exportTxtDataRow() const
{
	// Shortest text that reads back to the same double (std::to_chars): rawlog-edit --export-txt
	// keeps the full precision of the stored values.
	std::ostringstream s;
	auto put = [&](bool present, double v) {
		s << ' ';
		if (present && std::isfinite(v))
		{
			char buf[32];
			const auto r = std::to_chars(buf, buf + sizeof(buf), v);
			s.write(buf, r.ptr - buf);
		}
		else s << "NaN";
	};
	for (int a = 0; a < 3; a++) put(hasAxis[a], rate_dph[a]);
	for (std::size_t i = 0; i < temp_C.size(); i++) put(tempValid[i], temp_C[i]);
	put(hasTableRate, tableRate_dph);
	put(hasField, field_uT);
	put(hasPower, powerOn ? 1.0 : 0.0);
	return s.str().substr(1);
}
