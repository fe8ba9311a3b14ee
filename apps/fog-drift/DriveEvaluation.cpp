/* fog-drift: heading and position drift of raw, compensated and ideal FOG on a drive. */
#include "DriveEvaluation.h"

#include "DriveCompensation.h"
#include "Progress.h"
#include "StreamingDrive.h"
#include "VariantPipeline.h"

#include <mrpt_fog/model/CalibrationYaml.h>
#include <mrpt_fog/obs/Units.h>
#include <mrpt_fog_heading/CalibrationEarthRate.h>
#include <mrpt_fog_nav/Rotation.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

namespace mrpt_fog::drift
{
namespace
{
/** Latitudes further apart than this differ (metadata are written to 1e-6 deg or so). */
constexpr double kLatitudeConflict_deg = 1e-3;

std::string latitudeConflict(const char* option, double option_deg, const char* source, double meta_deg,
							 const char* aside = "")
{
	char b[400];
	std::snprintf(b, sizeof b,
				  "%s %.6g overrides %s %.6g%s: the vertical Earth rate used differs by %.4g deg/h", option,
				  option_deg, source, meta_deg, aside,
				  units::kEarthRate_dph *
					  std::abs(std::sin(option_deg * units::kDegToRad) - std::sin(meta_deg * units::kDegToRad)));
	return b;
}
}  // namespace

bool noteCalibrationEarthRate(DriveEvaluation& e, const DriveSettings& st, const Calibration& zcal)
{
	if (st.cal_latitude_deg)
	{
		const bool in_file = std::isfinite(zcal.latitude_deg);
		const double meta_deg = in_file ? zcal.latitude_deg : e.drive.latitude_deg.value_or(NAN);
		if (std::isfinite(meta_deg) && std::abs(meta_deg - *st.cal_latitude_deg) > kLatitudeConflict_deg)
			e.option_conflicts.push_back(latitudeConflict(
				"--cal-latitude-deg", *st.cal_latitude_deg,
				in_file ? "the calibration file's latitude_deg" : "the drive's metadata latitude_deg", meta_deg,
				in_file ? "" : " (the calibration file has none)"));
	}
	// The Earth-rate rule (heading/CalibrationEarthRate.h).
	heading::CalibrationEarthRateOptions o;
	o.calibration_latitude_deg = st.cal_latitude_deg;
	o.bias_without_earth_rate = st.cal_no_earth_rate;
	heading::CalibrationEarthRate r;
	try
	{
		r = heading::calibrationEarthRate(zcal, e.latitude_deg, o);
	}
	catch (const std::invalid_argument&)
	{
		throw std::runtime_error("--cal-latitude-deg: must be within [-90, 90]");
	}
	e.calibration_latitude_source = heading::latitudeSourceName(r.source);
	if (r.bias_holds_earth_rate) e.calibration_earth_rate_dph = r.add_back_dph;
	return r.bias_holds_earth_rate;
}

HeadingOptions headingOptionsFor(DriveEvaluation& e, const std::string& path, const DriveSettings& st)
{
	if (st.latitude_deg)
	{
		e.latitude_deg = *st.latitude_deg;
		if (e.drive.latitude_deg && std::abs(*e.drive.latitude_deg - e.latitude_deg) > kLatitudeConflict_deg)
			e.option_conflicts.push_back(latitudeConflict("--latitude-deg", e.latitude_deg,
														  "the drive's metadata latitude_deg", *e.drive.latitude_deg));
	}
	else if (e.drive.latitude_deg) e.latitude_deg = *e.drive.latitude_deg;
	else throw std::runtime_error(path + ": no latitude_deg in the metadata; give --latitude-deg");
	if (!(std::abs(e.latitude_deg) <= 90)) throw std::runtime_error("--latitude-deg: must be within [-90, 90]");
	HeadingOptions hopt = st.heading;
	hopt.latitude_deg = e.latitude_deg;
	return hopt;
}

void appendDriftSeries(nav::DriftSeries& into, nav::DriftSeries&& part, double distance_m)
{
	if (into.t_s.empty() && into.name.empty())
	{
		into = std::move(part);
		return;
	}
	into.t_s.insert(into.t_s.end(), part.t_s.begin(), part.t_s.end());
	into.heading_error_deg.insert(into.heading_error_deg.end(), part.heading_error_deg.begin(), part.heading_error_deg.end());
	into.position_error_m.insert(into.position_error_m.end(), part.position_error_m.begin(), part.position_error_m.end());
	into.heading_error_max_deg = std::max(into.heading_error_max_deg, part.heading_error_max_deg);
	into.position_error_max_m = std::max(into.position_error_max_m, part.position_error_max_m);
	into.heading_error_final_deg = part.heading_error_final_deg;
	into.heading_error_final_signed_deg = part.heading_error_final_signed_deg;
	into.position_error_final_m = part.position_error_final_m;
	into.position_error_final_pct = part.position_error_final_pct;
	if (distance_m > 0) into.position_error_max_pct = 100.0 * into.position_error_max_m / distance_m;
}

DriveEvaluation evaluateDrive(const std::string& path, const DriveSettings& st)
{
	if (canStream(st))
		if (auto streamed = evaluateDriveStreaming(path, st)) return std::move(*streamed);
	DriveEvaluation e;
	e.input = path;
	{
		app::Progress progress("fog-drift: reading " + path, st.quiet);
		e.drive = readDrive(
			path, st.labels, [&](std::uint64_t n, std::uint64_t done, std::uint64_t total) { progress.update(n, done, total); },
			st.read_options);
	}
	const HeadingOptions hopt = headingOptionsFor(e, path, st);

	const FogSeries& fog = e.drive.fog;
	const bool triad_log = fog.has_axis[0] && fog.has_axis[1] && fog.has_axis[2];
	std::optional<CalibrationSet> cals;
	if (!st.cal_path.empty()) cals = loadCalibrationSet(st.cal_path);
	const bool cal_all = cals && cals->forAxis(GyroAxis::X) && cals->forAxis(GyroAxis::Y) && cals->forAxis(GyroAxis::Z);
	const bool ideal_triad = !e.drive.fog_ideal || (e.drive.fog_ideal->has_axis[0] && e.drive.fog_ideal->has_axis[1] &&
													e.drive.fog_ideal->has_axis[2]);
	e.three_axis = triad_log && (!cals || cal_all) && ideal_triad;
	if (triad_log && !e.three_axis)
		e.three_axis_note = cals && !cal_all ? "the calibration does not cover x, y and z: the vertical gyro alone"
											 : "FOG_IDEAL is not a triad: the vertical gyro alone";

	// The gyro-off stretches of the FOG (GyroOff.h): each powered span is navigated alone.
	std::vector<PoweredSpan> spans;
	{
		PowerSpanBuilder power;
		for (std::size_t k = 0; k < fog.size(); k++) power.add(fog.epoch_s + fog.time_s[k], fog.power.empty() ? NAN : fog.power[k]);
		power.finish();
		e.gyro_off = power.stretches();
		spans = power.powered();
		if (spans.empty()) throw std::runtime_error(path + ": FOG '" + fog.sensor_label + "': the gyro is off throughout");
		TruthYawAt yaw(stretchQueryTimes(e.gyro_off));
		for (const auto& p : e.drive.truth) yaw.add(p.t_s, p.yaw_rad);
		yaw.finish();
		setTruthHeadingChanges(e.gyro_off, yaw);
	}
	const bool gyro_off = !e.gyro_off.empty();
	e.powered_spans = spans.size();
	auto run = [&](const std::string& name, const std::vector<double>& t, const std::array<const std::vector<double>*, 3>& r) {
		// The times and rates of a variant serve the triad's attitude figures and --odometry-out
		// (compensated, else raw): the others, single-axis, are not kept.
		const bool odometry_variant = name == (st.cal_path.empty() ? "raw" : "compensated");
		const bool keep = st.keep_trajectories == KeptTrajectories::All ||
						  (st.keep_trajectories == KeptTrajectories::ForOdometry && odometry_variant);
		HeadingOptions o = hopt;
		o.keep_rates = e.three_axis || (odometry_variant && st.keep_trajectories != KeptTrajectories::None);
		o.empty_if_no_odometry = gyro_off;
		VariantResult all;
		nav::Trajectory kept;
		nav::DriftSeries series;
		std::size_t navigated = 0;
		for (const PoweredSpan& span : spans)
		{
			if (gyro_off)
			{
				if (t.empty()) break;
				const auto w = navigationWindow(span, t.front(), t.back(), e.drive.odometry.t_s.front(),
												e.drive.odometry.t_s.back(), e.drive.truth.front().t_s,
												e.drive.truth.back().t_s);
				if (!w) continue;
				o.window_t0_s = w->first, o.window_t1_s = w->second;
			}
			VariantResult part = e.three_axis ? deadReckonVariant(t, *r[0], *r[1], *r[2], e.drive, o)
											  : deadReckonVariant(t, *r[2], e.drive, o);
			if (part.trajectory.empty()) continue;  // too short to navigate (gyro_off only)
			navigated++;
			if (gyro_off)  // a span between two truth poses has no error to give (the streamed path skips it too)
			{
				const auto& tr = e.drive.truth;
				const auto it = std::lower_bound(tr.begin(), tr.end(), part.trajectory.front().t_s,
												 [](const nav::TrajectoryPoint& p, double v) { return p.t_s < v; });
				if (it == tr.end() || it->t_s > part.trajectory.back().t_s) continue;
			}
			// Its drift figures now (computeDriftReport treats each variant alone), then the
			// trajectory goes unless kept: the variants' trajectories are not all held at once.
			std::vector<nav::NamedTrajectory> alone(1);
			alone.front() = {name, std::move(part.trajectory)};
			nav::DriftReport one = nav::computeDriftReport(e.drive.truth, alone);
			e.report.distance_m = one.distance_m;
			e.report.duration_s = one.duration_s;
			appendDriftSeries(series, std::move(one.variants.front()), one.distance_m);
			if (keep)
			{
				if (kept.empty()) kept = std::move(alone.front().second);
				else kept.insert(kept.end(), alone.front().second.begin(), alone.front().second.end());
			}
			for (auto [to, from] : {std::pair{&all.t_s, &part.t_s}, {&all.yaw_rate_rad_s, &part.yaw_rate_rad_s},
								   {&all.roll_rad, &part.roll_rad}, {&all.pitch_rad, &part.pitch_rad}})
			{
				if (to->empty()) *to = std::move(*from);
				else to->insert(to->end(), from->begin(), from->end());
			}
		}
		if (navigated == 0)
			throw std::runtime_error("no powered span of the gyro overlaps the odometry and the truth long enough to "
									 "navigate");
		if (name == "raw") e.powered_spans_navigated = navigated;
		// The trajectory lives in variants alone (results[i].trajectory is left empty): one copy
		// of each (~80 B per sample).
		e.results.push_back(std::move(all));
		e.variants.emplace_back(name, std::move(kept));
		e.report.variants.push_back(std::move(series));
	};
	// The heading gyro is the vertical (z) axis; a triad's x / y enter the 3-D strapdown.
	auto rates = [&](const FogSeries& s) -> std::array<const std::vector<double>*, 3> {
		if (!s.has_axis[2])
			throw std::runtime_error(path + ": FOG '" + s.sensor_label +
									 "' has no z (vertical) axis; fog-drift integrates the vertical gyro");
		return {&s.rate_dph[0], &s.rate_dph[1], &s.rate_dph[2]};
	};
	std::vector<double> t_fog = absoluteTimes(fog);
	run("raw", t_fog, rates(fog));
	std::array<std::vector<double>, 3> comp;
	if (cals)
	{
		const Calibration* zcal = cals->forAxis(GyroAxis::Z);
		if (!zcal) throw std::runtime_error(st.cal_path + ": axes: no calibration for axis z (the heading gyro)");
		const bool bias_holds_earth = noteCalibrationEarthRate(e, st, *zcal);
		if (e.three_axis && bias_holds_earth)
			throw std::runtime_error(st.cal_path +
									 ": the bias holds the Earth rate of the calibration mount (earth_rate handling "
									 "in_bias), which is unknown for the horizontal axes: calibrate a triad from runs "
									 "that state it (metadata earth_rate_dph.<axis>, fog-sim --triad writes it)");
		for (const GyroAxis a : {GyroAxis::X, GyroAxis::Y})  // a triad's horizontal axes: the thermal model alone
		{
			const Calibration* c = cals->forAxis(a);
			const std::size_t i = static_cast<std::size_t>(a);
			if (c && e.three_axis)
			{
				comp[i] = app::compensatedDriveRate_dph(fog, *c, st.cal_path, st.screen_thermistors, &e.field_warning);
				e.magnetic_term |= c->magnetic.has_value();
			}
			else
				comp[i] = fog.rate_dph[i];  // not integrated (vertical gyro alone) or absent
		}
		// The vertical gyro: the library's heading pipeline (VariantPipeline.h) gives the rate the
		// strapdown integrates: screened, compensated, the calibration's field offset and the
		// standstill updates' offset removed, the calibration's Earth rate added back (the
		// strapdown removes the drive's own).
		if (st.refinement.enabled && e.three_axis)
			e.refinement.note = "not run: a triad FOG runs the 3-D strapdown, which is not refined";
		const auto pipe = compensatedPipeline(fog, *zcal, st, hopt, t_fog.front(),
											  st.refinement.enabled && !e.three_axis, e);
		comp[2] = pipelineRate_dph(*pipe, fog, e.drive.odometry, st.cal_path);
		reportCompensation(*pipe, *zcal, !fog.field_uT.empty(), st, e);
		// The temperatures have served (compensation is the last to read them): released, 8 B per
		// thermistor and sample. The drive's FOG keeps its times, rates and power.
		e.drive.fog.thermistors.clear();
		e.drive.fog.temp_C.clear();
		e.drive.fog.temp_C.shrink_to_fit();
		run("compensated", t_fog, {&comp[0], &comp[1], &comp[2]});
	}
	if (e.drive.fog_ideal) run("ideal", absoluteTimes(*e.drive.fog_ideal), rates(*e.drive.fog_ideal));

	if (e.three_axis)
	{
		for (std::size_t v = 0; v < e.results.size(); v++)
		{
			const VariantResult& r = e.results[v];
			AttitudeFigures af;
			double sr = 0, sp = 0;
			for (std::size_t k = 0; k < r.t_s.size(); k++)
			{
				const auto q = nav::interpolate(e.drive.truth, r.t_s[k]).q_nb.normalized();
				const double dr = std::abs(nav::wrapToPi(r.roll_rad[k] - rollOf(q))) * units::kRadToDeg;
				const double dp = std::abs(nav::wrapToPi(r.pitch_rad[k] - pitchOf(q))) * units::kRadToDeg;
				sr += dr * dr, sp += dp * dp;
				af.roll_error_max_deg = std::max(af.roll_error_max_deg, dr);
				af.pitch_error_max_deg = std::max(af.pitch_error_max_deg, dp);
				af.roll_error_final_deg = dr, af.pitch_error_final_deg = dp;
			}
			const double n = static_cast<double>(std::max<std::size_t>(r.t_s.size(), 1));
			af.roll_error_rms_deg = std::sqrt(sr / n);
			af.pitch_error_rms_deg = std::sqrt(sp / n);
			e.attitude[e.variants[v].first] = af;
		}
		if (e.drive.fog_ideal)
		{
			const FogSeries& ideal = *e.drive.fog_ideal;
			// RMS over consecutive 100 s blocks of the block mean of (gyro - ideal): the thermal
			// error left at the time scale that tilts the attitude (per-sample differences are
			// dominated by the two outputs' independent angle quantisation, ~0.03 deg/h).
			const auto rmsVsIdeal = [&](const std::array<const std::vector<double>*, 3>& r) {
				std::array<double, 3> out{};
				for (std::size_t a = 0; a < 3; a++)
				{
					double s2 = 0, block_sum = 0, block_start = fog.time_s.front();
					std::size_t blocks = 0, block_n = 0;
					for (std::size_t k = 0; k < r[a]->size() && k < ideal.rate_dph[a].size(); k++)
					{
						if (fog.time_s[k] - block_start >= 100.0)
						{
							if (block_n) s2 += std::pow(block_sum / static_cast<double>(block_n), 2), blocks++;
							block_sum = 0, block_n = 0, block_start = fog.time_s[k];
						}
						const double d = (*r[a])[k] - ideal.rate_dph[a][k];
						if (fog.gyroOn(k) && std::isfinite(d)) block_sum += d, block_n++;
					}
					out[a] = blocks ? std::sqrt(s2 / static_cast<double>(blocks)) : std::numeric_limits<double>::quiet_NaN();
				}
				return out;
			};
			if (ideal.size() == fog.size())
			{
				e.rate_error_rms_dph["raw"] = rmsVsIdeal(rates(fog));
				if (cals) e.rate_error_rms_dph["compensated"] = rmsVsIdeal({&comp[0], &comp[1], &comp[2]});
			}
		}
	}

	// Dead reckoning and the triad figures are done: from here on only the truth and the
	// trajectories are read (report, segments, CSV, plots). The per-sample FOG, ideal FOG and
	// odometry are released (~100 B per sample); the FOG's label, epoch and metadata stay.
	std::vector<double>().swap(t_fog);
	for (auto& c : comp) std::vector<double>().swap(c);
	{
		FogSeries kept;
		kept.sensor_label = fog.sensor_label;
		kept.epoch_s = fog.epoch_s;
		kept.has_axis = fog.has_axis;
		kept.metadata = fog.metadata;
		e.drive.fog = std::move(kept);
	}
	e.drive.fog_ideal.reset();
	e.drive.odometry = OdometryPoses{};

	e.segments = nav::segmentDrive(e.drive.truth, st.figures);
	cutSegmentsAtGyroOff(e.segments, nullptr, e.gyro_off, st.figures);
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

namespace
{
const char* const kVariants[] = {"raw", "compensated", "ideal"};

/** t["<key>.<variant>"] = that member of by_variant[variant] (NaN where the variant is missing),
 * for every variant and every (key, member) of `fields`. */
template <class Figures>
void putPerVariant(std::map<std::string, double>& t, const std::map<std::string, Figures>& by_variant,
				   std::initializer_list<std::pair<const char*, double Figures::*>> fields)
{
	for (const char* name : kVariants)
	{
		const auto it = by_variant.find(name);
		for (const auto& [key, member] : fields)
			t[std::string(key) + "." + name] =
				it != by_variant.end() ? it->second.*member : std::numeric_limits<double>::quiet_NaN();
	}
}
}  // namespace

std::map<std::string, double> driveFigureTable(const DriveEvaluation& e)
{
	const double nan = std::numeric_limits<double>::quiet_NaN();
	std::map<std::string, double> t;
	using HF = nav::HeadingFigures;
	putPerVariant<HF>(t, e.figures,
					  {{"heading_error_rms_deg", &HF::heading_error_rms_deg},
					   {"heading_error_max_deg", &HF::heading_error_max_deg},
					   {"heading_error_final_deg", &HF::heading_error_final_deg},
					   {"heading_drift_between_turns_dph", &HF::heading_drift_between_turns_dph},
					   {"turn_scale_factor_ppm", &HF::turn_scale_factor_ppm}});
	if (e.three_axis)
	{
		using AF = AttitudeFigures;
		putPerVariant<AF>(t, e.attitude,
						  {{"roll_error_rms_deg", &AF::roll_error_rms_deg},
						   {"roll_error_max_deg", &AF::roll_error_max_deg},
						   {"roll_error_final_deg", &AF::roll_error_final_deg},
						   {"pitch_error_rms_deg", &AF::pitch_error_rms_deg},
						   {"pitch_error_max_deg", &AF::pitch_error_max_deg},
						   {"pitch_error_final_deg", &AF::pitch_error_final_deg}});
		for (const char* name : {"raw", "compensated"})  // the ideal run has no rate error
		{
			const auto jt = e.rate_error_rms_dph.find(name);
			for (std::size_t a = 0; a < 3; a++)
				t[std::string("rate_error_rms_100s_dph.") + "xyz"[a] + "." + name] =
					jt != e.rate_error_rms_dph.end() ? jt->second[a] : nan;
		}
	}
	const auto ratio = [&](const std::string& a, const std::string& b) { return std::abs(t[a]) / std::abs(t[b]); };
	t["ratio.heading_rms_compensated_over_raw"] = ratio("heading_error_rms_deg.compensated", "heading_error_rms_deg.raw");
	t["ratio.heading_rms_compensated_over_ideal"] = ratio("heading_error_rms_deg.compensated", "heading_error_rms_deg.ideal");
	t["ratio.drift_between_turns_compensated_over_raw"] =
		ratio("heading_drift_between_turns_dph.compensated", "heading_drift_between_turns_dph.raw");
	if (e.three_axis)
	{
		for (const char* a : {"x", "y", "z"})
			t[std::string("ratio.rate_error_") + a + "_compensated_over_raw"] =
				ratio(std::string("rate_error_rms_100s_dph.") + a + ".compensated", std::string("rate_error_rms_100s_dph.") + a + ".raw");
		t["ratio.roll_rms_compensated_over_ideal"] = ratio("roll_error_rms_deg.compensated", "roll_error_rms_deg.ideal");
		t["ratio.pitch_rms_compensated_over_ideal"] = ratio("pitch_error_rms_deg.compensated", "pitch_error_rms_deg.ideal");
	}
	return t;
}

}  // namespace mrpt_fog::drift
