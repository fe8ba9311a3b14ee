/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/NumberFormat.h>
#include <mrpt_fog/plot/LinePlot.h>

#include <opencv2/imgproc.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mrpt_fog
{
namespace plot_colour
{
cv::Scalar cycle(std::size_t k)
{
	static const cv::Scalar c[] = {kBlue, kOrange, kGreen, kRed, kPurple, kBrown, kGrey};
	return c[k % (sizeof(c) / sizeof(c[0]))];
}
}  // namespace plot_colour

namespace
{
constexpr int kFont = cv::FONT_HERSHEY_SIMPLEX;
constexpr double kTickFontScale = 0.4, kLabelFontScale = 0.45, kTitleFontScale = 0.5;
const cv::Scalar kGridColour(225, 225, 225), kAxisColour(0, 0, 0), kTextColour(30, 30, 30);

double niceStep(double raw)
{
	if (!(raw > 0) || !std::isfinite(raw)) return 1.0;
	const double e = std::pow(10.0, std::floor(std::log10(raw)));
	const double f = raw / e;
	return (f <= 1.0 ? 1.0 : f <= 2.0 ? 2.0 : f <= 5.0 ? 5.0 : 10.0) * e;
}

double u(double v, bool log) { return log ? std::log10(v) : v; }

/** Limits of an axis: the set ones, or nice limits around the data. */
cv::Vec2d resolveLimits(const PlotAxis& axis, std::vector<double> values, const char* which)
{
	double lo = INFINITY, hi = -INFINITY;
	for (double v : values)
		if (std::isfinite(v) && (!axis.log || v > 0))
		{
			lo = std::min(lo, v);
			hi = std::max(hi, v);
		}
	if (!(lo <= hi))
	{
		lo = axis.log ? 1.0 : 0.0;
		hi = axis.log ? 10.0 : 1.0;
	}
	if (axis.log)
	{
		double a = std::pow(10.0, std::floor(std::log10(lo) + 1e-9));
		double b = std::pow(10.0, std::ceil(std::log10(hi) - 1e-9));
		if (b <= a) b = a * 10;
		lo = a;
		hi = b;
	}
	else
	{
		if (hi - lo <= 1e-12 * std::max(1.0, std::abs(hi)))
		{
			const double pad = std::max(1e-9, 0.1 * std::abs(hi));
			lo -= pad;
			hi += pad;
		}
		const double step = niceStep((hi - lo) / 6);
		lo = std::floor(lo / step + 1e-9) * step;
		hi = std::ceil(hi / step - 1e-9) * step;
	}
	if (std::isfinite(axis.min)) lo = axis.min;
	if (std::isfinite(axis.max)) hi = axis.max;
	if (!(hi > lo) || (axis.log && !(lo > 0)))
		throw std::invalid_argument(std::string("plot ") + which + " axis '" + axis.label +
									"': limits must satisfy min < max (and min > 0 on a log axis)");
	return {lo, hi};
}

void putTextRotated(cv::Mat& img, const std::string& text, cv::Point centre, double scale)
{
	int base = 0;
	const cv::Size sz = cv::getTextSize(text, kFont, scale, 1, &base);
	cv::Mat t(sz.height + base + 4, sz.width + 4, CV_8UC3, cv::Scalar(255, 255, 255));
	cv::putText(t, text, {2, sz.height + 2}, kFont, scale, kTextColour, 1, cv::LINE_AA);
	cv::Mat r;
	cv::rotate(t, r, cv::ROTATE_90_COUNTERCLOCKWISE);
	cv::Rect dst(centre.x - r.cols / 2, centre.y - r.rows / 2, r.cols, r.rows);
	const cv::Rect clipped = dst & cv::Rect(0, 0, img.cols, img.rows);
	if (clipped.empty()) return;
	r(cv::Rect(clipped.x - dst.x, clipped.y - dst.y, clipped.width, clipped.height)).copyTo(img(clipped));
}

void putTextCentred(cv::Mat& img, const std::string& text, cv::Point centre, double scale)
{
	int base = 0;
	const cv::Size sz = cv::getTextSize(text, kFont, scale, 1, &base);
	cv::putText(img, text, {centre.x - sz.width / 2, centre.y + sz.height / 2}, kFont, scale, kTextColour, 1,
				cv::LINE_AA);
}

cv::Point clampPoint(const cv::Point2d& p)
{
	auto c = [](double v) { return static_cast<int>(std::lround(std::clamp(v, -1e6, 1e6))); };
	return {c(p.x), c(p.y)};
}

void drawSegment(cv::Mat& img, const cv::Rect& area, cv::Point2d a, cv::Point2d b, const PlotSeries& s,
				 double& dash_phase)
{
	cv::Point pa = clampPoint(a), pb = clampPoint(b);
	if (!cv::clipLine(area, pa, pb)) return;
	if (!s.dashed)
	{
		cv::line(img, pa, pb, s.colour, s.thickness_px, cv::LINE_8);
		return;
	}
	constexpr double on = 8, period = 13;
	const double len = std::hypot(pb.x - pa.x, pb.y - pa.y);
	for (double d = 0; d < len;)
	{
		const double ph = std::fmod(dash_phase + d, period);
		const double step = ph < on ? std::min(on - ph, len - d) : std::min(period - ph, len - d);
		if (ph < on)
		{
			const cv::Point2d p0 = pa + (pb - pa) * (d / len), p1 = pa + (pb - pa) * ((d + step) / len);
			cv::line(img, clampPoint(p0), clampPoint(p1), s.colour, s.thickness_px, cv::LINE_8);
		}
		d += std::max(step, 1e-3);
	}
	dash_phase = std::fmod(dash_phase + len, period);
}
}  // namespace

std::vector<double> niceTicks(double lo, double hi, bool log, int target)
{
	std::vector<double> t;
	if (!(hi > lo)) return t;
	if (log)
	{
		if (!(lo > 0)) return t;
		const int d0 = static_cast<int>(std::floor(std::log10(lo) + 1e-9));
		const int d1 = static_cast<int>(std::ceil(std::log10(hi) - 1e-9));
		const int every = std::max(1, (d1 - d0 + target - 1) / target);
		const bool minor = d1 - d0 < 3;
		for (int d = d0; d <= d1; d++)
			for (double m : {1.0, 2.0, 5.0})
			{
				if (m != 1.0 && !minor) continue;
				if (m == 1.0 && (d - d0) % every != 0) continue;
				const double v = m * std::pow(10.0, d);
				if (v >= lo * (1 - 1e-9) && v <= hi * (1 + 1e-9)) t.push_back(v);
			}
		return t;
	}
	const double step = niceStep((hi - lo) / std::max(1, target));
	for (double v = std::ceil(lo / step - 1e-9) * step; v <= hi + 1e-9 * step; v += step)
		t.push_back(std::abs(v) < 1e-12 * step ? 0.0 : v);
	return t;
}

std::string tickLabel(double v) { return formatValue("%.6g", v); }

PlotSeries& LinePlot::addSeries(PlotSeries s)
{
	if (s.x.size() != s.y.size())
		throw std::invalid_argument("plot series '" + s.label + "': " + std::to_string(s.x.size()) + " x values but " +
									std::to_string(s.y.size()) + " y values");
	series_.push_back(std::move(s));
	return series_.back();
}

void LinePlot::addShade(double x0, double x1, const cv::Scalar& colour, const std::string& label)
{
	shades_.push_back({std::min(x0, x1), std::max(x0, x1), colour, label});
}

bool LinePlot::hasRightAxis() const
{
	return std::any_of(series_.begin(), series_.end(), [](const PlotSeries& s) { return s.right_axis; });
}

cv::Rect LinePlot::dataArea(const cv::Rect& panel) const
{
	const int right = hasRightAxis() ? kMarginRightY2 : kMarginRight;
	return {panel.x + kMarginLeft, panel.y + kMarginTop, std::max(10, panel.width - kMarginLeft - right),
			std::max(10, panel.height - kMarginTop - kMarginBottom)};
}

cv::Vec2d LinePlot::xLimits() const
{
	std::vector<double> v;
	for (const auto& s : series_) v.insert(v.end(), s.x.begin(), s.x.end());
	if (v.empty())
		for (const auto& sh : shades_)
		{
			v.push_back(sh.x0);
			v.push_back(sh.x1);
		}
	return resolveLimits(x_axis, v, "x");
}

cv::Vec2d LinePlot::yLimits(bool right_axis) const
{
	std::vector<double> v;
	for (const auto& s : series_)
		if (s.right_axis == right_axis) v.insert(v.end(), s.y.begin(), s.y.end());
	return resolveLimits(right_axis ? y2_axis : y_axis, v, right_axis ? "right y" : "y");
}

LinePlot::Mapping LinePlot::mapping(const cv::Rect& panel) const
{
	Mapping m;
	m.area = dataArea(panel);
	m.x = xLimits();
	m.y = yLimits(false);
	m.y2 = hasRightAxis() ? yLimits(true) : cv::Vec2d(0, 1);
	m.xlog = x_axis.log;
	m.ylog = y_axis.log;
	m.y2log = y2_axis.log;
	return m;
}

cv::Point2d LinePlot::Mapping::operator()(double xv, double yv, bool right_axis) const
{
	const cv::Vec2d& yl = right_axis ? y2 : y;
	const bool yl_log = right_axis ? y2log : ylog;
	const double fx = (u(xv, xlog) - u(x[0], xlog)) / (u(x[1], xlog) - u(x[0], xlog));
	const double fy = (u(yv, yl_log) - u(yl[0], yl_log)) / (u(yl[1], yl_log) - u(yl[0], yl_log));
	return {area.x + fx * (area.width - 1), area.y + (area.height - 1) - fy * (area.height - 1)};
}

cv::Point2d LinePlot::toPixel(const cv::Rect& panel, double x, double y, bool right_axis) const
{
	return mapping(panel)(x, y, right_axis);
}

void LinePlot::drawShades(cv::Mat& img, const Mapping& map) const
{
	const cv::Rect area = map.area;
	const cv::Vec2d yl = map.y;
	// alpha-blended
	for (const auto& sh : shades_)
	{
		const double c0 = map(sh.x0, yl[0]).x, c1 = map(sh.x1, yl[0]).x;
		const int a = std::max(area.x, static_cast<int>(std::floor(std::clamp(c0, -1e6, 1e6))));
		const int b = std::min(area.x + area.width, static_cast<int>(std::ceil(std::clamp(c1, -1e6, 1e6))) + 1);
		if (b <= a) continue;
		cv::Mat roi = img(cv::Rect(a, area.y, b - a, area.height));
		cv::Mat fill(roi.size(), roi.type(), sh.colour);
		cv::addWeighted(roi, 0.75, fill, 0.25, 0.0, roi);
	}
}

void LinePlot::drawGridAndTicks(cv::Mat& img, const Mapping& map) const
{
	const cv::Rect area = map.area;
	const cv::Vec2d xl = map.x, yl = map.y, y2l = map.y2;
	int base = 0;
	for (double t : niceTicks(xl[0], xl[1], x_axis.log))
	{
		const int c = static_cast<int>(std::lround(map(t, yl[0]).x));
		cv::line(img, {c, area.y}, {c, area.y + area.height - 1}, kGridColour, 1);
		cv::line(img, {c, area.y + area.height - 1}, {c, area.y + area.height + 3}, kAxisColour, 1);
		putTextCentred(img, tickLabel(t), {c, area.y + area.height + 12}, kTickFontScale);
	}
	for (double t : niceTicks(yl[0], yl[1], y_axis.log))
	{
		const int r = static_cast<int>(std::lround(map(xl[0], t).y));
		cv::line(img, {area.x, r}, {area.x + area.width - 1, r}, kGridColour, 1);
		cv::line(img, {area.x - 4, r}, {area.x, r}, kAxisColour, 1);
		const std::string s = tickLabel(t);
		const cv::Size sz = cv::getTextSize(s, kFont, kTickFontScale, 1, &base);
		cv::putText(img, s, {area.x - 6 - sz.width, r + sz.height / 2}, kFont, kTickFontScale, kTextColour, 1,
					cv::LINE_AA);
	}
	if (hasRightAxis())
		for (double t : niceTicks(y2l[0], y2l[1], y2_axis.log))
		{
			const int r = static_cast<int>(std::lround(map(xl[0], t, true).y));
			const int x = area.x + area.width - 1;
			cv::line(img, {x, r}, {x + 4, r}, kAxisColour, 1);
			const cv::Size sz = cv::getTextSize(tickLabel(t), kFont, kTickFontScale, 1, &base);
			cv::putText(img, tickLabel(t), {x + 6, r + sz.height / 2}, kFont, kTickFontScale, kTextColour, 1,
						cv::LINE_AA);
		}
}

void LinePlot::drawSeries(cv::Mat& img, const Mapping& map) const
{
	const cv::Rect area = map.area;
	// a long series is reduced to the min/max envelope of each pixel column
	for (const auto& s : series_)
	{
		const bool ylog = s.right_axis ? y2_axis.log : y_axis.log;
		std::vector<cv::Point2d> run;
		double dash_phase = 0;
		auto flush = [&]() {
			for (std::size_t i = 1; i < run.size(); i++) drawSegment(img, area, run[i - 1], run[i], s, dash_phase);
			if (run.size() == 1)
			{
				cv::Point p = clampPoint(run[0]), q = p;
				if (cv::clipLine(area, p, q)) cv::line(img, p, q, s.colour, s.thickness_px, cv::LINE_8);
			}
			run.clear();
		};
		const bool reduce = s.x.size() > static_cast<std::size_t>(4 * area.width);
		long col = -1;
		double cmin = 0, cmax = 0, clast = 0;
		for (std::size_t k = 0; k < s.x.size(); k++)
		{
			const double x = s.x[k], y = s.y[k];
			if (!std::isfinite(x) || !std::isfinite(y) || (x_axis.log && x <= 0) || (ylog && y <= 0))
			{
				if (reduce && col >= 0)
				{
					run.push_back({static_cast<double>(col), cmin});
					run.push_back({static_cast<double>(col), cmax});
					run.push_back({static_cast<double>(col), clast});
					col = -1;
				}
				flush();
				continue;
			}
			const cv::Point2d p = map(x, y, s.right_axis);
			if (!reduce)
			{
				run.push_back(p);
				continue;
			}
			const long c = std::lround(std::clamp(p.x, -1e6, 1e6));
			if (c != col)
			{
				if (col >= 0)
				{
					run.push_back({static_cast<double>(col), cmin});
					run.push_back({static_cast<double>(col), cmax});
					run.push_back({static_cast<double>(col), clast});
				}
				run.push_back(p);
				col = c;
				cmin = cmax = p.y;
			}
			cmin = std::min(cmin, p.y);
			cmax = std::max(cmax, p.y);
			clast = p.y;
		}
		if (reduce && col >= 0)
		{
			run.push_back({static_cast<double>(col), cmin});
			run.push_back({static_cast<double>(col), cmax});
			run.push_back({static_cast<double>(col), clast});
		}
		flush();
	}
}

void LinePlot::drawFrameAndLabels(cv::Mat& img, const Mapping& map, const cv::Rect& panel) const
{
	const cv::Rect area = map.area;
	cv::rectangle(img, area, kAxisColour, 1);
	putTextCentred(img, x_axis.label, {area.x + area.width / 2, area.y + area.height + 32}, kLabelFontScale);
	putTextRotated(img, y_axis.label, {panel.x + 12, area.y + area.height / 2}, kLabelFontScale);
	if (hasRightAxis())
		putTextRotated(img, y2_axis.label, {area.x + area.width + kMarginRightY2 - 14, area.y + area.height / 2},
					   kLabelFontScale);
	if (!title.empty()) putTextCentred(img, title, {area.x + area.width / 2, panel.y + kMarginTop / 2}, kTitleFontScale);
}

void LinePlot::drawLegend(cv::Mat& img, const Mapping& map) const
{
	const cv::Rect area = map.area;
	int base = 0;
	// top right of the data area: series and labelled shades
	std::vector<std::pair<std::string, std::pair<cv::Scalar, int>>> entries;  // text, (colour, kind)
	for (const auto& s : series_)
		if (!s.label.empty()) entries.push_back({s.label + (s.right_axis ? " (right)" : ""), {s.colour, s.dashed ? 1 : 0}});
	for (const auto& sh : shades_)
		if (!sh.label.empty()) entries.push_back({sh.label, {sh.colour, 2}});
	if (entries.empty()) return;
	int w = 0;
	for (const auto& e : entries) w = std::max(w, cv::getTextSize(e.first, kFont, kTickFontScale, 1, &base).width);
	const int row_h = 15, box_w = w + 38, box_h = static_cast<int>(entries.size()) * row_h + 8;
	const cv::Rect box(area.x + area.width - box_w - 6, area.y + 6, box_w, box_h);
	if ((box & area) != box) return;  // panel too small for a legend
	cv::rectangle(img, box, cv::Scalar(255, 255, 255), cv::FILLED);
	cv::rectangle(img, box, kGridColour.mul(cv::Scalar(0.7, 0.7, 0.7)), 1);
	for (std::size_t i = 0; i < entries.size(); i++)
	{
		const int y = box.y + 4 + static_cast<int>(i) * row_h + row_h / 2;
		const auto& [colour, kind] = entries[i].second;
		if (kind == 2)  // the shade's blended colour, as in the plot
			cv::rectangle(img, cv::Rect(box.x + 6, y - 5, 22, 10), colour * 0.25 + cv::Scalar(255, 255, 255) * 0.75,
						  cv::FILLED);
		else if (kind == 1)
		{
			cv::line(img, {box.x + 6, y}, {box.x + 13, y}, colour, 2);
			cv::line(img, {box.x + 19, y}, {box.x + 27, y}, colour, 2);
		}
		else
			cv::line(img, {box.x + 6, y}, {box.x + 28, y}, colour, 2);
		cv::putText(img, entries[i].first, {box.x + 33, y + 4}, kFont, kTickFontScale, kTextColour, 1, cv::LINE_AA);
	}
}

void LinePlot::draw(cv::Mat& img, const cv::Rect& panel) const
{
	const Mapping map = mapping(panel);
	drawShades(img, map);
	drawGridAndTicks(img, map);
	drawSeries(img, map);
	drawFrameAndLabels(img, map, panel);
	drawLegend(img, map);
}

}  // namespace mrpt_fog
