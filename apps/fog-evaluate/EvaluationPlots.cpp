/* fog-evaluate: the PNG figures. */
#include "EvaluationPlots.h"

#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/plot/PlotCanvas.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <stdexcept>

namespace mrpt_fog::evaluate
{
namespace
{
/** A lighter version of a colour (for the unaveraged samples). */
cv::Scalar light(const cv::Scalar& c) { return c * 0.35 + cv::Scalar(255, 255, 255) * 0.65; }

/** (time, column col) of the rows, in order. */
RecordPass rowColumn(const RowSpill& rows, std::size_t col)
{
	return [&rows, col](const RecordVisitor& v) {
		const std::size_t w = rows.width();
		rows.forEachBlock([&](const double* r, std::size_t n, std::size_t) {
			for (std::size_t j = 0; j < n; j++) v(r[j * w], r[j * w + col]);
		});
	};
}

/** (time, value(chunk, j)) of every sample of the run, in order. */
RecordPass runColumn(const FogRun& run, std::function<double(const FogSeries&, std::size_t)> value)
{
	return [&run, value](const RecordVisitor& v) {
		run.forEachChunk([&](const FogSeries& c, std::size_t) {
			for (std::size_t j = 0; j < c.size(); j++) v(c.time_s[j], value(c, j));
		});
	};
}

/** The record minus m. */
RecordPass minus(const RecordPass& pass, double m)
{
	return [pass, m](const RecordVisitor& v) { pass([&](double t, double y) { v(t, y - m); }); };
}

/** Mean of the finite thermistor readings of sample j (NaN when none). */
double meanTemperature_C(const FogSeries& s, std::size_t k)
{
	double sum = 0;
	int n = 0;
	for (const auto& col : s.temp_C)
		if (std::isfinite(col[k]))
		{
			sum += col[k];
			n++;
		}
	return n > 0 ? sum / n : NAN;
}

/** What every trace of the time plot shares: samples, first and last time, median interval. */
struct TimeAxis
{
	std::size_t n = 0;
	double front_s = 0, back_s = 0, dt_s = 0;
};

/** Window averages as a step line (each window's average held over its tau). */
void addAverages(LinePlot& p, const BiasStats& st, double mean, double time_scale, const std::string& label,
				 const cv::Scalar& colour)
{
	PlotSeries s;
	s.label = label;
	s.colour = colour;
	s.thickness_px = 2;
	for (std::size_t i = 0; i < st.window_count; i++)
	{
		const double a = (st.window_center_s[i] - st.tau_s / 2) * time_scale;
		const double b = (st.window_center_s[i] + st.tau_s / 2) * time_scale;
		if (i > 0 && std::abs(st.window_center_s[i] - st.window_center_s[i - 1] - st.tau_s) > 1e-6 * st.tau_s)
		{
			s.x.push_back(NAN);  // gap: an empty window in between
			s.y.push_back(NAN);
		}
		s.x.push_back(a);
		s.y.push_back(st.window_mean_dph[i] - mean);
		s.x.push_back(b);
		s.y.push_back(st.window_mean_dph[i] - mean);
	}
	p.addSeries(s);
}

/** A series (x scaled) with NaN inserted at the gaps of the log (> 5 sample periods), so that no
 * line is drawn across missing data. Read in one pass. */
PlotSeries gapBroken(const std::string& label, const RecordPass& pass, const TimeAxis& ax, double scale,
					 const cv::Scalar& colour)
{
	PlotSeries ps;
	ps.label = label;
	ps.colour = colour;
	const double dt = ax.dt_s;
	const std::size_t n = ax.n;
	// A long log is thinned to the lowest and highest sample of each of kBuckets time buckets:
	// the envelope that a line through every sample draws at this width, in bounded memory
	// (4 thermistors x 2.4 M samples took 300 MB here).
	constexpr std::size_t kBuckets = 4096;
	std::size_t k = 0;
	double t_prev = 0;
	if (n <= 4 * kBuckets)
	{
		pass([&](double t, double y) {
			if (k > 0 && t - t_prev > 5 * dt)
			{
				ps.x.push_back(NAN);
				ps.y.push_back(NAN);
			}
			ps.x.push_back(t * scale);
			ps.y.push_back(y);
			t_prev = t;
			k++;
		});
		return ps;
	}
	const double t0 = ax.front_s, span = ax.back_s - t0;
	const auto bucketOf = [&](double t) {
		return std::min(kBuckets - 1, static_cast<std::size_t>((t - t0) / span * static_cast<double>(kBuckets)));
	};
	struct Sample
	{
		std::size_t k;
		double t, y;
	};
	bool any = false;  // the bucket's lowest and highest finite samples (first of equals)
	Sample lo{}, hi{};
	std::size_t bucket = 0;
	const auto flush = [&] {
		if (!any)  // no reading in the bucket: the line breaks
		{
			ps.x.push_back(NAN);
			ps.y.push_back(NAN);
			return;
		}
		const Sample& a = lo.k <= hi.k ? lo : hi;
		const Sample& b = lo.k <= hi.k ? hi : lo;
		ps.x.push_back(a.t * scale);
		ps.y.push_back(a.y);
		if (lo.k != hi.k)
		{
			ps.x.push_back(b.t * scale);
			ps.y.push_back(b.y);
		}
	};
	pass([&](double t, double y) {
		if (k == 0) bucket = bucketOf(t);
		else
		{
			const bool gap = t - t_prev > 5 * dt;
			if (gap || bucketOf(t) != bucket)
			{
				flush();
				any = false;
				bucket = bucketOf(t);
			}
			if (gap)
			{
				ps.x.push_back(NAN);
				ps.y.push_back(NAN);
			}
		}
		if (std::isfinite(y))
		{
			if (!any || y < lo.y) lo = {k, t, y};
			if (!any || y > hi.y) hi = {k, t, y};
			any = true;
		}
		t_prev = t;
		k++;
	});
	flush();
	return ps;
}

/** The thin trace under the bold tau averages: averages over tau/10 (centres joined, broken at
 * empty windows), or the samples themselves when tau/10 is under 2 sample periods. */
PlotSeries shortTrace(const std::string& what, const RecordPass& pass, const TimeAxis& ax, double tau_s, double mean,
					  double scale, const cv::Scalar& colour)
{
	const double short_tau = tau_s / 10;
	if (short_tau < 2 * ax.dt_s) return gapBroken(what + " samples", minus(pass, mean), ax, scale, colour);
	PlotSeries ps;
	ps.label = what + " " + formatValue("%g", short_tau) + " s avg";
	ps.colour = colour;
	BiasStats st;
	try
	{
		st = biasStats(pass, short_tau);
	}
	catch (const std::invalid_argument&)
	{
		return ps;  // nothing to draw
	}
	for (std::size_t i = 0; i < st.window_count; i++)
	{
		if (i > 0 && st.window_center_s[i] - st.window_center_s[i - 1] > 1.5 * short_tau)
		{
			ps.x.push_back(NAN);
			ps.y.push_back(NAN);
		}
		ps.x.push_back(st.window_center_s[i] * scale);
		ps.y.push_back(st.window_mean_dph[i] - mean);
	}
	return ps;
}

/** Shades the intervals with the gyro powered off and the gaps in the log (> 5 sample periods):
 * the gaps first, then the off intervals (two passes). */
void shadeOffAndGaps(LinePlot& p, const FogRun& run, const TimeAxis& ax, double scale, bool with_labels)
{
	const double dt = ax.dt_s;
	bool off_labelled = !with_labels, gap_labelled = !with_labels;
	bool first = true;
	double t_prev = 0;
	run.forEachChunk([&](const FogSeries& c, std::size_t) {
		for (std::size_t j = 0; j < c.size(); j++)
		{
			const double t = c.time_s[j];
			if (!first && t - t_prev > 5 * dt)
			{
				p.addShade(t_prev * scale, t * scale, plot_colour::kRed, gap_labelled ? "" : "no data");
				gap_labelled = true;
			}
			first = false;
			t_prev = t;
		}
	});
	if (!run.hasPower()) return;
	bool off = false;
	double off_start = 0, off_last = 0;
	const auto shade = [&] {
		p.addShade(off_start * scale, off_last * scale, plot_colour::kGrey, off_labelled ? "" : "gyro off");
		off_labelled = true;
	};
	run.forEachChunk([&](const FogSeries& c, std::size_t) {
		for (std::size_t j = 0; j < c.size(); j++)
		{
			if (c.power[j] != 0.0)
			{
				if (off) shade(), off = false;
				continue;
			}
			if (!off) off = true, off_start = c.time_s[j];
			off_last = c.time_s[j];
		}
	});
	if (off) shade();
}

void biasVsTime(const std::string& path, const PlotInputs& in)
{
	const FogRun& run = *in.run;
	TimeAxis ax;
	ax.n = run.size();
	ax.front_s = run.frontTime_s();
	ax.back_s = run.backTime_s();
	ax.dt_s = medianSampleInterval_s(rowColumn(*in.rows, 0));
	const double duration_s = ax.back_s - ax.front_s;
	const bool hours = duration_s > 3 * 3600.0;
	const double scale = hours ? 1.0 / 3600.0 : 1.0;
	const std::string tlabel = hours ? "time [h]" : "time [s]";

	const std::size_t thermistors = run.header().thermistorCount();
	const bool temps = thermistors > 0;
	PlotCanvas fig(1100, temps ? 800 : 520);
	LinePlot& top = fig.addPanel(temps ? 1.7 : 1.0);
	top.title = "bias vs time (each about its own mean; " + formatValue("%g", in.tau_s) + " s averages bold, " +
				formatValue("%g", in.tau_s / 10) + " s thin)";
	top.x_axis.label = tlabel;
	top.x_axis.min = ax.front_s * scale;  // the run, not rounded out to a tick
	top.x_axis.max = ax.back_s * scale;
	top.y_axis.label = "bias - mean [deg/h]";
	shadeOffAndGaps(top, run, ax, scale, true);
	const double m_raw = in.raw->stats.mean_dph;
	top.addSeries(shortTrace("raw", rowColumn(*in.rows, 1), ax, in.tau_s, m_raw, scale, light(plot_colour::kBlue)));
	if (in.comp)
	{
		const double m_comp = in.comp->stats.mean_dph;
		top.addSeries(shortTrace("compensated", rowColumn(*in.rows, 2), ax, in.tau_s, m_comp, scale,
								 light(plot_colour::kOrange)));
		addAverages(top, in.raw->stats, m_raw, scale, "raw avg (mean " + formatValue("%.4g", m_raw) + " deg/h)",
					plot_colour::kBlue);
		addAverages(top, in.comp->stats, m_comp, scale, "compensated avg (mean " + formatValue("%.4g", m_comp) + " deg/h)",
					plot_colour::kOrange);
	}
	else
		addAverages(top, in.raw->stats, m_raw, scale, "raw avg (mean " + formatValue("%.4g", m_raw) + " deg/h)",
					plot_colour::kBlue);
	if (temps)
	{
		LinePlot& bottom = fig.addPanel(1.0);
		bottom.x_axis.label = tlabel;
		bottom.y_axis.label = "temperature [degC]";
		const cv::Vec2d xl = top.xLimits();
		bottom.x_axis.min = xl[0];
		bottom.x_axis.max = xl[1];
		shadeOffAndGaps(bottom, run, ax, scale, false);
		for (std::size_t i = 0; i < thermistors; i++)
			bottom.addSeries(gapBroken(run.header().thermistors[i].name,
									   runColumn(run, [i](const FogSeries& c, std::size_t j) { return c.temp_C[i][j]; }),
									   ax, scale, plot_colour::cycle(i + 2)));
	}
	fig.save(path);
}

bool biasVsTemperature(const std::string& path, const PlotInputs& in)
{
	if (in.run->header().thermistorCount() == 0) return false;
	BiasStats tstats;
	try
	{
		tstats = biasStats(runColumn(*in.run, meanTemperature_C), in.tau_s);
	}
	catch (const std::invalid_argument&)
	{
		return false;  // no usable temperatures
	}
	std::map<double, double> temp_at;  // window centre -> mean temperature (same window grid)
	for (std::size_t i = 0; i < tstats.window_count; i++) temp_at[tstats.window_center_s[i]] = tstats.window_mean_dph[i];
	auto series = [&](const RateEvaluation& e, const std::string& label, const cv::Scalar& colour) {
		PlotSeries ps;
		ps.label = label;
		ps.colour = colour;
		ps.thickness_px = 2;
		for (std::size_t i = 0; i < e.stats.window_count; i++)
		{
			const auto it = temp_at.find(e.stats.window_center_s[i]);
			ps.x.push_back(it == temp_at.end() ? NAN : it->second);
			ps.y.push_back(it == temp_at.end() ? NAN : e.stats.window_mean_dph[i] - e.stats.mean_dph);
		}
		return ps;
	};
	PlotCanvas fig(900, 650);
	LinePlot& p = fig.addPanel();
	p.title = formatValue("%g", in.tau_s) + " s averaged bias vs mean coil temperature (time order)";
	p.x_axis.label = "mean thermistor temperature [degC]";
	p.y_axis.label = "bias - mean [deg/h]";
	p.addSeries(series(*in.raw, "raw", plot_colour::kBlue));
	if (in.comp) p.addSeries(series(*in.comp, "compensated", plot_colour::kOrange));
	fig.save(path);
	return true;
}

void addNoiseLines(LinePlot& p, const RateEvaluation& e, const std::string& who, const cv::Scalar& colour)
{
	if (e.allan.empty()) return;
	const double t0 = e.allan.front().tau_s, t1 = e.allan.back().tau_s;
	auto line = [&](const AllanLineFit& f, const std::string& label) {
		if (!f.identified()) return;
		PlotSeries s;
		s.label = label;
		s.colour = colour;
		s.dashed = true;
		for (double t = t0; t <= t1 * 1.0001; t *= 2)
		{
			s.x.push_back(t);
			s.y.push_back(f.at(t));
		}
		p.addSeries(s);
	};
	const AllanNoiseTerms& n = e.terms;
	line(n.quantization, who + " Q = " + formatValue("%.3g", n.quantization_arcsec) + " arcsec");
	line(n.arw, who + " N = " + formatValue("%.3g", n.arw_dpsh) + " deg/sqrt(h)");
	line(n.flat, who + " 0.664 B, B = " + formatValue("%.3g", n.bias_instability_dph) + " deg/h");
	line(n.rrw, who + " K = " + formatValue("%.3g", n.rrw_dphsh) + " deg/h/sqrt(h)");
}

void allanPlot(const std::string& path, const PlotInputs& in)
{
	PlotCanvas fig(900, 700);
	LinePlot& p = fig.addPanel();
	p.title = "overlapping Allan deviation (IEEE 952 lines dashed)";
	p.x_axis = {"tau [s]", true};
	p.y_axis = {"Allan deviation [deg/h]", true};
	double lo = INFINITY, hi = -INFINITY;
	auto curve = [&](const RateEvaluation& e, const std::string& label, const cv::Scalar& colour) {
		PlotSeries s;
		s.label = label;
		s.colour = colour;
		s.thickness_px = 2;
		for (const auto& a : e.allan)
		{
			s.x.push_back(a.tau_s);
			s.y.push_back(a.adev);
			if (a.adev > 0)
			{
				lo = std::min(lo, a.adev);
				hi = std::max(hi, a.adev);
			}
		}
		p.addSeries(s);
	};
	curve(*in.raw, "raw", plot_colour::kBlue);
	if (in.comp) curve(*in.comp, "compensated", plot_colour::kOrange);
	if (lo <= hi)
	{
		// Limits from the curves only: the fitted lines are clipped to them.
		p.y_axis.min = std::pow(10.0, std::floor(std::log10(lo)));
		p.y_axis.max = std::pow(10.0, std::ceil(std::log10(hi)));
		if (p.y_axis.max <= p.y_axis.min) p.y_axis.max = p.y_axis.min * 10;
	}
	addNoiseLines(p, *in.raw, "raw", plot_colour::kBlue);
	if (in.comp) addNoiseLines(p, *in.comp, "comp.", plot_colour::kOrange);
	fig.save(path);
}
}  // namespace

std::vector<std::string> writeEvaluationPlots(const std::string& dir, const PlotInputs& in)
{
	std::error_code ec;
	std::filesystem::create_directories(dir, ec);
	if (ec) throw std::runtime_error("cannot create plot directory '" + dir + "': " + ec.message());
	std::vector<std::string> written;
	const std::string a = dir + "/bias_vs_time.png", b = dir + "/bias_vs_temperature.png",
					  c = dir + "/allan_deviation.png";
	biasVsTime(a, in);
	written.push_back(a);
	if (biasVsTemperature(b, in)) written.push_back(b);
	allanPlot(c, in);
	written.push_back(c);
	return written;
}

}  // namespace mrpt_fog::evaluate
