/* fog-localize: MRPT particle-filter localization with raw, compensated and ideal FOG heading. */
#include "LocalizeOutputs.h"

#include <mrpt/io/CFileGZOutputStream.h>
#include <mrpt/obs/CActionCollection.h>
#include <mrpt/obs/CSensoryFrame.h>
#include <mrpt/serialization/CArchive.h>
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/common/JsonWriter.h>
#include <mrpt_fog/plot/PlotCanvas.h>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace mrpt_fog::localize
{
namespace
{
cv::Scalar colourOf(const std::string& name)
{
	if (name == "raw") return plot_colour::kRed;
	if (name == "compensated") return plot_colour::kBlue;
	if (name == "ideal") return plot_colour::kGreen;
	return plot_colour::kPurple;
}

const GyroResult* gyro(const LocalizeResults& r, const std::string& name)
{
	for (const auto& g : r.gyros)
		if (g.name == name) return &g;
	return nullptr;
}

double ratio(double a, double b) { return b > 0 ? a / b : NAN; }

/** Paired comparison of two gyros' open-field RMS over the same seeds: mean difference a - b
 * [m] and its standard error (NaN with fewer than 2 seeds). */
std::pair<double, double> pairedDifference(const GyroResult& a, const GyroResult& b)
{
	const auto& x = a.summary.open_rms_per_seed_m;
	const auto& y = b.summary.open_rms_per_seed_m;
	const std::size_t n = std::min(x.size(), y.size());
	if (n < 2) return {n ? x[0] - y[0] : NAN, NAN};
	double m = 0;
	for (std::size_t i = 0; i < n; ++i) m += x[i] - y[i];
	m /= n;
	double v = 0;
	for (std::size_t i = 0; i < n; ++i) v += (x[i] - y[i] - m) * (x[i] - y[i] - m);
	return {m, std::sqrt(v / (n - 1) / n)};
}

/** "better", "worse" or "cannot tell" (|difference| < 2 standard errors, or < 2 seeds). */
const char* verdict(const std::pair<double, double>& d)
{
	if (!std::isfinite(d.second) || std::abs(d.first) < 2 * d.second) return "cannot tell";
	return d.first < 0 ? "better" : "worse";
}

void writeGz(const std::string& path, const std::function<void(mrpt::serialization::CArchive&)>& body)
{
	writeFileAtomically(path, [&](const std::string& tmp) {
		mrpt::io::CFileGZOutputStream f;
		if (!f.open(tmp)) throw std::runtime_error(tmp + ": cannot open for writing");
		auto ar = mrpt::serialization::archiveFrom(f);
		body(ar);
		f.close();
	});
}

std::string iniText(const std::string& gyro_name, const MclOptions& m, const LaserOptions& l, const mrpt::poses::CPose2D& start)
{
	const auto& g = m.motion;
	std::ostringstream s;
	s.precision(10);
	s << "# MRPT pf-localization on fog-localize's world, odometry from the " << gyro_name << " FOG.\n"
	  << "# Run: pf-localization pf-localization_" << gyro_name << ".ini   (in this folder, headless)\n"
	  << "# The rawlog is in actions-observations format: each CActionRobotMovement2D carries the FOG\n"
	  << "# motion model (Gaussian: a1=" << g.distance_frac << " a2=0 a3=0 a4=" << g.scale_factor_ppm * 1e-6
	  << " minStdXY=" << g.min_std_xy_m << " m minStdPHI from " << g.heading_bias_dph << " deg/h over "
	  << g.horizon_s << " s),\n# so [DummyOdometryParams] is not used. The increments are scaled by the odometry scale\n"
	  << "# fog-localize's first filter seed had calibrated by then (pf-localization has no such calibration).\n"
	  << (m.roughening_k > 0 ? "# fog-localize roughened after each resampling (--roughening-k); pf-localization does not.\n" : "")
	  << "[LocalizationExperiment]\n"
	  << "map_file=map.gridmap.gz\n"
	  << "rawlog_file=localize_" << gyro_name << ".rawlog\n"
	  << "ground_truth_path_file=ground_truth.txt\n"
	  << "logOutput_dir=LOG_" << gyro_name << "\n"
	  << "particles_count=" << m.particles << "\n"
	  << "experimentRepetitions=1\n"
	  << "SAVE_STATS_ONLY=false\n"
	  << "SHOW_PROGRESS_3D_REAL_TIME=false\n"
	  << "3DSceneFrequency=-1\n"
	  << "init_PDF_mode=1\n"
	  << "init_PDF_min_x=" << start.x() - m.init_xy_m << "\ninit_PDF_max_x=" << start.x() + m.init_xy_m << "\n"
	  << "init_PDF_min_y=" << start.y() - m.init_xy_m << "\ninit_PDF_max_y=" << start.y() + m.init_xy_m << "\n"
	  << "init_PDF_min_yaw_deg=" << start.phi() * 180 / M_PI - m.init_yaw_deg << "\ninit_PDF_max_yaw_deg="
	  << start.phi() * 180 / M_PI + m.init_yaw_deg << "\n\n"
	  << "[PF_options]\nPF_algorithm=pfStandardProposal\nresamplingMethod=prSystematic\nadaptiveSampleSize=0\n"
	  << "BETA=0.5\npowFactor=" << m.pow_factor << "\nsampleSize=1\n\n"
	  << "[KLD_options]\nKLD_binSize_PHI_deg=2\nKLD_binSize_XY=0.5\nKLD_delta=0.01\nKLD_epsilon=0.01\n"
	  << "KLD_maxSampleSize=1000\nKLD_minSampleSize=150\nKLD_minSamplesPerBin=0\n\n"
	  << "[MetricMap]\noccupancyGrid_count=1\n\n"
	  << "[MetricMap_occupancyGrid_00_creationOpts]\nresolution=2\n\n"
	  << "[MetricMap_occupancyGrid_00_likelihoodOpts]\nlikelihoodMethod=lmLikelihoodField_Thrun\n"
	  << "LF_stdHit=" << m.lf_std_hit_m << "\nLF_zHit=0.95\nLF_zRandom=0.05\nLF_maxRange=" << l.range_m
	  << "\nLF_decimation=" << m.lf_decimation << "\nLF_maxCorrsDistance=" << 3 * m.lf_std_hit_m
	  << "\nenableLikelihoodCache=true\n";
	return s.str();
}
}  // namespace

void printSummary(const LocalizeResults& r, const World& world, const mrpt::obs::CActionRobotMovement2D::TMotionModelOptions::TOptions_GaussianModel& wheel_model)
{
	std::printf("  compensated gyro: calibration %s\n", describeCalibration(r.calibration).c_str());
	std::printf("  position RMS [m] per stretch kind (pooled over %zu filter seeds; %.0f s run time)\n",
				r.gyros.empty() ? 0 : r.gyros.front().seeds.size(), r.runtime_s);
	std::printf("  %-12s %10s %10s %10s %10s %14s %9s\n", "gyro", "open", "tunnel", "urban", "all", "worst open",
				"diverged");
	for (const auto& g : r.gyros)
	{
		auto at = [&](StretchKind k) {
			auto it = g.summary.position_rms_m.find(k);
			return it == g.summary.position_rms_m.end() ? NAN : it->second;
		};
		std::printf("  %-12s %10.2f %10.2f %10.2f %10.2f %7.2f (#%zu) %6zu/%zu\n", g.name.c_str(), at(StretchKind::Open),
					at(StretchKind::Tunnel), at(StretchKind::Urban), g.summary.position_rms_all_m,
					g.summary.stretches[g.summary.worst_open].position_rms_m, g.summary.worst_open, g.summary.diverged_runs,
					g.runs.size());
	}
	std::printf("  open stretches' heading budget [deg] (RMS over seeds; end = entry + gyro drift + filter walk; spread: the particles' own heading std at entry)\n");
	std::printf("  %-12s %3s %7s %9s %9s %9s %9s %9s %9s\n", "gyro", "#", "km", "entry", "spread", "gyro", "walk", "end",
				"entry [m]");
	for (const auto& g : r.gyros)
		for (const auto& h : g.heading_budget)
			std::printf("  %-12s %3zu %7.2f %9.4f %9.4f %+9.4f %9.4f %9.4f %9.2f\n", g.name.c_str(), h.index,
						h.length_m / 1000, h.entry_heading_rms_deg, h.entry_heading_spread_rms_deg, h.gyro_drift_deg,
						h.walk_rms_deg, h.end_heading_rms_deg, h.entry_position_rms_m);
	const GyroResult *raw = gyro(r, "raw"), *comp = gyro(r, "compensated"), *ideal = gyro(r, "ideal");
	if (raw && comp && ideal)
	{
		const double o_r = raw->summary.position_rms_m.at(StretchKind::Open);
		const double o_c = comp->summary.position_rms_m.at(StretchKind::Open);
		const double o_i = ideal->summary.position_rms_m.at(StretchKind::Open);
		std::printf("  open stretches: compensated / raw = %.3f (target <= 0.5), compensated / ideal = %.3f (target <= 1.5)\n",
					ratio(o_c, o_r), ratio(o_c, o_i));
		const auto dr = pairedDifference(*comp, *raw), di = pairedDifference(*comp, *ideal);
		std::printf("  paired over seeds (open-field RMS): compensated - raw = %+.2f +- %.2f m (%s), compensated - ideal = "
					"%+.2f +- %.2f m (%s)\n",
					dr.first, dr.second, verdict(dr), di.first, di.second, verdict(di));
	}
	if (!r.gyro_off.empty())
	{
		double total = 0;
		for (const auto& g : r.gyro_off) total += g.duration_s();
		const auto& wm = wheel_model;
		std::printf("  gyro off %.1f s in %zu stretch(es): heading not observable from the gyro there; the filter steps "
					"on the wheel odometry alone (Gaussian model: heading std %.2g deg + %.3g deg/m + %.3g of the turn), "
					"%s\n",
					total, r.gyro_off.size(), wm.minStdPHI * 180 / M_PI, wm.a3 * 180 / M_PI, wm.a4,
					r.gyro_off_recovery == GyroOffRecovery::Refix
						? "then at the turn-on the particles are re-drawn around a fix (the truth, as at the start)"
						: "and go on from there at the turn-on (no re-initialisation)");
		for (std::size_t i = 0; i < r.gyro_off.size(); i++)
		{
			const auto& g = r.gyro_off[i];
			std::printf("    %8.1f - %8.1f s (%.1f s, %zu samples):", g.off_s - r.t0_s, g.on_s - r.t0_s, g.duration_s(),
						g.samples);
			for (const auto& [kind, sec] : r.gyro_off_overlap_s[i]) std::printf(" %.1f s %s", sec, stretchKindName(kind));
			std::printf("\n");
		}
		for (const auto& g : r.gyros)
			std::printf("    %-12s %zu wheel-only steps: position RMS %.2f m (max %.2f), heading RMS %.3f deg there; %zu "
						"re-fix(es)\n",
						g.name.c_str(), g.wheel_only.steps, g.wheel_only.position_rms_m, g.wheel_only.position_max_m,
						g.wheel_only.heading_rms_deg, g.refixes);
	}
	const HeadingRelevance& hr = r.relevance;
	for (const FieldRelevance& f : hr.fields)
		std::printf("  open field #%zu: raw gyro drift %+.4f deg vs map-matching's entry heading error %.4f deg RMS "
					"(ideal gyro): %s; ideal / raw position RMS %.2f\n",
					f.index, f.raw_gyro_drift_deg, f.ideal_entry_heading_rms_deg,
					f.gyro_dominates ? "the gyro's drift dominates" : "the map-matching dominates",
					f.ideal_to_raw_position_rms);
	if (hr.heading_matters)
		std::printf("  heading matters on these open fields: a perfect gyro gives %.2fx the raw position RMS (<= %.1f)\n",
					hr.ideal_to_raw_position_rms, HeadingRelevance::kMaxReachableRatio);
	else
		std::printf("  CANNOT TELL on these open fields: even the ideal gyro gives %.2fx the raw position RMS (> %.1f): the "
					"map-matching's entry error, not the gyro, sets the error here, so the 'compensated <= %.1fx raw' target "
					"cannot be judged (try --fields turns)\n",
					hr.ideal_to_raw_position_rms, HeadingRelevance::kMaxReachableRatio, HeadingRelevance::kMaxReachableRatio);
	(void)world;
}

void writeOutputs(const std::string& dir, const std::string& json_path, const LocalizeResults& r, const World& world,
				  const std::vector<mrpt::obs::CObservation2DRangeScan::Ptr>& scans, const std::vector<double>& scan_t,
				  const nav::Trajectory& truth, const MclOptions& mcl, const LaserOptions& laser)
{
	// ---- JSON
	JsonValue j = JsonValue::object();
	j["drive"] = r.drive;
	j["input_notices"] = r.input_notices;
	{
		// always present: total_s 0 on a powered drive
		JsonValue& go = j["gyro_off"];
		go = JsonValue::object();
		double total = 0;
		go["stretches"] = JsonValue::array();
		for (std::size_t i = 0; i < r.gyro_off.size(); i++)
		{
			const auto& g = r.gyro_off[i];
			total += g.duration_s();
			JsonValue e = JsonValue::object();
			e["off_s"] = g.off_s - r.t0_s;
			e["on_s"] = g.on_s - r.t0_s;
			e["duration_s"] = g.duration_s();
			e["samples"] = static_cast<unsigned long>(g.samples);
			e["to_end"] = g.to_end;
			JsonValue& ov = e["seconds_by_stretch_kind"];
			ov = JsonValue::object();
			for (const auto& [kind, sec] : r.gyro_off_overlap_s[i]) ov[stretchKindName(kind)] = sec;
			go["stretches"].push_back(std::move(e));
		}
		go["total_s"] = total;
		{
			const auto& wm = mcl.wheel_only_motion.gaussianModel;
			JsonValue& mm = go["wheel_only_motion"];
			mm = JsonValue::object();
			mm["a1_m_per_m"] = wm.a1;
			mm["a2"] = wm.a2;
			mm["a3_deg_per_m"] = wm.a3 * 180 / M_PI;
			mm["a4_per_turn"] = wm.a4;
			mm["min_std_xy_m"] = wm.minStdXY;
			mm["min_std_phi_deg"] = wm.minStdPHI * 180 / M_PI;
		}
		go["recovery"] = r.gyro_off_recovery == GyroOffRecovery::Refix ? "refix" : "none";
		JsonValue& w = go["wheel_only"];
		w = JsonValue::object();
		for (const auto& g : r.gyros)
		{
			JsonValue& e = w[g.name];
			e = JsonValue::object();
			e["steps"] = static_cast<unsigned long>(g.wheel_only.steps);
			e["position_rms_m"] = std::isfinite(g.wheel_only.position_rms_m) ? JsonValue(g.wheel_only.position_rms_m) : JsonValue();
			e["position_max_m"] = std::isfinite(g.wheel_only.position_max_m) ? JsonValue(g.wheel_only.position_max_m) : JsonValue();
			e["heading_rms_deg"] = std::isfinite(g.wheel_only.heading_rms_deg) ? JsonValue(g.wheel_only.heading_rms_deg) : JsonValue();
			e["refixes"] = static_cast<unsigned long>(g.refixes);
		}
	}
	{
		JsonValue& c = j["calibration"];
		c = JsonValue::object();
		c["path"] = r.calibration.path;
		c["source"] = toString(r.calibration.source);
		c["fitted_on"] = JsonValue::array();
		for (const auto& f : r.calibration.fitted_on) c["fitted_on"].push_back(f);
		c["bias_model"] = r.calibration.cal.preset;
		if (const auto& sf = r.calibration.cal.scale_factor)
		{
			JsonValue& m = c["scale_factor"];
			m = JsonValue::object();
			m["thermistor"] = sf->thermistor;
			m["order"] = static_cast<unsigned long>(sf->order());
			m["slope_ppm_per_C"] = sf->slope_ppm_per_C;
			m["min_C"] = sf->min_C;
			m["max_C"] = sf->max_C;
		}
		else
			c["scale_factor"] = JsonValue();
		c["description"] = describeCalibration(r.calibration);
	}
	j["seeds"] = JsonValue::array();
	if (!r.gyros.empty())
		for (unsigned s : r.gyros.front().seeds) j["seeds"].push_back(s);
	j["particles"] = static_cast<unsigned long>(mcl.particles);
	j["roughening_k"] = mcl.roughening_k;
	JsonValue& pr = j["position_rms_m"];
	pr = JsonValue::object();
	for (const auto& g : r.gyros) pr[g.name] = g.summary.position_rms_m.at(StretchKind::Open);
	JsonValue& hr = j["heading_rms_deg"];
	hr = JsonValue::object();
	for (const auto& g : r.gyros) hr[g.name] = g.summary.heading_rms_deg.at(StretchKind::Open);
	const GyroResult *raw = gyro(r, "raw"), *comp = gyro(r, "compensated"), *ideal = gyro(r, "ideal");
	if (raw && comp && ideal)
	{
		j["ratio_compensated_to_raw"] = ratio(comp->summary.position_rms_m.at(StretchKind::Open),
											  raw->summary.position_rms_m.at(StretchKind::Open));
		j["ratio_compensated_to_ideal"] = ratio(comp->summary.position_rms_m.at(StretchKind::Open),
												ideal->summary.position_rms_m.at(StretchKind::Open));
	}
	if (raw && comp && ideal)
	{
		for (const auto& [key, other] : {std::pair<const char*, const GyroResult*>{"compensated_minus_raw", raw},
										 {"compensated_minus_ideal", ideal}})
		{
			const auto d = pairedDifference(*comp, *other);
			JsonValue& e = j["paired_open_rms_difference_m"][key];
			e["mean"] = d.first;
			e["standard_error"] = std::isfinite(d.second) ? JsonValue(d.second) : JsonValue();
			e["verdict"] = verdict(d);
		}
	}
	JsonValue& kinds = j["position_rms_m_by_kind"];
	kinds = JsonValue::object();
	for (const auto& g : r.gyros)
	{
		JsonValue& k = kinds[g.name];
		k = JsonValue::object();
		for (const auto& [kind, v] : g.summary.position_rms_m) k[stretchKindName(kind)] = v;
	}
	JsonValue& per_seed = j["open_position_rms_m_per_seed"];
	per_seed = JsonValue::object();
	JsonValue& worst = j["worst_open_stretch"];
	worst = JsonValue::object();
	JsonValue& div = j["diverged_runs"];
	div = JsonValue::object();
	JsonValue& scale = j["odometry_scale_final"];
	scale = JsonValue::object();
	for (const auto& g : r.gyros)
	{
		per_seed[g.name] = JsonValue::array();
		for (double v : g.summary.open_rms_per_seed_m) per_seed[g.name].push_back(v);
		JsonValue& w = worst[g.name];
		const auto& f = g.summary.stretches[g.summary.worst_open];
		w["stretch"] = static_cast<unsigned long>(f.index);
		w["position_rms_m"] = f.position_rms_m;
		w["position_max_m"] = f.position_max_m;
		w["heading_rms_deg"] = f.heading_rms_deg;
		div[g.name] = static_cast<unsigned long>(g.summary.diverged_runs);
		scale[g.name] = JsonValue::array();
		for (double v : g.final_scale) scale[g.name].push_back(v);
	}
	JsonValue& hb = j["heading_budget"];
	hb = JsonValue::object();
	for (const auto& g : r.gyros)
	{
		hb[g.name] = JsonValue::array();
		for (const auto& h : g.heading_budget)
		{
			JsonValue e = JsonValue::object();
			e["stretch"] = static_cast<unsigned long>(h.index);
			e["duration_s"] = h.duration_s;
			e["length_m"] = h.length_m;
			e["entry_heading_rms_deg"] = h.entry_heading_rms_deg;
			e["entry_heading_mean_deg"] = h.entry_heading_mean_deg;
			e["entry_heading_spread_rms_deg"] = h.entry_heading_spread_rms_deg;
			e["entry_position_rms_m"] = h.entry_position_rms_m;
			e["gyro_drift_deg"] = h.gyro_drift_deg;
			e["walk_rms_deg"] = h.walk_rms_deg;
			e["end_heading_rms_deg"] = h.end_heading_rms_deg;
			hb[g.name].push_back(e);
		}
	}
	{
		const HeadingRelevance& hrel = r.relevance;
		JsonValue& rel = j["heading_relevance"];
		rel = JsonValue::object();
		rel["ideal_to_raw_position_rms"] = hrel.ideal_to_raw_position_rms;
		rel["max_reachable_ratio"] = HeadingRelevance::kMaxReachableRatio;
		rel["heading_matters"] = hrel.heading_matters;
		rel["verdict"] = hrel.heading_matters ? "heading matters" : "cannot tell: the map-matching dominates";
		rel["fields"] = JsonValue::array();
		for (const FieldRelevance& f : hrel.fields)
		{
			JsonValue e = JsonValue::object();
			e["stretch"] = static_cast<unsigned long>(f.index);
			e["raw_gyro_drift_deg"] = f.raw_gyro_drift_deg;
			e["ideal_entry_heading_rms_deg"] = f.ideal_entry_heading_rms_deg;
			e["ideal_to_raw_position_rms"] = f.ideal_to_raw_position_rms;
			e["gyro_dominates"] = f.gyro_dominates;
			rel["fields"].push_back(e);
		}
	}
	JsonValue& st = j["stretches"];
	st = JsonValue::array();
	for (std::size_t i = 0; i < world.stretches.size(); ++i)
	{
		const Stretch& s = world.stretches[i];
		JsonValue e = JsonValue::object();
		e["kind"] = stretchKindName(s.kind);
		e["t_begin_s"] = s.t_begin_s - r.t0_s;
		e["t_end_s"] = s.t_end_s - r.t0_s;
		e["s_begin_m"] = s.s_begin_m;
		e["s_end_m"] = s.s_end_m;
		JsonValue& rms = e["position_rms_m"];
		rms = JsonValue::object();
		for (const auto& g : r.gyros) rms[g.name] = g.summary.stretches[i].position_rms_m;
		JsonValue& hrms = e["heading_rms_deg"];
		hrms = JsonValue::object();
		for (const auto& g : r.gyros) hrms[g.name] = g.summary.stretches[i].heading_rms_deg;
		st.push_back(e);
	}
	j["runtime_s"] = r.runtime_s;
	const std::string json_text = j.dump();
	writeTextFileAtomically(dir + "/localize.json", json_text);
	if (!json_path.empty()) writeTextFileAtomically(json_path, json_text);

	// ---- errors.png: mean over seeds of position / heading error vs time, open stretches shaded.
	{
		PlotCanvas fig(1100, 800);
		LinePlot& p = fig.addPanel(1.5);
		p.title = "MRPT localization error vs time (mean over filter seeds); shaded: open fields (orange), tunnel (grey)";
		p.x_axis.label = "time [s]";
		p.y_axis.label = "position error [m]";
		LinePlot& q = fig.addPanel(1.0);
		q.x_axis.label = "time [s]";
		q.y_axis.label = "heading error [deg]";
		for (auto* panel : {&p, &q})
			for (const auto& s : world.stretches)
				if (s.kind != StretchKind::Urban)
					panel->addShade(s.t_begin_s - r.t0_s, s.t_end_s - r.t0_s,
									s.kind == StretchKind::Open ? plot_colour::kOrange : plot_colour::kGrey);
		for (const auto& g : r.gyros)
		{
			PlotSeries e{g.name, {}, {}, colourOf(g.name), 2}, h{g.name, {}, {}, colourOf(g.name), 1};
			const auto& r0 = g.runs.front();
			for (std::size_t k = 0; k < r0.t_s.size(); ++k)
			{
				double se = 0, sh = 0;
				for (const auto& run : g.runs)
				{
					se += run.position_m[k];
					sh += run.heading_deg[k];
				}
				e.x.push_back(r0.t_s[k] - r.t0_s);
				e.y.push_back(se / g.runs.size());
				h.y.push_back(sh / g.runs.size());
			}
			h.x = e.x;
			p.addSeries(e);
			q.addSeries(h);
		}
		fig.save(dir + "/errors.png");
	}

	// ---- map.png: the grid (downsampled), the route coloured by stretch kind.
	{
		const auto& g = *world.grid;
		const int sx = static_cast<int>(g.getSizeX()), sy = static_cast<int>(g.getSizeY());
		const int step = std::max(1, std::max(sx, sy) / 2000);
		cv::Mat img(sy / step, sx / step, CV_8UC3, cv::Scalar(255, 255, 255));
		for (int y = 0; y < sy; ++y)
			for (int x = 0; x < sx; ++x)
				if (g.getCell(x, y) < 0.5f)
				{
					const int px = x / step, py = (sy - 1 - y) / step;
					if (px < img.cols && py < img.rows) img.at<cv::Vec3b>(py, px) = cv::Vec3b(0, 0, 0);
				}
		for (std::size_t i = 1; i < truth.size(); i += 5)
		{
			const Stretch& s = stretchAt(world.stretches, truth[i].t_s);
			const cv::Scalar c = s.kind == StretchKind::Open ? plot_colour::kOrange
															 : (s.kind == StretchKind::Tunnel ? plot_colour::kPurple : plot_colour::kBlue);
			const int px = g.x2idx(truth[i].x_m) / step, py = (sy - 1 - g.y2idx(truth[i].y_m)) / step;
			cv::circle(img, {px, py}, 1, c, cv::FILLED);
		}
		cv::putText(img, "route: blue urban, orange open fields, purple tunnel; black: obstacles", {10, 25},
					cv::FONT_HERSHEY_SIMPLEX, 0.6, cv::Scalar(0, 0, 0), 1);
		std::vector<uchar> png;
		if (!cv::imencode(".png", img, png)) throw std::runtime_error(dir + "/map.png: PNG encoding failed");
		writeTextFileAtomically(dir + "/map.png", std::string(png.begin(), png.end()));
	}

	// ---- pf-localization inputs: map, rawlogs, .ini, ground truth.
	writeGz(dir + "/map.gridmap.gz", [&](mrpt::serialization::CArchive& ar) { ar << *world.grid; });
	{
		std::ostringstream gt;
		gt.precision(15);
		for (double t : scan_t)
		{
			const nav::TrajectoryPoint p = nav::interpolate(truth, t);
			gt << t << ' ' << p.x_m << ' ' << p.y_m << ' ' << p.yaw_rad << '\n';
		}
		writeTextFileAtomically(dir + "/ground_truth.txt", gt.str());
	}
	const mrpt::poses::CPose2D start(nav::interpolate(truth, scan_t.front()).x_m, nav::interpolate(truth, scan_t.front()).y_m,
									 nav::interpolate(truth, scan_t.front()).yaw_rad);
	for (const auto& g : r.gyros)
	{
		writeGz(dir + "/localize_" + g.name + ".rawlog", [&](mrpt::serialization::CArchive& ar) {
			for (std::size_t k = 1; k < scan_t.size(); ++k)
			{
				mrpt::obs::CActionRobotMovement2D act;
				act.timestamp = mrpt::Clock::fromDouble(scan_t[k]);
				// The increments as the first seed's filter used them (odometry scale calibrated so far).
				mrpt::poses::CPose2D incr = g.odometry[k] - g.odometry[k - 1];
				const double sc = k < g.first_run.odometry_scale.size() ? g.first_run.odometry_scale[k] : 1.0;
				incr.x(incr.x() * sc);
				incr.y(incr.y() * sc);
				const bool wheel_only = k < g.odometry_step.size() && g.odometry_step[k] == StepSource::WheelOnly;
				act.computeFromOdometry(incr, wheel_only ? mcl.wheel_only_motion : mcl.motion.toMrpt(scan_t[k] - scan_t[k - 1]));
				mrpt::obs::CActionCollection acts;
				acts.insert(act);
				mrpt::obs::CSensoryFrame sf;
				sf.insert(scans[k]);
				ar << acts << sf;
			}
		});
		writeTextFileAtomically(dir + "/pf-localization_" + g.name + ".ini", iniText(g.name, mcl, laser, start));
	}
}

}  // namespace mrpt_fog::localize
