/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <gtest/gtest.h>
#include <mrpt/io/CFileGZInputStream.h>
#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CObservationComment.h>
#include <mrpt/obs/CObservationIMU.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRawDAQ.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>

#include <limits>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/io/RawlogObjectReader.h>
#include <mrpt/obs/CActionRobotMovement2D.h>
#include <mrpt/obs/CObservation2DRangeScan.h>
#include <mrpt_fog/io/AllocationGuard.h>
#include <mrpt_fog/io/GzFile.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>

#include "IoTestUtil.h"

using namespace mrpt_fog;
using iotest::dataFile;
using iotest::ioErrorOf;
using iotest::slurp;

namespace
{
/** A synthetic chamber-like series with known values (10 Hz, dropouts, all optional fields). */
FogSeries makeSeries(const std::string& label, std::size_t n, double epoch_s = 1700000000.0)
{
	std::mt19937_64 rng(3);
	std::normal_distribution<double> noise(0.0, 0.01);
	FogSeries s;
	s.sensor_label = label;
	s.epoch_s = epoch_s;
	s.has_axis = {false, false, true};
	s.thermistors = {{"Ti1", CoilSide::Inner, 0}, {"To1", CoilSide::Outer, 0}};
	s.temp_C.assign(2, {});
	for (std::size_t k = 0; k < n; k++)
	{
		s.time_s.push_back(static_cast<double>(k) / 10.0);  // the double nearest k/10 s, as a CSV gives
		s.rate_dph[2].push_back(0.5 + noise(rng));
		s.temp_C[0].push_back(k % 17 == 5 ? std::nan("") : 25.0 - 0.001 * k + noise(rng));
		s.temp_C[1].push_back(25.5 - 0.001 * k + noise(rng));
		s.table_rate_dph.push_back(15.041);
		s.field_uT.push_back(50 + noise(rng));
		s.power.push_back(1);
	}
	s.metadata = {{"latitude_deg", "30.5"}};
	return s;
}

mrpt::obs::CObservation::Ptr odometryAt(double t_unix, double x)
{
	auto o = mrpt::obs::CObservationOdometry::Create();
	o->sensorLabel = "ODOMETRY";
	o->timestamp = mrpt::Clock::fromDouble(t_unix);
	o->odometry = mrpt::poses::CPose2D(x, 2 * x, 0.1);
	return o;
}

/** Objects of a rawlog read with MRPT's plain archive (independent of our reader). */
std::vector<std::string> classNamesByStockReader(const std::string& path)
{
	std::vector<std::string> names;
	mrpt::io::CFileGZInputStream f(path);
	auto arch = mrpt::serialization::archiveFrom(f);
	for (;;)
	{
		try
		{
			names.push_back(arch.ReadObject()->GetRuntimeClass()->className);
		}
		catch (const std::exception&)
		{
			break;
		}
	}
	return names;
}

/** Rewrites a gz file after editing its decompressed bytes. */
void editRawlog(const std::string& in, const std::string& out, const std::function<void(std::string&)>& edit)
{
	std::string bytes = io::readWholeFile(in);
	edit(bytes);
	io::writeWholeFileAtomically(out, bytes, true);
}
}  // namespace

TEST(FogRawlog, CsvToRawlogToCsvKeepsEveryValue)
{
	iotest::ScratchDir dir;
	const FogSeries csv = readFogCsv(dataFile("sample.csv"));
	writeFogRawlog(dir.path("a.rawlog"), csv);
	const FogRawlogContents back = readFogRawlog(dir.path("a.rawlog"));
	EXPECT_EQ(back.objects_read, csv.size() + 1);  // + the metadata comment
	EXPECT_TRUE(back.others.empty());
	iotest::expectSameSeries(csv, back.fog);
	// And the CSV text written from both is byte-identical.
	writeFogCsv(dir.path("direct.csv"), csv);
	writeFogCsv(dir.path("via_rawlog.csv"), back.fog);
	EXPECT_EQ(slurp(dir.path("direct.csv")), slurp(dir.path("via_rawlog.csv")));
	// The printed values are the input's (same text cell by cell for the data rows).
	EXPECT_NE(slurp(dir.path("via_rawlog.csv")).find("0.3,1e-05,25.04,25.33,25.01,,15.041,,0\n"), std::string::npos);
}

TEST(FogRawlog, PowerOffRowsSurviveCsvRawlogCsvAndStockHasNoRateThere)
{
	iotest::ScratchDir dir;
	const FogSeries csv = readFogCsv(dataFile("power_cycle.csv"));
	std::size_t off = 0;
	for (std::size_t k = 0; k < csv.size(); k++) off += csv.gyroOn(k) ? 0 : 1;
	ASSERT_EQ(off, 225u);  // make_power_cycle.py: 3000 <= t < 3900 s at 4 s
	ASSERT_EQ(csv.turnOnSamples(), std::vector<std::size_t>({975}));
	writeFogRawlog(dir.path("p.rawlog"), csv);
	const FogRawlogContents back = readFogRawlog(dir.path("p.rawlog"));
	iotest::expectSameSeries(csv, back.fog);
	writeFogCsv(dir.path("direct.csv"), csv);
	writeFogCsv(dir.path("via_rawlog.csv"), back.fog);
	EXPECT_EQ(slurp(dir.path("direct.csv")), slurp(dir.path("via_rawlog.csv")));
	EXPECT_NE(slurp(dir.path("via_rawlog.csv")).find("\n3000,,11.95,7.47,0\n"), std::string::npos);
	// Stock form: the IMU observation of a power-off row carries no rate (absent, not NaN).
	const auto stock = stockObservationsForRawlog(csv);
	std::size_t imu_without_rate = 0, imu_with_rate = 0;
	for (const auto& o : stock)
		if (auto imu = std::dynamic_pointer_cast<mrpt::obs::CObservationIMU>(o))
		{
			if (imu->has(mrpt::obs::IMU_WZ))
			{
				EXPECT_TRUE(std::isfinite(imu->get(mrpt::obs::IMU_WZ)));
				imu_with_rate++;
			}
			else
				imu_without_rate++;
		}
	EXPECT_EQ(imu_without_rate, 225u);
	EXPECT_EQ(imu_with_rate, csv.size() - 225u);
}

TEST(FogRawlog, TimesAreExactToTheTickFarFromTheEpoch)
{
	iotest::ScratchDir dir;
	FogSeries s = makeSeries("FOG", 2000);
	s.epoch_s = 1767225600.0;  // 2026: a double of UNIX seconds resolves only ~0.24 us here
	// Irregular times with 7 decimals (MRPT's 100 ns tick), e.g. 0.0123457 s steps.
	for (std::size_t k = 0; k < s.size(); k++) s.time_s[k] = static_cast<double>(123457 * k + k * k % 7) / 1e7;
	writeFogRawlog(dir.path("t.rawlog"), s);
	const FogSeries back = readFogRawlog(dir.path("t.rawlog")).fog;
	ASSERT_EQ(back.size(), s.size());
	for (std::size_t k = 0; k < s.size(); k++) ASSERT_EQ(back.time_s[k], s.time_s[k]) << k;
}

TEST(FogRawlog, FinerTimesAreRoundedToTheNearest100ns)
{
	iotest::ScratchDir dir;
	FogSeries s = makeSeries("FOG", 100);
	for (std::size_t k = 0; k < s.size(); k++) s.time_s[k] = 0.1 * static_cast<double>(k) + 1.23e-9 * k;
	writeFogRawlog(dir.path("t.rawlog"), s);
	const FogSeries back = readFogRawlog(dir.path("t.rawlog")).fog;
	for (std::size_t k = 0; k < s.size(); k++)
		EXPECT_EQ(back.time_s[k], std::round(s.time_s[k] * 1e7) / 1e7) << k;
}

TEST(FogRawlog, WithoutMetadataCommentTheEpochIsTheFirstWholeSecond)
{
	iotest::ScratchDir dir;
	const FogSeries s = makeSeries("FOG", 20, 1700000000.0);
	std::vector<mrpt::obs::CObservation::Ptr> objs;
	for (auto& o : observationsFromSeries(s)) objs.push_back(o);
	writeRawlogObservations(dir.path("plain.rawlog"), objs);
	const FogSeries back = readFogRawlog(dir.path("plain.rawlog")).fog;
	EXPECT_EQ(back.epoch_s, 1700000000.0);
	EXPECT_TRUE(back.metadata.empty());
	for (std::size_t k = 0; k < s.size(); k++) EXPECT_NEAR(back.time_s[k], s.time_s[k], 1e-6);
}

TEST(FogRawlog, OtherObservationsPassThroughMergedByTime)
{
	iotest::ScratchDir dir;
	const FogSeries s = makeSeries("FOG", 50);
	std::vector<mrpt::obs::CObservation::Ptr> others;
	for (int i = 0; i < 10; i++) others.push_back(odometryAt(s.epoch_s + 0.45 * i + 0.05, i));
	auto imu = mrpt::obs::CObservationIMU::Create();
	imu->sensorLabel = "IMU";
	imu->timestamp = mrpt::Clock::fromDouble(s.epoch_s + 4.55);
	imu->set(mrpt::obs::IMU_WZ, 0.01);
	others.push_back(imu);
	writeFogRawlog(dir.path("o.rawlog"), s, others);

	const FogRawlogContents back = readFogRawlog(dir.path("o.rawlog"));
	EXPECT_EQ(back.objects_read, 1 + s.size() + others.size());
	ASSERT_EQ(back.others.size(), others.size());
	for (int i = 0; i < 10; i++)
	{
		auto o = std::dynamic_pointer_cast<mrpt::obs::CObservationOdometry>(back.others[i]);
		ASSERT_TRUE(o);
		EXPECT_EQ(o->timestamp, others[i]->timestamp);
		EXPECT_EQ(o->odometry.x(), i);
		EXPECT_EQ(o->odometry.y(), 2.0 * i);
	}
	auto imu_back = std::dynamic_pointer_cast<mrpt::obs::CObservationIMU>(back.others[10]);
	ASSERT_TRUE(imu_back);
	EXPECT_EQ(imu_back->get(mrpt::obs::IMU_WZ), 0.01);
	iotest::expectSameSeries(s, back.fog);

	// In the file, objects after the comment are in non-decreasing time order (MRPT's own reader).
	mrpt::io::CFileGZInputStream f(dir.path("o.rawlog"));
	auto arch = mrpt::serialization::archiveFrom(f);
	std::vector<mrpt::Clock::time_point> times;
	for (std::size_t i = 0; i < back.objects_read; i++)
		times.push_back(std::dynamic_pointer_cast<mrpt::obs::CObservation>(arch.ReadObject())->timestamp);
	EXPECT_TRUE(std::is_sorted(times.begin() + 1, times.end()));
}

TEST(FogRawlog, SensoryFramesAreUnpacked)
{
	iotest::ScratchDir dir;
	const FogSeries s = makeSeries("FOG", 12);
	const auto obs = observationsFromSeries(s);
	{
		mrpt::io::CFileGZOutputStream f(dir.path("sf.rawlog"));
		auto arch = mrpt::serialization::archiveFrom(f);
		for (std::size_t k = 0; k < obs.size(); k += 3)
		{
			mrpt::obs::CSensoryFrame sf;
			for (std::size_t j = k; j < k + 3; j++) sf.insert(obs[j]);
			arch << sf;
		}
	}
	const FogRawlogContents back = readFogRawlog(dir.path("sf.rawlog"));
	EXPECT_EQ(back.objects_read, 4u);
	ASSERT_EQ(back.fog.size(), 12u);
	for (std::size_t k = 0; k < 12; k++) EXPECT_EQ(back.fog.rate_dph[2][k], s.rate_dph[2][k]);
}

// The actions-observations format with another sensor: the sample reader takes the FOG from the
// frames and skips the actions; the object reader gives every object as it stands.
TEST(FogRawlog, ActionsFormatWithOtherSensorsIsRead)
{
	iotest::ScratchDir dir;
	const FogSeries s = makeSeries("FOG", 12);
	const auto obs = observationsFromSeries(s);
	{
		mrpt::io::CFileGZOutputStream f(dir.path("act.rawlog"));
		auto arch = mrpt::serialization::archiveFrom(f);
		for (std::size_t k = 0; k < obs.size(); k += 3)
		{
			mrpt::obs::CActionCollection acts;
			mrpt::obs::CActionRobotMovement2D mv;
			mv.computeFromOdometry(mrpt::poses::CPose2D(0.5, 0, 0.01), {});
			mv.timestamp = obs[k]->timestamp;
			acts.insert(mv);
			arch << acts;
			mrpt::obs::CSensoryFrame sf;
			for (std::size_t j = k; j < k + 3; j++) sf.insert(obs[j]);
			auto scan = mrpt::obs::CObservation2DRangeScan::Create();
			scan->sensorLabel = "LIDAR";
			scan->timestamp = obs[k]->timestamp;
			scan->resizeScan(181);
			for (std::size_t i = 0; i < 181; i++) scan->setScanRange(i, 1.0f + i), scan->setScanRangeValidity(i, true);
			sf.insert(scan);
			arch << sf;
		}
	}
	const FogRawlogContents back = readFogRawlog(dir.path("act.rawlog"));
	ASSERT_EQ(back.fog.size(), 12u);
	EXPECT_EQ(back.objects_read, 8u);
	EXPECT_EQ(back.others.size(), 4u);  // the scans
	RawlogObjectReader r(dir.path("act.rawlog"));
	std::size_t frames = 0, collections = 0;
	while (auto o = r.next())
	{
		if (auto sf = std::dynamic_pointer_cast<mrpt::obs::CSensoryFrame>(o))
		{
			frames++;
			auto scan = sf->getObservationByClass<mrpt::obs::CObservation2DRangeScan>();
			ASSERT_TRUE(scan);
			ASSERT_EQ(scan->getScanSize(), 181u);
			EXPECT_EQ(scan->getScanRange(180), 181.0f);
		}
		else if (std::dynamic_pointer_cast<mrpt::obs::CActionCollection>(o))
			collections++;
	}
	EXPECT_EQ(frames, 4u);
	EXPECT_EQ(collections, 4u);
	EXPECT_EQ(r.format(), RawlogFormat::ActionsObservations);
	// MRPT's aligned allocations reach the guard in this program (else other classes are refused)
	EXPECT_TRUE(io::detail::AllocationGuard::active());
}

TEST(FogRawlog, SeveralFogLabelsAreSelectable)
{
	iotest::ScratchDir dir;
	const FogSeries real = makeSeries("FOG", 30);
	FogSeries ideal = makeSeries("FOG_IDEAL", 30);
	for (auto& r : ideal.rate_dph[2]) r = 0.25;
	std::vector<mrpt::obs::CObservation::Ptr> others;
	for (auto& o : fogObservationsForRawlog(ideal)) others.push_back(o);
	others.erase(others.begin());  // FOG_IDEAL samples only, no second metadata block
	writeFogRawlog(dir.path("drive.rawlog"), real, others);

	const std::string msg = ioErrorOf([&] { readFogRawlog(dir.path("drive.rawlog")); });
	EXPECT_NE(msg.find("several FOG sensors 'FOG' (30), 'FOG_IDEAL' (30)"), std::string::npos) << msg;
	const auto a = readFogRawlog(dir.path("drive.rawlog"), "FOG");
	iotest::expectSameSeries(real, a.fog);
	EXPECT_EQ(a.others.size(), 30u);
	const auto b = readFogRawlog(dir.path("drive.rawlog"), "FOG_IDEAL");
	EXPECT_EQ(b.fog.rate_dph[2], ideal.rate_dph[2]);
	EXPECT_EQ(b.others.size(), 31u);  // FOG samples + FOG's metadata comment, untouched
	const std::string absent = ioErrorOf([&] { readFogRawlog(dir.path("drive.rawlog"), "GYRO"); });
	EXPECT_NE(absent.find("no FOG sensor labelled 'GYRO'"), std::string::npos) << absent;
}

// A stock MRPT reader stops silently at an unregistered class; ours must not.
TEST(FogRawlog, UnknownClassIsReportedWithWhereAndWhat)
{
	iotest::ScratchDir dir;
	writeFogRawlog(dir.path("ok.rawlog"), makeSeries("FOG", 10));
	const std::string cls = "mrpt_fog::CObservationFOG";
	editRawlog(dir.path("ok.rawlog"), dir.path("unknown.rawlog"), [&](std::string& b) {
		// Rename the class of the 5th FOG sample (object #5) to an unregistered one.
		std::size_t p = 0;
		for (int i = 0; i < 5; i++) p = b.find(cls, p) + cls.size();
		ASSERT_NE(p, std::string::npos);
		b[p - 1] = 'X';
	});
	EXPECT_EQ(classNamesByStockReader(dir.path("unknown.rawlog")).size(), 5u);  // stock: stops, no error
	const std::string msg = ioErrorOf([&] { readFogRawlog(dir.path("unknown.rawlog")); });
	EXPECT_NE(msg.find("unknown.rawlog: read 5 objects, then stopped at object #5 (byte offset"), std::string::npos)
		<< msg;
	EXPECT_NE(msg.find("unknown class 'mrpt_fog::CObservationFOX'"), std::string::npos) << msg;
}

TEST(FogRawlog, CutInTheMiddleOfAnObject)
{
	iotest::ScratchDir dir;
	writeFogRawlog(dir.path("ok.rawlog"), makeSeries("FOG", 10));
	const std::size_t full = io::readWholeFile(dir.path("ok.rawlog")).size();
	editRawlog(dir.path("ok.rawlog"), dir.path("cut.rawlog"), [&](std::string& b) { b.resize(b.size() - 20); });
	const std::string msg = ioErrorOf([&] { readFogRawlog(dir.path("cut.rawlog")); });
	EXPECT_NE(msg.find("read 10 objects, then stopped at object #10"), std::string::npos) << msg;
	EXPECT_NE(msg.find(std::to_string(full - 20) + " bytes in all"), std::string::npos) << msg;
	EXPECT_NE(msg.find("ends in the middle of this object (truncated file"), std::string::npos) << msg;
}

TEST(FogRawlog, TruncatedGzipIsDetectedEvenAtAnObjectBoundary)
{
	iotest::ScratchDir dir;
	writeFogRawlog(dir.path("ok.rawlog"), makeSeries("FOG", 200));
	const std::string gz = slurp(dir.path("ok.rawlog"));
	for (std::size_t cut : {std::size_t(4), std::size_t(8), gz.size() / 2})
	{
		{
			std::ofstream f(dir.path("cut.rawlog"), std::ios::binary | std::ios::trunc);
			f.write(gz.data(), static_cast<std::streamsize>(gz.size() - cut));
		}
		const std::string msg = ioErrorOf([&] { readFogRawlog(dir.path("cut.rawlog")); });
		EXPECT_NE(msg.find("cut.rawlog"), std::string::npos) << msg;
		EXPECT_NE(msg.find("truncated"), std::string::npos) << msg;
	}
}

TEST(FogRawlog, EmptyAndMissingFiles)
{
	iotest::ScratchDir dir;
	std::ofstream(dir.path("empty.rawlog")).close();
	EXPECT_NE(ioErrorOf([&] { readFogRawlog(dir.path("empty.rawlog")); }).find("empty rawlog"), std::string::npos);
	EXPECT_NE(ioErrorOf([&] { readFogRawlog(dir.path("none.rawlog")); }).find("none.rawlog"), std::string::npos);
	std::vector<mrpt::obs::CObservation::Ptr> objs{odometryAt(1.0, 0)};
	writeRawlogObservations(dir.path("nofog.rawlog"), objs);
	EXPECT_NE(ioErrorOf([&] { readFogRawlog(dir.path("nofog.rawlog")); }).find("no CObservationFOG"), std::string::npos);
}

TEST(FogRawlog, StockFormHasImuAndDaqValues)
{
	const FogSeries s = makeSeries("FOG", 20);
	const auto objs = stockObservationsForRawlog(s);
	ASSERT_EQ(objs.size(), 40u);
	for (std::size_t k = 0; k < s.size(); k++)
	{
		auto imu = std::dynamic_pointer_cast<mrpt::obs::CObservationIMU>(objs[2 * k]);
		auto daq = std::dynamic_pointer_cast<mrpt::obs::CObservationRawDAQ>(objs[2 * k + 1]);
		ASSERT_TRUE(imu && daq);
		EXPECT_DOUBLE_EQ(imu->get(mrpt::obs::IMU_WZ), s.rate_dph[2][k] * M_PI / 180.0 / 3600.0);
		ASSERT_EQ(daq->AIN_double.size(), 2u);
		EXPECT_TRUE(iotest::sameValue(daq->AIN_double[0], s.temp_C[0][k]));
		EXPECT_EQ(daq->AIN_double[1], s.temp_C[1][k]);
		EXPECT_EQ(imu->timestamp, daq->timestamp);
	}
}

TEST(FogRawlog, FailedWriteLeavesNoFile)
{
	iotest::ScratchDir dir;
	FogSeries bad = makeSeries("FOG", 5);
	bad.rate_dph[2][3] = std::nan("");
	const std::string msg = ioErrorOf([&] { writeFogRawlog(dir.path("bad.rawlog"), bad); });
	EXPECT_NE(msg.find("bad.rawlog"), std::string::npos) << msg;
	EXPECT_FALSE(std::filesystem::exists(dir.path("bad.rawlog")));
	ioErrorOf([&] { writeFogRawlog("/nonexistent/dir/x.rawlog", makeSeries("FOG", 5)); });
	FogSeries multi_line = makeSeries("FOG", 5);
	multi_line.metadata.emplace_back("note", "a\nb");  // would not survive the metadata comment
	EXPECT_NE(ioErrorOf([&] { writeFogRawlog(dir.path("m.rawlog"), multi_line); }).find("metadata key 'note'"),
			  std::string::npos);
	EXPECT_FALSE(std::filesystem::exists(dir.path("m.rawlog")));
}

TEST(FogLogIO, DispatchesByExtension)
{
	iotest::ScratchDir dir;
	const FogSeries s = readFogLog(dataFile("sample.csv"));
	for (const char* name : {"x.rawlog", "x.csv", "x.csv.gz"})
	{
		writeFogLog(dir.path(name), s);
		iotest::expectSameSeries(s, readFogLog(dir.path(name)));
	}
	EXPECT_NE(ioErrorOf([&] { writeFogLog(dir.path("x.txt"), s); }).find("unknown file type '.txt'"), std::string::npos);
	EXPECT_NE(ioErrorOf([&] { readFogLog(dataFile("sample.csv"), "OTHER"); }).find("not 'OTHER'"), std::string::npos);
}


// Found by fuzz_rawlog: a thermistor angle read as NaN made the first observation's layout unequal
// to itself, and the reader threw std::invalid_argument ("observation 0 has a different layout
// than the first one") instead of FogIoError. A non-finite angle is now a corrupt object.
TEST(FogRawlog, NonFiniteThermistorAngleIsACorruptObject)
{
	iotest::ScratchDir dir;
	const FogSeries s = makeSeries("FOG", 5);
	std::vector<mrpt::obs::CObservation::Ptr> objs;
	for (auto& o : observationsFromSeries(s))
	{
		o->thermistors.at(0).angle_deg = std::numeric_limits<double>::quiet_NaN();
		objs.push_back(o);
	}
	writeRawlogObservations(dir.path("nan_angle.rawlog"), objs);
	const std::string e = ioErrorOf([&] { readFogRawlog(dir.path("nan_angle.rawlog")); });
	EXPECT_NE(e.find("nan_angle.rawlog"), std::string::npos) << e;
	EXPECT_NE(e.find("thermistor angle"), std::string::npos) << e;
}
