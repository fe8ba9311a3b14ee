/* mrpt_fog: temperature-error compensation of fiber-optic gyroscopes for MRPT. */
#include <mrpt_fog/common/AtomicFile.h>
#include <mrpt_fog/plot/PlotCanvas.h>

#include <opencv2/imgcodecs.hpp>

#include <cerrno>
#include <cstring>
#include <fstream>
#include <numeric>
#include <stdexcept>

namespace mrpt_fog
{
PlotCanvas::PlotCanvas(int width_px, int height_px) : width_(width_px), height_(height_px)
{
	if (width_px < 200 || height_px < 150)
		throw std::invalid_argument("plot size " + std::to_string(width_px) + " x " + std::to_string(height_px) +
									" px is too small (at least 200 x 150)");
}

LinePlot& PlotCanvas::addPanel(double height_weight)
{
	if (!(height_weight > 0)) throw std::invalid_argument("plot panel height weight must be > 0");
	panels_.emplace_back();
	weights_.push_back(height_weight);
	return panels_.back();
}

LinePlot& PlotCanvas::addPanel(double height_weight, const std::string& x_label, const std::string& y_label,
							   const std::string& title)
{
	LinePlot& p = addPanel(height_weight);
	p.x_axis.label = x_label;
	p.y_axis.label = y_label;
	p.title = title;
	return p;
}

cv::Rect PlotCanvas::panelRect(std::size_t i) const
{
	if (i >= panels_.size()) throw std::out_of_range("plot panel index out of range");
	const double total = std::accumulate(weights_.begin(), weights_.end(), 0.0);
	const double before = std::accumulate(weights_.begin(), weights_.begin() + static_cast<std::ptrdiff_t>(i), 0.0);
	const int y0 = static_cast<int>(std::lround(height_ * before / total));
	const int y1 = static_cast<int>(std::lround(height_ * (before + weights_[i]) / total));
	return {0, y0, width_, y1 - y0};
}

cv::Mat PlotCanvas::render() const
{
	cv::Mat img(height_, width_, CV_8UC3, cv::Scalar(255, 255, 255));
	for (std::size_t i = 0; i < panels_.size(); i++) panels_[i].draw(img, panelRect(i));
	return img;
}

void PlotCanvas::save(const std::string& path_png) const
{
	const cv::Mat img = render();
	std::vector<uchar> png;
	if (!cv::imencode(".png", img, png)) throw std::runtime_error("cannot encode PNG for '" + path_png + "'");
	writeFileAtomically(path_png, [&](const std::string& tmp) {
		std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
		if (!f) throw std::runtime_error("cannot write '" + path_png + "': " + std::strerror(errno));
		f.write(reinterpret_cast<const char*>(png.data()), static_cast<std::streamsize>(png.size()));
		f.close();
		if (!f) throw std::runtime_error("cannot write '" + path_png + "': write error (disk full?)");
	});
}

}  // namespace mrpt_fog
