/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "DriveEvaluation.h"

#include "Compensation.h"

#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/obs/Units.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mrpt_fog::drift
{
DriveEvaluation evaluateDrive(const std::string& path, const DriveSettings& st)
{
	DriveEvaluation e;
	e.input = path;
	e.drive = readDrive(path);
	if (st.latitude_deg) e.latitude_deg = *st.latitude_deg;
	else if (e.drive.latitude_deg) e.latitude_deg = *e.drive.latitude_deg;
	else throw std::runtime_error(path + ": no latitude_deg in the metadata; give --latitude-deg");
	if (!(std::abs(e.latitude_deg) <= 90)) throw std::runtime_error("--latitude-deg: must be within [-90, 90]");
	HeadingOptions hopt = st.heading;
	hopt.latitude_deg = e.latitude_deg;

	auto run = [&](const std::string& name, const std::vector<double>& t, const std::vector<double>& rate) {
		e.results.push_back(deadReckonVariant(t, rate, e.drive, hopt));
		e.variants.emplace_back(name, e.results.back().trajectory);
	};
	// The heading gyro is the vertical (z) axis; x/y axes of a triad are not used (planar drive).
	auto verticalRate = [&](const FogSeries& s) -> const std::vector<double>& {
		if (!s.has_axis[2])
			throw std::runtime_error(path + ": FOG '" + s.sensor_label +
									 "' has no z (vertical) axis; fog-drift integrates the vertical gyro");
		return s.rate_dph[2];
	};
	const std::vector<double> t_fog = absoluteTimes(e.drive.fog);
	run("raw", t_fog, verticalRate(e.drive.fog));
	if (!st.cal_path.empty())
	{
		const Calibration cal = loadCalibrationYaml(st.cal_path, GyroAxis::Z);
		double cal_lat_deg = e.latitude_deg;
		e.calibration_latitude_source = "drive";
		if (st.cal_latitude_deg)
		{
			cal_lat_deg = *st.cal_latitude_deg;
			e.calibration_latitude_source = "option";
		}
		else if (std::isfinite(cal.latitude_deg))
		{
			cal_lat_deg = cal.latitude_deg;
			e.calibration_latitude_source = "calibration";
		}
		if (!(std::abs(cal_lat_deg) <= 90)) throw std::runtime_error("--cal-latitude-deg: must be within [-90, 90]");
		const bool bias_holds_earth = !st.cal_no_earth_rate && cal.earth_rate == EarthRateHandling::InBias;
		if (bias_holds_earth) e.calibration_earth_rate_dph = units::kEarthRate_dph * std::sin(cal_lat_deg * units::kDegToRad);
		std::vector<double> comp = compensatedRate_dph(e.drive.fog, cal, st.cal_path, st.screen_thermistors);
		// The compensated rate lacks the Earth rate the bias held; the strapdown removes the
		// drive's own: add the first back so that it is not removed twice. Scale factor: the
		// bias (hence its Earth rate) is removed before the division, so the Earth rate goes
		// back unscaled.
		for (double& r : comp) r += e.calibration_earth_rate_dph;
		run("compensated", t_fog, comp);
	}
	if (e.drive.fog_ideal) run("ideal", absoluteTimes(*e.drive.fog_ideal), verticalRate(*e.drive.fog_ideal));

	e.report = nav::computeDriftReport(e.drive.truth, e.variants);
	e.segments = nav::segmentDrive(e.drive.truth, st.figures);
	for (const auto& v : e.report.variants)
		e.figures[v.name] = nav::computeHeadingFigures(v.t_s, v.heading_error_deg, e.drive.truth, e.segments);
	return e;
}

Spread spreadOf(std::vector<double> v)
{
	v.erase(std::remove_if(v.begin(), v.end(), [](double x) { return !std::isfinite(x); }), v.end());
	Spread s;
	s.n = v.size();
	if (v.empty())
	{
		s.median = s.q1 = s.q3 = s.min = s.max = std::numeric_limits<double>::quiet_NaN();
		return s;
	}
	std::sort(v.begin(), v.end());
	auto q = [&](double p) {
		const double x = p * static_cast<double>(v.size() - 1);
		const std::size_t i = static_cast<std::size_t>(std::floor(x));
		const double f = x - static_cast<double>(i);
		return i + 1 < v.size() ? v[i] + f * (v[i + 1] - v[i]) : v[i];
	};
	s.median = q(0.5);
	s.q1 = q(0.25);
	s.q3 = q(0.75);
	s.min = v.front();
	s.max = v.back();
	return s;
}

std::map<std::string, double> driveFigureTable(const DriveEvaluation& e)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	std::map<std::string, double> t;
	for (const char* name : {"raw", "compensated", "ideal"})
	{
		const auto it = e.figures.find(name);
		const bool has = it != e.figures.end();
		const std::string n(name);
		t["heading_error_rms_deg." + n] = has ? it->second.heading_error_rms_deg : nan;
		t["heading_error_max_deg." + n] = has ? it->second.heading_error_max_deg : nan;
		t["heading_error_final_deg." + n] = has ? it->second.heading_error_final_deg : nan;
		t["heading_drift_between_turns_dph." + n] = has ? it->second.heading_drift_between_turns_dph : nan;
		t["turn_scale_factor_ppm." + n] = has ? it->second.turn_scale_factor_ppm : nan;
	}
	const auto ratio = [&](const std::string& a, const std::string& b) { return std::abs(t[a]) / std::abs(t[b]); };
	t["ratio.heading_rms_compensated_over_raw"] = ratio("heading_error_rms_deg.compensated", "heading_error_rms_deg.raw");
	t["ratio.heading_rms_compensated_over_ideal"] = ratio("heading_error_rms_deg.compensated", "heading_error_rms_deg.ideal");
	t["ratio.drift_between_turns_compensated_over_raw"] =
		ratio("heading_drift_between_turns_dph.compensated", "heading_drift_between_turns_dph.raw");
	return t;
}

}  // namespace mrpt_fog::drift
