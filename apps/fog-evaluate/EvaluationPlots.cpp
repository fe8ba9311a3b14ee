/* fog-evaluate: the PNG figures. */
#include "EvaluationPlots.h"

#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/plot/PlotCanvas.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <stdexcept>

namespace mrpt_fog::evaluate
{
namespace
{
/** A lighter version of a colour (for the unaveraged samples). */
cv::Scalar light(const cv::Scalar& c) { return c * 0.35 + cv::Scalar(255, 255, 255) * 0.65; }

std::vector<double> minus(const std::vector<double>& v, double m)
{
	std::vector<double> out(v);
	for (double& x : out) x -= m;
	return out;
}

/** Mean of the finite thermistor readings per sample (NaN when none). */
std::vector<double> meanTemperature_C(const FogSeries& s)
{
	std::vector<double> out(s.size(), NAN);
	for (std::size_t k = 0; k < s.size(); k++)
	{
		double sum = 0;
		int n = 0;
		for (const auto& col : s.temp_C)
			if (std::isfinite(col[k]))
			{
				sum += col[k];
				n++;
			}
		if (n > 0) out[k] = sum / n;
	}
	return out;
}

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
 * line is drawn across missing data. */
PlotSeries gapBroken(const std::string& label, const std::vector<double>& time_s, const std::vector<double>& y,
					 double scale, const cv::Scalar& colour)
{
	PlotSeries ps;
	ps.label = label;
	ps.colour = colour;
	const double dt = medianSampleInterval_s(time_s);
	const std::size_t n = time_s.size();
	// A long log is thinned to the lowest and highest sample of each of kBuckets time buckets:
	// the envelope that a line through every sample draws at this width, in bounded memory
	// (issue 14: 4 thermistors x 2.4 M samples took 300 MB here).
	constexpr std::size_t kBuckets = 4096;
	if (n <= 4 * kBuckets)
	{
		for (std::size_t k = 0; k < n; k++)
		{
			if (k > 0 && time_s[k] - time_s[k - 1] > 5 * dt)
			{
				ps.x.push_back(NAN);
				ps.y.push_back(NAN);
			}
			ps.x.push_back(time_s[k] * scale);
			ps.y.push_back(y[k]);
		}
		return ps;
	}
	const double t0 = time_s.front(), span = time_s.back() - t0;
	const auto bucketOf = [&](std::size_t k) {
		return std::min(kBuckets - 1, static_cast<std::size_t>((time_s[k] - t0) / span * static_cast<double>(kBuckets)));
	};
	const auto flush = [&](std::size_t a, std::size_t b) {  // samples [a, b)
		std::size_t lo = b, hi = b;
		for (std::size_t k = a; k < b; k++)
			if (std::isfinite(y[k]))
			{
				if (lo == b || y[k] < y[lo]) lo = k;
				if (hi == b || y[k] > y[hi]) hi = k;
			}
		if (lo == b)  // no reading in the bucket: the line breaks
		{
			ps.x.push_back(NAN);
			ps.y.push_back(NAN);
			return;
		}
		for (std::size_t k : {std::min(lo, hi), std::max(lo, hi)})
		{
			ps.x.push_back(time_s[k] * scale);
			ps.y.push_back(y[k]);
			if (lo == hi) break;
		}
	};
	std::size_t start = 0;
	for (std::size_t k = 1; k < n; k++)
	{
		const bool gap = time_s[k] - time_s[k - 1] > 5 * dt;
		if (gap || bucketOf(k) != bucketOf(start))
		{
			flush(start, k);
			start = k;
		}
		if (gap)
		{
			ps.x.push_back(NAN);
			ps.y.push_back(NAN);
		}
	}
	flush(start, n);
	return ps;
}

/** The thin trace under the bold tau averages: averages over tau/10 (centres joined, broken at
 * empty windows), or the samples themselves when tau/10 is under 2 sample periods. */
PlotSeries shortTrace(const std::string& what, const std::vector<double>& time_s, const std::vector<double>& y,
					  double tau_s, double mean, double scale, const cv::Scalar& colour)
{
	const double short_tau = tau_s / 10;
	if (short_tau < 2 * medianSampleInterval_s(time_s))
		return gapBroken(what + " samples", time_s, minus(y, mean), scale, colour);
	PlotSeries ps;
	ps.label = what + " " + formatValue("%g", short_tau) + " s avg";
	ps.colour = colour;
	BiasStats st;
	try
	{
		st = biasStats(time_s, y, short_tau);
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

/** Shades the intervals with the gyro powered off and the gaps in the log (> 5 sample periods). */
void shadeOffAndGaps(LinePlot& p, const FogSeries& s, double scale, bool with_labels)
{
	const double dt = medianSampleInterval_s(s.time_s);
	bool off_labelled = !with_labels, gap_labelled = !with_labels;
	for (std::size_t k = 1; k < s.size(); k++)
		if (s.time_s[k] - s.time_s[k - 1] > 5 * dt)
		{
			p.addShade(s.time_s[k - 1] * scale, s.time_s[k] * scale, plot_colour::kRed, gap_labelled ? "" : "no data");
			gap_labelled = true;
		}
	if (s.power.empty()) return;
	for (std::size_t k = 0; k < s.size();)
	{
		if (s.power[k] != 0.0)
		{
			k++;
			continue;
		}
		std::size_t e = k;
		while (e + 1 < s.size() && s.power[e + 1] == 0.0) e++;
		p.addShade(s.time_s[k] * scale, s.time_s[e] * scale, plot_colour::kGrey, off_labelled ? "" : "gyro off");
		off_labelled = true;
		k = e + 1;
	}
}

void biasVsTime(const std::string& path, const PlotInputs& in)
{
	const FogSeries& s = *in.series;
	const double duration_s = s.time_s.back() - s.time_s.front();
	const bool hours = duration_s > 3 * 3600.0;
	const double scale = hours ? 1.0 / 3600.0 : 1.0;
	const std::string tlabel = hours ? "time [h]" : "time [s]";

	const bool temps = s.thermistorCount() > 0;
	PlotCanvas fig(1100, temps ? 800 : 520);
	LinePlot& top = fig.addPanel(temps ? 1.7 : 1.0);
	top.title = "bias vs time (each about its own mean; " + formatValue("%g", in.tau_s) + " s averages bold, " +
				formatValue("%g", in.tau_s / 10) + " s thin)";
	top.x_axis.label = tlabel;
	top.x_axis.min = s.time_s.front() * scale;  // the run, not rounded out to a tick
	top.x_axis.max = s.time_s.back() * scale;
	top.y_axis.label = "bias - mean [deg/h]";
	shadeOffAndGaps(top, s, scale, true);
	const double m_raw = in.raw->stats.mean_dph;
	top.addSeries(shortTrace("raw", s.time_s, *in.raw_bias_dph, in.tau_s, m_raw, scale, light(plot_colour::kBlue)));
	if (in.comp)
	{
		const double m_comp = in.comp->stats.mean_dph;
		top.addSeries(
			shortTrace("compensated", s.time_s, *in.comp_bias_dph, in.tau_s, m_comp, scale, light(plot_colour::kOrange)));
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
		shadeOffAndGaps(bottom, s, scale, false);
		for (std::size_t i = 0; i < s.thermistorCount(); i++)
			bottom.addSeries(gapBroken(s.thermistors[i].name, s.time_s, s.temp_C[i], scale, plot_colour::cycle(i + 2)));
	}
	fig.save(path);
}

bool biasVsTemperature(const std::string& path, const PlotInputs& in)
{
	const FogSeries& s = *in.series;
	if (s.thermistorCount() == 0) return false;
	BiasStats tstats;
	try
	{
		tstats = biasStats(s.time_s, meanTemperature_C(s), in.tau_s);
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
