#pragma once
// Simple, labelled charts drawn with OpenCV (no plotting library): line charts with optional
// error bars, dashed reference series and horizontal marker lines; grouped bar charts; and a
// tiler that puts panels on one page with a title.
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

namespace projsurf::eval {

struct Series {
    std::string label;
    cv::Scalar color{0, 0, 0};  ///< BGR
    std::vector<double> x;      ///< line charts only; bar charts use the category index
    std::vector<double> y;      ///< NaN = no value (a gap)
    std::vector<double> err;    ///< optional +-error per point (same size as y)
    bool dashed = false;        ///< e.g. the paper's published values
    int marker = 0;             ///< 0 circle, 1 square, 2 triangle, 3 diamond
};

struct LineChart {
    std::string title, x_label, y_label;
    std::vector<Series> series;
    double y_min = 0.0, y_max = 0.0;  ///< y_max <= y_min: from the data
    bool log_y = false;               ///< log10 axis (values <= 0 are clamped to y_min)
    std::vector<double> x_ticks;      ///< empty: the union of the series' x
    struct HLine {
        double value = 0.0;
        std::string label;
        bool label_left = false;   ///< label at the left end (else the right end)
        bool label_below = false;  ///< label under the line (else above)
    };
    std::vector<HLine> h_lines;  ///< labelled horizontal reference lines (dashed grey)
    cv::Size size{640, 440};
};
cv::Mat drawLineChart(const LineChart &chart);

struct BarChart {
    std::string title, y_label;
    std::vector<std::string> categories;  ///< groups along x
    std::vector<Series> series;           ///< one bar per series in each group (y[i] for category i)
    double y_max = 0.0;                   ///< <= 0: from the data
    cv::Size size{900, 440};
};
cv::Mat drawBarChart(const BarChart &chart);

/// Panels (any sizes, BGR) in a grid of `cols` columns on white, with a title line on top.
cv::Mat tilePanels(const std::vector<cv::Mat> &panels, int cols, const std::string &title);

/// A label strip above an image (white text on dark grey), for captions in composites.
cv::Mat withCaption(const cv::Mat &image, const std::string &caption, double font_scale = 0.8);

}  // namespace projsurf::eval
