/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#pragma once

/** \file PlotCanvas.h
 * A PNG figure: one or more LinePlot panels stacked vertically (e.g. bias on top, temperature
 * below, sharing the time axis), rendered with OpenCV and written atomically (encoded in memory
 * with cv::imencode, written to a temporary file and renamed, see common/AtomicFile.h).
 *
 *   PlotCanvas fig(1000, 700);
 *   LinePlot& p = fig.addPanel(2.0);
 *   p.x_axis.label = "time [s]"; p.y_axis.label = "bias [deg/h]";
 *   p.addSeries({"raw", t, rate});
 *   fig.save("bias.png");
 */

#include <mrpt_fog/plot/LinePlot.h>

#include <deque>
#include <string>

namespace mrpt_fog
{
class PlotCanvas
{
   public:
	/** Figure size in pixels; throws std::invalid_argument below 200 x 150. */
	PlotCanvas(int width_px, int height_px);

	/** Adds a panel below the previous ones; heights are shared in proportion to weight (> 0). */
	LinePlot& addPanel(double height_weight = 1.0);
	/** The same, with its axis labels (units in them, e.g. "time [s]") and title set. */
	LinePlot& addPanel(double height_weight, const std::string& x_label, const std::string& y_label,
					   const std::string& title = "");
	LinePlot& panel(std::size_t i) { return panels_.at(i); }
	std::size_t panelCount() const { return panels_.size(); }

	/** Rectangle of panel i in the image. */
	cv::Rect panelRect(std::size_t i) const;
	int width() const { return width_; }
	int height() const { return height_; }

	/** The figure as a CV_8UC3 image (white background). */
	cv::Mat render() const;
	/** Renders and writes a PNG atomically; throws std::runtime_error naming the path on failure
	 * (directory missing, not writable, encoding failed). */
	void save(const std::string& path_png) const;

   private:
	int width_, height_;
	std::deque<LinePlot> panels_;  // deque: references returned by addPanel stay valid
	std::vector<double> weights_;
};

}  // namespace mrpt_fog
