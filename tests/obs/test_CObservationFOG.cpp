/* Tests of mrpt_fog::CObservationFOG: serialization round trip, versioning, stock conversions. */
#include <gtest/gtest.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <cmath>
#include <vector>
#include <sstream>
#include <iterator>

using namespace mrpt_fog;

namespace
{
CObservationFOG::Ptr makeSample()
{
	auto o = CObservationFOG::Create();
	o->sensorLabel = "FOG1";
	o->timestamp = mrpt::Clock::fromDouble(1.7e9 + 0.25);
	o->sensorPose = mrpt::poses::CPose3D(0.1, 0.2, 0.3, 0.4, 0.0, 0.0);
	o->hasAxis = {false, false, false};
	o->setRate_dph(GyroAxis::Z, 12.5);
	o->setRate_dph(GyroAxis::X, -3.25);
	o->addThermistor({"Ti1", CoilSide::Inner, 0.0}, 21.37);
	o->addThermistor({"To1", CoilSide::Outer, 0.0}, std::nan(""));
	o->addThermistor({"Ti2", CoilSide::Inner, 180.0}, -39.99);
	o->hasTableRate = true;
	o->tableRate_dph = 15.0;
	o->hasPower = true;
	o->powerOn = false;
	return o;
}

/** `o` written as an object (class name, version, payload) into buf, which is then rewound. */
void writeObject(mrpt::io::CMemoryStream& buf, const CObservationFOG& o)
{
	mrpt_fog::registerAllClasses_mrpt_fog();
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch << o;
	buf.Seek(0);
}
}  // namespace

TEST(CObservationFOG, SerializeRoundTrip_v0)
{
	const auto o = makeSample();
	mrpt::io::CMemoryStream buf;
	writeObject(buf, *o);
	auto obj = mrpt::serialization::archiveFrom(buf).ReadObject();
	auto r = std::dynamic_pointer_cast<CObservationFOG>(obj);
	ASSERT_TRUE(r);
	EXPECT_EQ(r->sensorLabel, "FOG1");
	EXPECT_EQ(r->timestamp, o->timestamp);
	EXPECT_NEAR(r->sensorPose.x(), 0.1, 1e-12);
	EXPECT_TRUE(r->hasAxis[0]);
	EXPECT_FALSE(r->hasAxis[1]);
	EXPECT_TRUE(r->hasAxis[2]);
	EXPECT_EQ(r->rateOf_dph(GyroAxis::Z), 12.5);
	EXPECT_EQ(r->rateOf_dph(GyroAxis::X), -3.25);
	ASSERT_EQ(r->thermistors.size(), 3u);
	EXPECT_EQ(r->thermistors[1].name, "To1");
	EXPECT_EQ(r->thermistors[1].side, CoilSide::Outer);
	EXPECT_EQ(r->thermistors[2].angle_deg, 180.0);
	EXPECT_EQ(r->temperature_C(0), 21.37);
	EXPECT_TRUE(std::isnan(r->temperature_C(1)));
	EXPECT_FALSE(r->tempValid[1]);
	EXPECT_EQ(r->temperature_C(2), -39.99);
	EXPECT_TRUE(r->hasTableRate);
	EXPECT_EQ(r->tableRate_dph, 15.0);
	EXPECT_FALSE(r->hasField);
	EXPECT_TRUE(r->hasPower);
	EXPECT_FALSE(r->powerOn);
}

TEST(CObservationFOG, UnknownVersionThrows)
{
	mrpt::io::CMemoryStream buf;
	writeObject(buf, *makeSample());
	// Object layout: [class-name header][version byte][payload]. Patch the version byte.
	auto* data = static_cast<uint8_t*>(const_cast<void*>(buf.getRawBufferData()));
	const std::string name = "mrpt_fog::CObservationFOG";
	const auto size = buf.getTotalBytesCount();
	size_t pos = std::string::npos;
	for (size_t i = 0; i + name.size() < size; i++)
		if (std::equal(name.begin(), name.end(), data + i))
		{
			pos = i + name.size();
			break;
		}
	ASSERT_NE(pos, std::string::npos);
	ASSERT_EQ(data[pos], 0u);  // current version
	data[pos] = 99;
	EXPECT_ANY_THROW(mrpt::serialization::archiveFrom(buf).ReadObject());
}

TEST(CObservationFOG, RatesInRadPerSec)
{
	const auto o = makeSample();
	// 3600 deg/h = 1 deg/s
	o->setRate_dph(GyroAxis::Z, 3600.0);
	EXPECT_NEAR(o->rate_rad_s(GyroAxis::Z), M_PI / 180.0, 1e-15);
	EXPECT_THROW(o->rate_rad_s(GyroAxis::Y), std::out_of_range);
}

TEST(CObservationFOG, ToStockIMUAndDAQ)
{
	const auto o = makeSample();
	const auto imu = o->toIMU();
	EXPECT_NEAR(imu->get(mrpt::obs::IMU_WZ), 12.5 * units::kDegPerHourToRadPerSec, 1e-18);
	EXPECT_NEAR(imu->get(mrpt::obs::IMU_WX), -3.25 * units::kDegPerHourToRadPerSec, 1e-18);
	EXPECT_FALSE(imu->has(mrpt::obs::IMU_WY));
	// mean of the two valid readings only: the dropout is not 0 C
	EXPECT_NEAR(imu->get(mrpt::obs::IMU_TEMPERATURE), (21.37 - 39.99) / 2, 1e-12);
	const auto daq = o->toRawDAQ();
	ASSERT_EQ(daq->AIN_double.size(), 3u);
	EXPECT_EQ(daq->AIN_channel_count, 3);
	EXPECT_TRUE(std::isnan(daq->AIN_double[1]));
}

TEST(CObservationFOG, ExportTxt)
{
	const auto o = makeSample();
	EXPECT_EQ(o->exportTxtHeader(),
			  "rate_x_dph rate_y_dph rate_z_dph temp_Ti1_C temp_To1_C temp_Ti2_C table_rate_dph field_uT power");
	EXPECT_EQ(o->exportTxtDataRow(), "-3.25 NaN 12.5 21.37 NaN -39.99 15 NaN 0");
}

// rawlog-edit --export-txt keeps every stored bit: values that need 17 significant digits
// (the former 10-digit export lost 1e-9 relative) read back to the same double.
TEST(CObservationFOG, ExportTxtFullPrecision)
{
	auto o = makeSample();
	const double rate = 0.1 + 1.0 / 3.0 * 1e-7, temp = -39.987654321098765;
	o->setRate_dph(GyroAxis::Z, rate);
	o->temp_C[0] = temp;
	std::istringstream row(o->exportTxtDataRow());
	std::vector<std::string> cols{std::istream_iterator<std::string>(row), std::istream_iterator<std::string>()};
	ASSERT_EQ(cols.size(), 9u);
	EXPECT_EQ(std::stod(cols[2]), rate) << cols[2];
	EXPECT_EQ(std::stod(cols[3]), temp) << cols[3];
}

TEST(CObservationFOG, DescriptionMentionsDropout)
{
	const auto o = makeSample();
	std::ostringstream s;
	o->getDescriptionAsText(s);
	EXPECT_NE(s.str().find("DROPOUT"), std::string::npos);
	EXPECT_NE(s.str().find("12.500000 deg/h"), std::string::npos);
}

TEST(CObservationFOG, InvalidNotSerialized)
{
	auto o = makeSample();
	o->powerOn = true;  // a NaN rate with the gyro powered is invalid
	o->rate_dph[2] = std::nan("");
	mrpt::io::CMemoryStream buf;
	auto arch = mrpt::serialization::archiveFrom(buf);
	EXPECT_ANY_THROW(arch << *o);
	o->hasPower = false;  // ... and without a power state
	EXPECT_ANY_THROW(arch << *o);
}

TEST(CObservationFOG, GyroOffHasNoRateSampleButKeepsTheThermistors)
{
	auto o = makeSample();  // power off
	o->rate_dph[2] = std::nan("");
	mrpt::io::CMemoryStream buf;
	writeObject(buf, *o);
	CObservationFOG back;
	auto arch = mrpt::serialization::archiveFrom(buf);
	arch >> back;
	EXPECT_TRUE(std::isnan(back.rate_dph[2]));
	EXPECT_FALSE(back.powerOn);
	ASSERT_EQ(back.tempValid, o->tempValid);
	for (std::size_t i = 0; i < o->temp_C.size(); i++)
		if (o->tempValid[i]) EXPECT_EQ(back.temp_C[i], o->temp_C[i]);
	EXPECT_FALSE(o->toIMU()->has(mrpt::obs::IMU_WZ));  // stock form: no rate, not a NaN rate
}
