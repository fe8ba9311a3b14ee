/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file LinePlot.h
 * One panel of a PNG figure drawn with OpenCV: several x-y series with colours and a legend,
 * axes with ticks and labels (units go in the label, e.g. "time [s]"), optional log-log axes,
 * an optional second y axis on the right, and shaded x-intervals (e.g. the segments of a test
 * profile). Panels are stacked into a figure by PlotCanvas (plot/PlotCanvas.h).
 *
 * Axis mapping (used by the tests, and documented so that a pixel can be predicted): the data
 * area of a panel drawn into `panel` is dataArea(panel) = panel minus the fixed margins
 * kMarginLeft/Right/Top/Bottom (pixels); a value x maps to column
 *   left + (u(x) - u(xmin)) / (u(xmax) - u(xmin)) * (width - 1),   u = identity or log10,
 * and y to row  bottom - (u(y) - u(ymin)) / (u(ymax) - u(ymin)) * (height - 1), rounded.
 * Axis limits are automatic (nice round limits around the finite data; whole decades on a log
 * axis) unless set. NaN points break a line; non-positive values are skipped on a log axis.
 */

#include <opencv2/core.hpp>

#include <string>
#include <vector>

namespace mrpt_fog
{
/** Colours (BGR) for series, chosen to be distinguishable. */
namespace plot_colour
{
const cv::Scalar kBlue(180, 119, 31), kOrange(14, 127, 255), kGreen(44, 160, 44), kRed(40, 39, 214),
	kPurple(189, 103, 148), kBrown(75, 86, 140), kGrey(127, 127, 127), kBlack(0, 0, 0);
/** The k-th default series colour (cycles). */
cv::Scalar cycle(std::size_t k);
}  // namespace plot_colour

struct PlotSeries
{
	std::string label;  //!< legend text ("" = not in the legend)
	std::vector<double> x, y;  //!< same size; NaN breaks the line
	cv::Scalar colour = plot_colour::kBlue;
	int thickness_px = 1;
	bool right_axis = false;  //!< plotted against the second (right) y axis
	bool dashed = false;  //!< dashed line (e.g. fitted or reference lines)
};

struct PlotAxis
{
	std::string label;  //!< with units, e.g. "rate [deg/h]"
	bool log = false;  //!< log10 scale
	double min = NAN, max = NAN;  //!< NaN = automatic
};

class LinePlot
{
   public:
	static constexpr int kMarginLeft = 78, kMarginRight = 20, kMarginTop = 28, kMarginBottom = 44;
	/** Extra right margin when a second y axis is used. */
	static constexpr int kMarginRightY2 = 70;

	std::string title;
	PlotAxis x_axis, y_axis;
	PlotAxis y2_axis;  //!< used only when some series has right_axis = true

	/** Adds a series; throws std::invalid_argument when x and y differ in size. */
	PlotSeries& addSeries(PlotSeries s);
	/** Shades [x0, x1] over the full height (alpha-blended, drawn below the series). */
	void addShade(double x0, double x1, const cv::Scalar& colour, const std::string& label = "");

	const std::vector<PlotSeries>& series() const { return series_; }
	bool hasRightAxis() const;

	/** The data rectangle inside a panel rectangle (see the file comment). */
	cv::Rect dataArea(const cv::Rect& panel) const;
	/** Resolved axis limits [min, max] (automatic ones computed from the data). */
	cv::Vec2d xLimits() const;
	cv::Vec2d yLimits(bool right_axis = false) const;
	/** Pixel of a data point when the panel is drawn into `panel` (unrounded). */
	cv::Point2d toPixel(const cv::Rect& panel, double x, double y, bool right_axis = false) const;

	/** Draws the panel into img inside `panel` (img must be CV_8UC3). */
	void draw(cv::Mat& img, const cv::Rect& panel) const;

   private:
	/** Everything the axis mapping needs, resolved once per draw. */
	struct Mapping
	{
		cv::Rect area;
		cv::Vec2d x, y, y2;
		bool xlog, ylog, y2log;
		cv::Point2d operator()(double x, double y, bool right_axis = false) const;
	};
	Mapping mapping(const cv::Rect& panel) const;
	// The stages of draw(), in the order it runs them.
	void drawShades(cv::Mat& img, const Mapping& map) const;
	void drawGridAndTicks(cv::Mat& img, const Mapping& map) const;
	void drawSeries(cv::Mat& img, const Mapping& map) const;
	void drawFrameAndLabels(cv::Mat& img, const Mapping& map, const cv::Rect& panel) const;
	void drawLegend(cv::Mat& img, const Mapping& map) const;

	struct Shade
	{
		double x0, x1;
		cv::Scalar colour;
		std::string label;
	};
	std::vector<PlotSeries> series_;
	std::vector<Shade> shades_;
};

/** "Nice" tick positions (1, 2, 5 x 10^k steps) covering [lo, hi] with about `target` ticks;
 * on a log axis the decades (and 2, 5 multiples when fewer than 3 decades). */
std::vector<double> niceTicks(double lo, double hi, bool log, int target = 6);
/** Short tick text: %g with up to 6 significant digits. */
std::string tickLabel(double v);

}  // namespace mrpt_fog
