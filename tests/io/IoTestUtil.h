/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once
/* Helpers shared by the io tests: scratch files and exception-message checks. */

#include <gtest/gtest.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <functional>
#include <string>

#include "support/ExceptionMessage.h"

namespace iotest
{
inline std::string dataFile(const std::string& name) { return std::string(FOG_TEST_DATA_DIR) + "/io/" + name; }

/** The bytes of a file ("" when it cannot be read). */
inline std::string slurp(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	return std::string(std::istreambuf_iterator<char>(f), {});
}

/** Writes text to a file (replacing it). */
inline void spit(const std::string& path, const std::string& text)
{
	std::ofstream f(path, std::ios::binary);
	f << text;
}

/** A fresh scratch directory per test (removed at the end). */
class ScratchDir
{
   public:
	ScratchDir()
	{
		const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
		dir_ = std::filesystem::temp_directory_path() /
			   ("mrpt_fog_io_" + std::string(info->test_suite_name()) + "_" + info->name() + "_" +
				std::to_string(::getpid()));
		std::filesystem::remove_all(dir_);
		std::filesystem::create_directories(dir_);
	}
	~ScratchDir() { std::filesystem::remove_all(dir_); }
	std::string path(const std::string& name) const { return (dir_ / name).string(); }

   private:
	std::filesystem::path dir_;
};

/** Runs f, expects a FogIoError, returns its message ("" and a failure if none). */
inline std::string ioErrorOf(const std::function<void()>& f) { return fogtest::messageOf<mrpt_fog::FogIoError>(f); }

/** Both NaN, or exactly equal. */
inline bool sameValue(double a, double b) { return (std::isnan(a) && std::isnan(b)) || a == b; }

inline void expectSameSeries(const mrpt_fog::FogSeries& a, const mrpt_fog::FogSeries& b)
{
	EXPECT_EQ(a.sensor_label, b.sensor_label);
	EXPECT_EQ(a.epoch_s, b.epoch_s);
	EXPECT_TRUE(a.sameLayout(b));
	EXPECT_EQ(a.metadata, b.metadata);
	ASSERT_EQ(a.size(), b.size());
	for (std::size_t k = 0; k < a.size(); k++)
	{
		EXPECT_EQ(a.time_s[k], b.time_s[k]) << "sample " << k;
		for (int ax = 0; ax < 3; ax++)
			if (a.has_axis[ax])  // NaN == NaN here: a power-off row has no rate sample
				EXPECT_TRUE(sameValue(a.rate_dph[ax][k], b.rate_dph[ax][k])) << "axis " << ax << " sample " << k;
		for (std::size_t i = 0; i < a.temp_C.size(); i++)
			EXPECT_TRUE(sameValue(a.temp_C[i][k], b.temp_C[i][k]))
				<< "thermistor " << i << " sample " << k << ": " << a.temp_C[i][k] << " vs " << b.temp_C[i][k];
	}
	ASSERT_EQ(a.table_rate_dph.size(), b.table_rate_dph.size());
	for (std::size_t k = 0; k < a.table_rate_dph.size(); k++) EXPECT_TRUE(sameValue(a.table_rate_dph[k], b.table_rate_dph[k]));
	ASSERT_EQ(a.field_uT.size(), b.field_uT.size());
	for (std::size_t k = 0; k < a.field_uT.size(); k++) EXPECT_TRUE(sameValue(a.field_uT[k], b.field_uT[k]));
	EXPECT_EQ(a.power, b.power);
}

}  // namespace iotest
