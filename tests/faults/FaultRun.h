/* mrpt_fog: shared fixture of the fault-injection tests: a short simulated chamber run. */
#pragma once

#include <mrpt/containers/yaml.h>
#include <mrpt_fog/metrics/BiasMetrics.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/Compensator.h>
#include <mrpt_fog/sim/ChamberRun.h>

#include <cmath>
#include <cstdint>
#include <string>

namespace faulttest
{
/** 140 min chamber profile: hold, cool to 0 degC, hold, heat to 45 degC, hold, back to 25 degC
 * (1 degC/min ramps, as in the seed's test). Sampled at 1 Hz: 8401 samples. */
inline mrpt_fog::sim::ChamberProfile shortProfile()
{
	const char* yaml =
		"name: fault_short\n"
		"initial_temp_C: 25\n"
		"segments:\n"
		"  - {type: hold, duration_min: 10}\n"
		"  - {type: ramp, to_C: 0, rate_C_per_min: 1}\n"
		"  - {type: hold, duration_min: 15}\n"
		"  - {type: ramp, to_C: 45, rate_C_per_min: 1}\n"
		"  - {type: hold, duration_min: 15}\n"
		"  - {type: ramp, to_C: 25, rate_C_per_min: 1}\n"
		"  - {type: hold, duration_min: 10}\n";
	return mrpt_fog::sim::ChamberProfile::fromYaml(mrpt::containers::yaml::FromText(yaml), "fault_short");
}

/** The short run of the default simulated device with noise seed `seed`, 1 Hz. */
inline mrpt_fog::FogSeries simulatedRun(std::uint64_t seed)
{
	mrpt_fog::sim::SimSettings s;
	s.seed = seed;
	s.rate_hz = 1.0;
	return mrpt_fog::sim::simulateChamber(shortProfile(), mrpt_fog::sim::FogDevice::defaultDevice(), s);
}

/** Calibration run (seed 1) and validation run (seed 2, same profile, other noise). */
inline const mrpt_fog::FogSeries& calibrationRun()
{
	static const mrpt_fog::FogSeries r = simulatedRun(1);
	return r;
}
inline const mrpt_fog::FogSeries& validationRun()
{
	static const mrpt_fog::FogSeries r = simulatedRun(2);
	return r;
}

/** 4-thermistor multipoint calibration (with one fallback per thermistor) on calibrationRun(). */
inline const mrpt_fog::Calibration& calibration()
{
	static const mrpt_fog::Calibration c = mrpt_fog::fitCalibration({calibrationRun()}, "multipoint");
	return c;
}

/** 100 s bias stability [deg/h] of a compensated output. */
inline double stability100_dph(const mrpt_fog::CompensatedSeries& c)
{
	return mrpt_fog::biasStats(c.time_s, c.compensated_dph, 100.0).stability_dph;
}

/** Index of the first sample at or after time t [s]. */
inline std::size_t sampleAt(const mrpt_fog::FogSeries& s, double t)
{
	std::size_t k = 0;
	while (k < s.size() && s.time_s[k] < t) k++;
	return k;
}

}  // namespace faulttest

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <utility>

#include "support/ExceptionMessage.h"

namespace faulttest
{
/** A fresh scratch directory per test (removed at the end). */
class ScratchDir
{
   public:
	ScratchDir()
	{
		const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
		dir_ = std::filesystem::temp_directory_path() / ("mrpt_fog_faults_" + std::string(info->test_suite_name()) +
														  "_" + info->name() + "_" + std::to_string(::getpid()));
		std::filesystem::remove_all(dir_);
		std::filesystem::create_directories(dir_);
	}
	~ScratchDir()
	{
		std::error_code ec;
		std::filesystem::permissions(dir_, std::filesystem::perms::owner_all, std::filesystem::perm_options::add, ec);
		std::filesystem::remove_all(dir_, ec);
	}
	std::string path(const std::string& name) const { return (dir_ / name).string(); }
	const std::filesystem::path& dir() const { return dir_; }

   private:
	std::filesystem::path dir_;
};

inline std::string readBytes(const std::string& path)
{
	std::ifstream f(path, std::ios::binary);
	std::ostringstream o;
	o << f.rdbuf();
	return o.str();
}

inline void writeBytes(const std::string& path, const std::string& bytes)
{
	std::ofstream f(path, std::ios::binary | std::ios::trunc);
	f << bytes;
}

/** The first `n` samples of a series (same layout and metadata). */
inline mrpt_fog::FogSeries head(const mrpt_fog::FogSeries& s, std::size_t n)
{
	mrpt_fog::FogSeries out = s;
	out.resize(n);
	return out;
}

/** Runs f; returns the message of the exception of type E it must throw ("" + failure if not). */
template <class E, class F>
std::string errorOf(F&& f)
{
	return fogtest::messageOf<E>(std::forward<F>(f));
}

}  // namespace faulttest
