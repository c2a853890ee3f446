#include "projsurf/detection/paper/outline_raster.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf {
namespace {

/// Cells further than this from the grid's origin are clipped before drawing.
constexpr double kFarCell = 1 << 20;

/// Clips the segment a-b to the box [lo, hi] (Liang-Barsky); false when nothing is inside
/// or an end is not finite.
bool clipToBox(Eigen::Vector2d &a, Eigen::Vector2d &b, const Eigen::Vector2d &lo, const Eigen::Vector2d &hi) {
    if (!a.allFinite() || !b.allFinite()) return false;
    double t0 = 0.0, t1 = 1.0;
    const Eigen::Vector2d d = b - a;
    for (int k = 0; k < 2; ++k) {
        const double p[2] = {-d[k], d[k]}, q[2] = {a[k] - lo[k], hi[k] - a[k]};
        for (int s = 0; s < 2; ++s) {
            if (p[s] == 0.0) {
                if (q[s] < 0.0) return false;
                continue;
            }
            const double r = q[s] / p[s];
            if (p[s] < 0.0)
                t0 = std::max(t0, r);
            else
                t1 = std::min(t1, r);
        }
    }
    if (t0 > t1) return false;
    const Eigen::Vector2d a0 = a;
    a = a0 + t0 * d;
    b = a0 + t1 * d;
    return true;
}

}  // namespace

void drawLine(cv::Mat &grid, const Eigen::Vector2i &a, const Eigen::Vector2i &b, uchar value) {
    int x0 = a.x(), y0 = a.y();
    const int x1 = b.x(), y1 = b.y();
    const int dx = std::abs(x1 - x0), dy = -std::abs(y1 - y0);
    const int sx = x0 < x1 ? 1 : -1, sy = y0 < y1 ? 1 : -1;
    int err = dx + dy;
    while (true) {
        if (x0 >= 0 && y0 >= 0 && x0 < grid.cols && y0 < grid.rows) grid.at<uchar>(y0, x0) = value;
        if (x0 == x1 && y0 == y1) break;
        const int e2 = 2 * err;
        if (e2 >= dy) {
            err += dy;
            x0 += sx;
        }
        if (e2 <= dx) {
            err += dx;
            y0 += sy;
        }
    }
}

void fillOutsideRows(cv::Mat &grid, uchar value) {
    for (int r = 0; r < grid.rows; ++r) {
        uchar *row = grid.ptr<uchar>(r);
        int first = 0;
        while (first < grid.cols && row[first] == 0) ++first;
        if (first == grid.cols) {
            std::fill(row, row + grid.cols, value);
            continue;
        }
        std::fill(row, row + first, value);
        int last = grid.cols - 1;
        while (last >= 0 && row[last] == 0) --last;
        std::fill(row + last + 1, row + grid.cols, value);
    }
}

cv::Mat outlineMask(const RasterFrame &frame, const std::vector<Segment2> &edges) {
    cv::Mat grid = cv::Mat::zeros(frame.rows, frame.cols, CV_8UC1);
    auto cellOf = [&](const Eigen::Vector2d &c) {
        return Eigen::Vector2i(static_cast<int>(std::floor(c.x())), static_cast<int>(std::floor(c.y())));
    };
    for (const auto &e : edges) {
        Eigen::Vector2d a = frame.toCell(e[0]), b = frame.toCell(e[1]);
        // Edges far outside the grid (far points) are clipped to it first, so that the cell
        // numbers fit an int and the line walk stays short; nearer ones are drawn as they are.
        if (!(a.cwiseAbs().maxCoeff() <= kFarCell && b.cwiseAbs().maxCoeff() <= kFarCell) &&
            !clipToBox(a, b, Eigen::Vector2d(-1.0, -1.0), Eigen::Vector2d(frame.cols + 1.0, frame.rows + 1.0)))
            continue;
        drawLine(grid, cellOf(a), cellOf(b), 1);
    }
    fillOutsideRows(grid, 1);
    return grid;
}

}  // namespace projsurf
