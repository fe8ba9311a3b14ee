/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
/* The rawlog reader's fast path (decodeFogObservation) against MRPT's own CArchive: the same
 * objects, field for field, and every input it cannot vouch for left to CArchive. */
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/io/CMemoryStream.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/FogLogReader.h>
#include <mrpt_fog/obs/FogObservationDecode.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <cmath>
#include <random>

#include "IoTestUtil.h"

using namespace mrpt_fog;

namespace
{
/** A FOG observation with every field set (long thermistor names: beyond std::string's SSO). */
CObservationFOG::Ptr makeObservation(std::mt19937_64& rng, const std::string& label, const mrpt::poses::CPose3D& pose,
									 int64_t ticks)
{
	std::uniform_real_distribution<double> u(-50, 50);
	auto o = CObservationFOG::Create();
	o->sensorLabel = label;
	o->sensorPose = pose;
	o->timestamp = mrpt::Clock::time_point(mrpt::Clock::duration(ticks));
	o->hasAxis = {true, false, true};
	o->rate_dph = {u(rng), 0.0, u(rng)};
	o->addThermistor({"Ti1", CoilSide::Inner, 0}, u(rng));
	o->addThermistor({"thermistor_with_a_long_name", CoilSide::Outer, 90}, u(rng), rng() % 5 != 0);
	o->addThermistor({"To3", CoilSide::Other, -45.5}, u(rng));
	o->hasTableRate = true;
	o->tableRate_dph = u(rng);
	o->hasField = true;
	o->field_uT = u(rng);
	o->hasPower = true;
	o->powerOn = rng() % 7 != 0;
	if (!o->powerOn) o->rate_dph[0] = o->rate_dph[2] = std::nan("");
	return o;
}

std::string serialized(const mrpt::serialization::CSerializable& o)
{
	mrpt::io::CMemoryStream mem;
	auto arch = mrpt::serialization::archiveFrom(mem);
	arch << o;
	return std::string(static_cast<const char*>(mem.getRawBufferData()), mem.getTotalBytesCount());
}

void expectSameObservation(const CObservationFOG& a, const CObservationFOG& b, const std::string& where)
{
	EXPECT_EQ(a.timestamp, b.timestamp) << where;
	EXPECT_EQ(a.sensorLabel, b.sensorLabel) << where;
	EXPECT_EQ(a.sensorPose, b.sensorPose) << where;
	EXPECT_EQ(a.hasAxis, b.hasAxis) << where;
	for (int k = 0; k < 3; k++) EXPECT_TRUE(iotest::sameValue(a.rate_dph[k], b.rate_dph[k])) << where;
	EXPECT_EQ(a.thermistors, b.thermistors) << where;
	EXPECT_EQ(a.tempValid, b.tempValid) << where;
	ASSERT_EQ(a.temp_C.size(), b.temp_C.size()) << where;
	for (std::size_t i = 0; i < a.temp_C.size(); i++) EXPECT_TRUE(iotest::sameValue(a.temp_C[i], b.temp_C[i])) << where;
	EXPECT_EQ(a.hasTableRate, b.hasTableRate) << where;
	EXPECT_EQ(a.tableRate_dph, b.tableRate_dph) << where;
	EXPECT_EQ(a.hasField, b.hasField) << where;
	EXPECT_EQ(a.field_uT, b.field_uT) << where;
	EXPECT_EQ(a.hasPower, b.hasPower) << where;
	EXPECT_EQ(a.powerOn, b.powerOn) << where;
}
}  // namespace

TEST(FogObservationDecode, GivesWhatCArchiveGivesAndRefusesWhatItCannotVouchFor)
{
	registerAllClasses_mrpt_fog();
	std::mt19937_64 rng(11);
	const mrpt::poses::CPose3D pose(0.1, -0.2, 0.3, 0.4, 0.5, -0.6);
	const detail::SerializedPose sp{pose, detail::serializedPoseBytes(pose)};
	EXPECT_EQ(sp.bytes, serialized(pose));
	for (int trial = 0; trial < 50; trial++)
	{
		const auto o = makeObservation(rng, "FOG", pose, 1000 + trial);
		const std::string bytes = serialized(*o) + "trailing";
		CObservationFOG back;
		const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
		ASSERT_EQ(detail::decodeFogObservation(p, bytes.size(), sp, back), bytes.size() - 8);
		expectSameObservation(*o, back, "trial " + std::to_string(trial));
		// What CArchive decodes from the same bytes (the reference).
		mrpt::io::CMemoryStream mem;
		mem.assignMemoryNotOwn(bytes.data(), bytes.size());
		auto arch = mrpt::serialization::archiveFrom(mem);
		const auto ref = std::dynamic_pointer_cast<CObservationFOG>(arch.ReadObject());
		ASSERT_TRUE(ref);
		expectSameObservation(*ref, back, "vs CArchive, trial " + std::to_string(trial));
		// Every cut-short prefix is left to CArchive.
		if (trial == 0)
			for (std::size_t n = 0; n + 8 < bytes.size(); n++)
				EXPECT_EQ(detail::decodeFogObservation(p, n, sp, back), 0u) << "prefix " << n;
	}
	const auto o = makeObservation(rng, "FOG", pose, 7);
	const std::string good = serialized(*o);
	auto decodes = [&](const std::string& b, const detail::SerializedPose& with) {
		CObservationFOG back;
		return detail::decodeFogObservation(reinterpret_cast<const unsigned char*>(b.data()), b.size(), with, back);
	};
	EXPECT_EQ(decodes(good, sp), good.size());
	// Another pose than the expected one: left to CArchive.
	const mrpt::poses::CPose3D other(1, 0, 0, 0, 0, 0);
	EXPECT_EQ(decodes(good, {other, detail::serializedPoseBytes(other)}), 0u);
	// Corruptions serializeFrom refuses (or CArchive's header/end checks) are refused too.
	const std::size_t body = 1 + 25 + 1;
	auto corrupted = [&](std::size_t at, unsigned char v) {
		std::string b = good;
		b.at(at) = static_cast<char>(v);
		return b;
	};
	EXPECT_EQ(decodes(corrupted(0, 0x80 | 24), sp), 0u);  // class name length
	EXPECT_EQ(decodes(corrupted(25, 'X'), sp), 0u);  // class name
	EXPECT_EQ(decodes(corrupted(26, 1), sp), 0u);  // version 1
	const std::size_t axes_at = body + 8 + 4 + 3 + sp.bytes.size();
	ASSERT_EQ(good.at(axes_at), 5);  // x and z
	EXPECT_EQ(decodes(corrupted(axes_at, 0), sp), 0u);
	EXPECT_EQ(decodes(corrupted(axes_at, 8), sp), 0u);
	const std::size_t side_at = axes_at + 1 + 24 + 2 + 4 + 3;
	ASSERT_EQ(good.at(side_at), static_cast<char>(CoilSide::Inner));
	EXPECT_EQ(decodes(corrupted(side_at, 3), sp), 0u);
	std::string nan_angle = good;
	const double nan = std::nan("");
	std::memcpy(&nan_angle[side_at + 1], &nan, 8);
	EXPECT_EQ(decodes(nan_angle, sp), 0u);
	EXPECT_EQ(decodes(corrupted(good.size() - 1, 0x87), sp), 0u);  // end flag
	std::string long_count = good;  // thermistor count beyond the bytes present
	long_count[side_at - 3 - 4 - 2] = static_cast<char>(0xff);
	EXPECT_EQ(decodes(long_count, sp), 0u);
}

// A rawlog written by MRPT's own writer with what the fast path must hand back to CArchive
// (first object, pose changes, other sensors and classes, objects across the 256 KiB buffer):
// the reader gives exactly what CArchive reads.
TEST(FogRawlog, FastPathEqualsArchive)
{
	iotest::ScratchDir dir;
	std::mt19937_64 rng(5);
	const mrpt::poses::CPose3D a(0, 0, 0, 0, 0, 0), b(0.5, 0, 0.1, 0.2, 0, 0), c(0, 1, 0, 0, 0.3, 0);
	const std::string path = dir.path("mixed.rawlog");
	std::size_t objects = 0;
	{
		mrpt::io::CFileGZOutputStream f(path);
		auto arch = mrpt::serialization::archiveFrom(f);
		int64_t t = 17000000000000000;
		for (int k = 0; k < 4000; k++)
		{
			t += 100000;
			arch << *makeObservation(rng, "FOG", k < 1500 || k >= 3000 ? a : b, t);
			objects++;
			if (k % 97 == 0)
			{
				auto odo = mrpt::obs::CObservationOdometry::Create();
				odo->sensorLabel = "ODOMETRY";
				odo->timestamp = mrpt::Clock::time_point(mrpt::Clock::duration(t + 1));
				arch << *odo;
				objects++;
			}
			if (k >= 2000 && k < 2600 && k % 3 != 0)  // another FOG sensor with its own pose
			{
				arch << *makeObservation(rng, "FOG_IDEAL", c, t + 2);
				objects++;
			}
		}
	}
	// The reference: every object through MRPT's CArchive.
	std::vector<mrpt::serialization::CSerializable::Ptr> ref;
	{
		mrpt::io::CFileGZInputStream f(path);
		auto arch = mrpt::serialization::archiveFrom(f);
		for (std::size_t i = 0; i < objects; i++) ref.push_back(arch.ReadObject());
	}
	std::vector<mrpt::obs::CObservation::Ptr> others;
	FogLogReader reader(path, "FOG", ReadLimits{}, [&](const mrpt::obs::CObservation::Ptr& o) { others.push_back(o); });
	FogSample x;
	std::size_t fog = 0, other = 0;
	const int64_t epoch = mrpt::Clock::fromDouble(reader.header().epoch_s).time_since_epoch().count();
	std::vector<mrpt::serialization::CSerializable::Ptr> ref_others;
	for (const auto& r : ref)
	{
		const auto f = std::dynamic_pointer_cast<CObservationFOG>(r);
		if (!f || f->sensorLabel != "FOG")
		{
			ref_others.push_back(r);
			continue;
		}
		ASSERT_TRUE(reader.next(x)) << "FOG sample " << fog;
		const std::string where = "FOG sample " + std::to_string(fog++);
		EXPECT_EQ(x.time_s, static_cast<double>(f->timestamp.time_since_epoch().count() - epoch) / 1e7) << where;
		for (int k = 0; k < 3; k++)
			EXPECT_TRUE(iotest::sameValue(x.rate_dph[k], f->hasAxis[k] ? f->rate_dph[k] : std::nan(""))) << where;
		ASSERT_EQ(x.temp_C.size(), 3u);
		for (std::size_t i = 0; i < 3; i++) EXPECT_TRUE(iotest::sameValue(x.temp_C[i], f->temperature_C(i))) << where;
		EXPECT_EQ(x.table_rate_dph, f->tableRate_dph) << where;
		EXPECT_EQ(x.field_uT, f->field_uT) << where;
		EXPECT_EQ(x.power, f->powerOn ? 1.0 : 0.0) << where;
	}
	EXPECT_FALSE(reader.next(x));
	// The other objects reach the sink in file order, FOG_IDEAL (partly through the fast path) intact.
	ASSERT_EQ(others.size(), ref_others.size());
	for (const auto& r : ref_others)
	{
		EXPECT_EQ(std::string(others[other]->GetRuntimeClass()->className), r->GetRuntimeClass()->className);
		if (const auto f = std::dynamic_pointer_cast<CObservationFOG>(r))
			expectSameObservation(*f, dynamic_cast<const CObservationFOG&>(*others[other]),
								  "FOG_IDEAL object " + std::to_string(other));
		other++;
	}
	EXPECT_EQ(fog, 4000u);
	EXPECT_EQ(other, 42u + 400u);
	EXPECT_EQ(reader.objectsRead(), objects);
}
