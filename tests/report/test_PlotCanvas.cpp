/* Tests of mrpt_fog::PlotCanvas / LinePlot: the axis mapping in closed form (a drawn series lands
 * on the predicted pixel), log and second axes, shading, stacked panels, atomic PNG output. */
#include <gtest/gtest.h>
#include <mrpt_fog/plot/PlotCanvas.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <opencv2/imgcodecs.hpp>

using namespace mrpt_fog;

namespace
{
bool pixelIs(const cv::Mat& img, int row, int col, const cv::Scalar& bgr)
{
	const cv::Vec3b p = img.at<cv::Vec3b>(row, col);
	return p[0] == bgr[0] && p[1] == bgr[1] && p[2] == bgr[2];
}

// Closed form of the documented mapping, written independently of LinePlot::toPixel.
cv::Point expectedPixel(const cv::Rect& panel, bool y2, double fx, double fy)
{
	const int left = panel.x + LinePlot::kMarginLeft, top = panel.y + LinePlot::kMarginTop;
	const int w = panel.width - LinePlot::kMarginLeft - (y2 ? LinePlot::kMarginRightY2 : LinePlot::kMarginRight);
	const int h = panel.height - LinePlot::kMarginTop - LinePlot::kMarginBottom;
	return {static_cast<int>(std::lround(left + fx * (w - 1))),
			static_cast<int>(std::lround(top + (h - 1) - fy * (h - 1)))};
}
}  // namespace

TEST(PlotCanvas, LinearSeriesLandsOnPredictedPixel)
{
	PlotCanvas fig(640, 480);
	LinePlot& p = fig.addPanel();
	p.x_axis = {"time [s]", false, 0.0, 10.0};
	p.y_axis = {"rate [deg/h]", false, 0.0, 1.0};
	PlotSeries s;
	s.x = {0.0, 10.0};
	s.y = {0.5, 0.5};
	s.colour = plot_colour::kRed;
	p.addSeries(s);
	const cv::Mat img = fig.render();
	ASSERT_EQ(img.cols, 640);
	ASSERT_EQ(img.rows, 480);
	const cv::Point e = expectedPixel(fig.panelRect(0), false, 0.25, 0.5);
	EXPECT_TRUE(pixelIs(img, e.y, e.x, plot_colour::kRed)) << "at " << e;
	// One row above and below is not the series (the line is 1 px thick).
	EXPECT_FALSE(pixelIs(img, e.y - 2, e.x, plot_colour::kRed));
	EXPECT_FALSE(pixelIs(img, e.y + 2, e.x, plot_colour::kRed));
	const cv::Point2d q = p.toPixel(fig.panelRect(0), 2.5, 0.5);
	EXPECT_NEAR(q.x, e.x, 0.5);
	EXPECT_NEAR(q.y, e.y, 0.5);
}

TEST(PlotCanvas, LogLogAndRightAxisMapping)
{
	PlotCanvas fig(800, 600);
	LinePlot& p = fig.addPanel();
	p.x_axis = {"tau [s]", true, 1.0, 1000.0};
	p.y_axis = {"ADEV [deg/h]", true, 1e-3, 1.0};
	p.y2_axis = {"temperature [degC]", false, -40.0, 60.0};
	PlotSeries a;
	a.x = {1.0, 1000.0};
	a.y = {1.0, 1e-3};  // slope -1: passes through (10, 0.1), i.e. fx = 1/3, fy = 2/3
	a.colour = plot_colour::kGreen;
	p.addSeries(a);
	PlotSeries b;
	b.x = {1.0, 1000.0};
	b.y = {35.0, 35.0};  // right axis: fy = 0.75
	b.colour = plot_colour::kPurple;
	b.right_axis = true;
	p.addSeries(b);
	const cv::Mat img = fig.render();
	const cv::Point e1 = expectedPixel(fig.panelRect(0), true, 1.0 / 3.0, 2.0 / 3.0);
	const cv::Point e2 = expectedPixel(fig.panelRect(0), true, 0.5, 0.75);
	// A diagonal drawn with 8-connected Bresenham may pass one pixel off the real line.
	bool found = false;
	for (int dr = -1; dr <= 1; dr++)
		for (int dc = -1; dc <= 1; dc++) found = found || pixelIs(img, e1.y + dr, e1.x + dc, plot_colour::kGreen);
	EXPECT_TRUE(found) << "near " << e1;
	EXPECT_TRUE(pixelIs(img, e2.y, e2.x, plot_colour::kPurple)) << "at " << e2;
}

TEST(PlotCanvas, ShadeIsBlendedAndStackedPanelsShareHeight)
{
	PlotCanvas fig(600, 600);
	LinePlot& top = fig.addPanel(2.0);
	LinePlot& bottom = fig.addPanel(1.0);
	top.x_axis = {"time [s]", false, 0.0, 100.0};
	top.y_axis = {"bias [deg/h]", false, 0.0, 1.0};
	top.addShade(20.0, 40.0, cv::Scalar(0, 0, 255), "ramp");
	bottom.x_axis = {"time [s]", false, 0.0, 100.0};
	bottom.y_axis = {"T [degC]", false, 0.0, 1.0};
	EXPECT_EQ(fig.panelRect(0).height, 400);
	EXPECT_EQ(fig.panelRect(1).y, 400);
	EXPECT_EQ(fig.panelRect(1).height, 200);
	const cv::Mat img = fig.render();
	// Inside the shade, between grid lines: white * 0.75 + red * 0.25.
	const cv::Point e = expectedPixel(fig.panelRect(0), false, 0.33, 0.53);
	const cv::Vec3b px = img.at<cv::Vec3b>(e.y, e.x);
	EXPECT_NEAR(px[0], 191, 1);
	EXPECT_NEAR(px[1], 191, 1);
	EXPECT_NEAR(px[2], 255, 1);
	// Outside the shade: white.
	const cv::Point o = expectedPixel(fig.panelRect(0), false, 0.53, 0.53);
	EXPECT_TRUE(pixelIs(img, o.y, o.x, cv::Scalar(255, 255, 255)));
}

TEST(PlotCanvas, SaveWritesPngAtomically)
{
	const std::string dir = std::string(FOG_BINARY_DIR) + "/test_plot_canvas";
	std::filesystem::create_directories(dir);
	const std::string path = dir + "/fig.png";
	std::remove(path.c_str());
	PlotCanvas fig(500, 300);
	LinePlot& p = fig.addPanel();
	std::vector<double> x, y;
	for (int k = 0; k < 100000; k++)  // long series: reduced to a per-column envelope
	{
		x.push_back(k * 0.1);
		y.push_back(std::sin(k * 0.001) + 0.1 * std::sin(k * 1.7));
	}
	p.addSeries({"raw", x, y});
	p.title = "test";
	fig.save(path);
	const cv::Mat back = cv::imread(path, cv::IMREAD_COLOR);
	ASSERT_FALSE(back.empty());
	EXPECT_EQ(back.cols, 500);
	EXPECT_EQ(back.rows, 300);
	EXPECT_EQ(cv::norm(back, fig.render(), cv::NORM_INF), 0.0);
	EXPECT_FALSE(std::filesystem::exists(path + ".tmp-" + std::to_string(::getpid())));
	// A missing directory: an error naming the file, nothing written.
	const std::string bad = dir + "/no/such/dir/fig.png";
	try
	{
		fig.save(bad);
		FAIL() << "expected an exception";
	}
	catch (const std::runtime_error& e)
	{
		EXPECT_NE(std::string(e.what()).find(bad), std::string::npos) << e.what();
	}
	EXPECT_FALSE(std::filesystem::exists(bad));
}

TEST(PlotCanvas, TicksAndBadInput)
{
	EXPECT_EQ(niceTicks(0, 10, false), (std::vector<double>{0, 2, 4, 6, 8, 10}));
	EXPECT_EQ(niceTicks(1, 100, true), (std::vector<double>{1, 2, 5, 10, 20, 50, 100}));  // < 3 decades: 1-2-5
	EXPECT_EQ(niceTicks(1, 1000, true), (std::vector<double>{1, 10, 100, 1000}));
	EXPECT_EQ(niceTicks(1e-3, 1e5, true), (std::vector<double>{1e-3, 1e-1, 10, 1e3, 1e5}));  // every 2nd decade
	EXPECT_THROW(PlotCanvas(10, 10), std::invalid_argument);
	PlotCanvas fig(400, 300);
	LinePlot& p = fig.addPanel();
	EXPECT_THROW(p.addSeries({"bad", {1, 2}, {1}}), std::invalid_argument);
	p.x_axis = {"x", true, -1.0, 10.0};  // log axis with min <= 0
	p.addSeries({"ok", {1, 2}, {1, 2}});
	EXPECT_THROW(fig.render(), std::invalid_argument);
}
