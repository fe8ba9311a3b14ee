/* A synthetic vehicle drive with closed-form truth, for the fog-drift integration test
 * (tests/integration/nav.cmake):
 *
 *   nav_test_drive write DRIVE.rawlog CAL.yaml
 *       20 min on a circle (v = 10 m/s, one lap per 300 s, latitude 40 deg), 10 Hz, one
 *       thermistor warming from -10 C towards +20 C (tau 600 s):
 *       "FOG"       = yaw rate + Earth rate Omega sin(40 deg) + bias(T),
 *                     bias(T) = 2 deg/h + 0.05 deg/h/C * (T - 25 C): a known thermal error
 *       "FOG_IDEAL" = yaw rate + Earth rate
 *       "ODOMETRY"  = wheel odometry whose own heading is 1 % off (curvature 1.01 r) but
 *                     whose distances are exact: fog-drift must take heading from the gyro
 *       "GROUND_TRUTH" = the circle at 1 Hz
 *       (a second thermistor To1 = T - 3 C carries no information; it is there because a
 *       one-thermistor calibration YAML does not load yet: its fallback model has an empty
 *       signal list, which MRPT's YAML parser rejects)
 *       CAL.yaml: a calibration fitted (library fitCalibration, preset multipoint) on a static
 *       noise-free chamber run at the same site (-20..40 C ramp, bias(T) + Earth rate), so it
 *       absorbs the Earth rate as real static calibrations do.
 *   nav_test_drive check DRIFT.json
 *       ideal: heading error < 1e-4 deg and position error < 1e-3 m (constant-rate circle:
 *              the trapezoid and arc models are exact; the limit is float rounding);
 *       raw: final heading error = integral of bias(T(t)) over the 1200 s, in closed form
 *              (0.3672 deg), to 1e-4 deg;
 *       compensated: heading error < 1e-3 deg (the bias law is inside the model's class and
 *              the data are noise-free, so what remains is fit rounding: this checks the
 *              plumbing - sign, time alignment, the Earth rate removed exactly once).
 *   nav_test_drive write-gap DRIVE.rawlog CAL.yaml
 *       the same drive with the gyro off for 400 s < t < 650 s (power 0; "FOG" with an empty
 *       rate there, "FOG_IDEAL" with 0 deg/h, as fog-sim wrote before: a value that is no
 *       measurement). The vehicle turns 300 deg meanwhile, which no gyro sees.
 *   nav_test_drive check-gap DRIFT.json
 *       gyro_off: one stretch of 250 s (400 .. 650 s) whose truth heading change is 300 deg
 *              (closed form: kR x 250 s), figures over the 2 powered spans;
 *       ideal: heading error < 1e-4 deg and position error < 1e-3 m (each powered span is
 *              re-aligned from the truth at its start: nothing of the 300 deg is counted);
 *       raw: final heading error = integral of bias(T(t)) over 650 .. 1200 s (the last span,
 *              from its re-alignment) and max = the larger of that and the integral over
 *              0 .. 400 s, in closed form, to 1e-4 deg;
 *       compensated: heading error < 1e-3 deg.
 * Exit 0 = pass. */
#include <mrpt/core/Clock.h>
#include <mrpt/obs/CObservationOdometry.h>
#include <mrpt/obs/CObservationRobotPose.h>
#include <mrpt_fog/io/FogLogIO.h>
#include <mrpt_fog/model/Calibration.h>
#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/obs/CObservationFOG.h>
#include <mrpt_fog/obs/FogSeriesConversion.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog/obs/registerAllClasses.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>
#include <regex>
#include <sstream>

using namespace mrpt_fog;

namespace
{
constexpr double kEpoch = 1.7e9, kDuration = 1200.0, kDt = 0.1, kLat = 40.0;
constexpr double kV = 10.0, kR = 2 * units::kPi / 300.0;
constexpr double kBc_dph = 2.0, kK_dph_per_C = 0.05, kTref_C = 25.0;  // bias(T)
constexpr double kTstart_C = -10.0, kTrise_C = 30.0, kTau_s = 600.0;  // drive temperature

double driveTemp_C(double t) { return kTstart_C + kTrise_C * (1 - std::exp(-t / kTau_s)); }
double bias_dph(double T_C) { return kBc_dph + kK_dph_per_C * (T_C - kTref_C); }
double earthUp_dph() { return units::kEarthRate_dph * std::sin(kLat * units::kDegToRad); }
constexpr double kOffFrom_s = 400.0, kOnAt_s = 650.0;  // write-gap: the gyro is off for kOffFrom_s < t < kOnAt_s

/** Integral of bias(T(t)) over [0, T] [deg/h x s]. */
double biasIntegral(double T)
{
	return kBc_dph * T + kK_dph_per_C * ((kTstart_C - kTref_C) * T + kTrise_C * (T - kTau_s * (1 - std::exp(-T / kTau_s))));
}

/** Static chamber run for the calibration: 2 h linear ramp -20 -> 40 C at 1 Hz, noise-free. */
FogSeries chamberRun()
{
	FogSeries s;
	s.sensor_label = "FOG";
	s.epoch_s = kEpoch - 86400.0;
	s.has_axis = {false, false, true};
	s.thermistors = {{"Ti1", CoilSide::Inner, 0.0}, {"To1", CoilSide::Outer, 0.0}};
	const int n = 7200;
	s.resize(n + 1);
	for (int k = 0; k <= n; ++k)
	{
		s.time_s[k] = k;
		s.temp_C[0][k] = -20.0 + 60.0 * k / n;
		s.temp_C[1][k] = s.temp_C[0][k] - 3.0 + 2.0 * std::sin(2 * units::kPi * k / 1800.0);
		s.rate_dph[2][k] = earthUp_dph() + bias_dph(s.temp_C[0][k]);
	}
	return s;
}

FogSeries gyro(const std::string& label, bool with_bias, bool gap = false)
{
	FogSeries s;
	s.sensor_label = label;
	s.epoch_s = kEpoch;
	s.has_axis = {false, false, true};
	s.thermistors = {{"Ti1", CoilSide::Inner, 0.0}, {"To1", CoilSide::Outer, 0.0}};
	s.setMetadata("latitude_deg", "40");
	const int n = static_cast<int>(kDuration / kDt);
	s.resize(n + 1);
	for (int k = 0; k <= n; ++k)
	{
		const double t = k * kDt;
		s.time_s[k] = t;
		s.temp_C[0][k] = driveTemp_C(t);
		s.temp_C[1][k] = driveTemp_C(t) - 3.0;
		double r = kR * units::kRadPerSecToDegPerHour + earthUp_dph();
		if (with_bias) r += bias_dph(s.temp_C[0][k]);
		s.rate_dph[2][k] = r;
	}
	if (gap)
	{
		s.power.assign(s.size(), 1.0);
		for (int k = 0; k <= n; ++k)
			if (k > static_cast<int>(kOffFrom_s / kDt + 0.5) && k < static_cast<int>(kOnAt_s / kDt + 0.5))
			{
				s.power[k] = 0.0;
				s.rate_dph[2][k] = with_bias ? std::numeric_limits<double>::quiet_NaN() : 0.0;
			}
	}
	return s;
}

int write(const std::string& path, const std::string& cal_path, bool gap)
{
	saveCalibrationYaml(fitCalibration({chamberRun()}, "multipoint"), cal_path);
	std::vector<mrpt::obs::CObservation::Ptr> others;
	const FogSeries ideal = gyro("FOG_IDEAL", false, gap);
	const auto ideal_obs = observationsFromSeries(ideal);
	for (std::size_t k = 0; k < ideal_obs.size(); ++k)
	{
		ideal_obs[k]->timestamp = mrpt::Clock::fromDouble(kEpoch + ideal.time_s[k]);
		others.push_back(ideal_obs[k]);
	}
	const double r_odo = 1.01 * kR, radius_odo = kV / r_odo, radius = kV / kR;
	const int n = static_cast<int>(kDuration / kDt);
	for (int k = 0; k <= n; ++k)
	{
		const double t = k * kDt;
		auto odo = mrpt::obs::CObservationOdometry::Create();
		odo->sensorLabel = "ODOMETRY";
		odo->timestamp = mrpt::Clock::fromDouble(kEpoch + t);
		odo->odometry = mrpt::poses::CPose2D(radius_odo * std::sin(r_odo * t), radius_odo * (1 - std::cos(r_odo * t)), r_odo * t);
		others.push_back(odo);
		if (k % 10 == 0)
		{
			auto gt = mrpt::obs::CObservationRobotPose::Create();
			gt->sensorLabel = "GROUND_TRUTH";
			gt->timestamp = mrpt::Clock::fromDouble(kEpoch + t);
			gt->pose.mean = mrpt::poses::CPose3D(radius * std::sin(kR * t), radius * (1 - std::cos(kR * t)), 0, kR * t, 0, 0);
			others.push_back(gt);
		}
	}
	std::stable_sort(others.begin(), others.end(), [](const auto& a, const auto& b) { return a->timestamp < b->timestamp; });
	writeFogRawlog(path, gyro("FOG", true, gap), others);
	std::printf("nav_test_drive: wrote %s\n", path.c_str());
	return 0;
}

double jsonNumber(const std::string& text, const std::string& table, const std::string& variant)
{
	const std::regex re("\"" + table + "\"\\s*:\\s*\\{[^}]*\"" + variant + "\"\\s*:\\s*([-+0-9.eE]+)");
	std::smatch m;
	if (!std::regex_search(text, m, re)) throw std::runtime_error("JSON: no number for " + table + "." + variant);
	return std::stod(m[1]);
}

std::string readText(const std::string& path)
{
	std::ifstream in(path);
	std::stringstream ss;
	ss << in.rdbuf();
	if (ss.str().empty()) throw std::runtime_error(path + ": empty or missing");
	return ss.str();
}

/** The number after "key": in text (the first one). */
double jsonField(const std::string& text, const std::string& key)
{
	const std::regex re("\"" + key + "\"\\s*:\\s*([-+0-9.eE]+)");
	std::smatch m;
	if (!std::regex_search(text, m, re)) throw std::runtime_error("JSON: no number for " + key);
	return std::stod(m[1]);
}

int checkGap(const std::string& json_path)
{
	const std::string j = readText(json_path);
	const double total_s = jsonField(j, "total_s"), duration_s = jsonField(j, "duration_s");
	const double off_s = jsonField(j, "off_s"), on_s = jsonField(j, "on_s");
	const double turned_deg = jsonField(j, "truth_heading_change_deg");
	const double spans = jsonField(j, "powered_spans"), navigated = jsonField(j, "powered_spans_navigated");
	std::size_t stretches = 0;  // one object per stretch, each with its truth heading change
	for (std::size_t p = j.find("\"truth_heading_change_deg\""); p != std::string::npos;
		 p = j.find("\"truth_heading_change_deg\"", p + 1))
		stretches++;
	const bool one = stretches == 1;
	const double expected_turn_deg = kR * (kOnAt_s - kOffFrom_s) * units::kRadToDeg;  // 300 deg
	const double ideal_h = jsonNumber(j, "heading_error_max_deg", "ideal");
	const double ideal_p = jsonNumber(j, "position_error_max_m", "ideal");
	const double raw_final = jsonNumber(j, "heading_error_final_deg", "raw");
	const double raw_max = jsonNumber(j, "heading_error_max_deg", "raw");
	const double comp_h = jsonNumber(j, "heading_error_max_deg", "compensated");
	const double span1_deg = std::abs(biasIntegral(kOffFrom_s) / 3600.0);
	const double span2_deg = std::abs((biasIntegral(kDuration) - biasIntegral(kOnAt_s)) / 3600.0);
	std::printf("nav_test_drive: gyro off %.6g s (%.6g .. %.6g s, %g of %g spans navigated), truth turned %.6f deg "
				"(closed form %.6f); ideal heading max %.3g deg, position max %.3g m; raw heading final %.6f deg "
				"(closed form %.6f), max %.6f (closed form %.6f); compensated heading max %.3g deg\n",
				total_s, off_s, on_s, navigated, spans, turned_deg, expected_turn_deg, ideal_h, ideal_p, raw_final,
				span2_deg, raw_max, std::max(span1_deg, span2_deg), comp_h);
	const bool ok = one && std::abs(total_s - (kOnAt_s - kOffFrom_s)) < 1e-6 && total_s == duration_s &&
					std::abs(off_s - kOffFrom_s) < 1e-6 && std::abs(on_s - kOnAt_s) < 1e-6 &&
					std::abs(turned_deg - expected_turn_deg) < 1e-6 && spans == 2 && navigated == 2 && ideal_h < 1e-4 &&
					ideal_p < 1e-3 && std::abs(raw_final - span2_deg) < 1e-4 &&
					std::abs(raw_max - std::max(span1_deg, span2_deg)) < 1e-4 && comp_h < 1e-3;
	return ok ? 0 : 1;
}

int check(const std::string& json_path)
{
	const std::string j = readText(json_path);
	const double ideal_h = jsonNumber(j, "heading_error_max_deg", "ideal");
	const double ideal_p = jsonNumber(j, "position_error_max_m", "ideal");
	const double raw_h = jsonNumber(j, "heading_error_final_deg", "raw");
	const double comp_h = jsonNumber(j, "heading_error_max_deg", "compensated");
	// Integral of bias(T(t)) over [0, T]: kBc T + kK ((Tstart - Tref) T + Trise (T - tau (1 - e^{-T/tau}))).
	const double expected = std::abs(biasIntegral(kDuration) / 3600.0);
	std::printf("nav_test_drive: ideal heading max %.3g deg, position max %.3g m; raw heading final %.6f deg "
				"(closed form %.6f deg); compensated heading max %.3g deg\n",
				ideal_h, ideal_p, raw_h, expected, comp_h);
	const bool ok = ideal_h < 1e-4 && ideal_p < 1e-3 && std::abs(raw_h - expected) < 1e-4 && comp_h < 1e-3;
	return ok ? 0 : 1;
}
}  // namespace

int main(int argc, char** argv)
{
	try
	{
		registerAllClasses_mrpt_fog();
		const std::string mode = argc > 1 ? argv[1] : "";
		if (mode == "write" && argc == 4) return write(argv[2], argv[3], false);
		if (mode == "write-gap" && argc == 4) return write(argv[2], argv[3], true);
		if (mode == "check" && argc == 3) return check(argv[2]);
		if (mode == "check-gap" && argc == 3) return checkGap(argv[2]);
		std::cerr << "usage: nav_test_drive write|write-gap DRIVE.rawlog CAL.yaml | check|check-gap DRIFT.json\n";
		return 2;
	}
	catch (const std::exception& e)
	{
		std::cerr << "nav_test_drive: error: " << e.what() << "\n";
		return 1;
	}
}
