#include "projsurf/detection/raster_frame.hpp"

#include <algorithm>
#include <cmath>

#include "projsurf/types/clamp_to_int.hpp"

namespace projsurf {

RasterFrame makeRasterFrame(const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double cell, int max_cells) {
    RasterFrame f;
    f.cell = cell;
    f.top_left = {lo.x(), hi.y()};
    // Clamped before converting: a far point (or NaN) must not overflow the int.
    f.cols = clampToInt(std::ceil((hi.x() - lo.x()) / cell), 1, max_cells);
    f.rows = clampToInt(std::ceil((hi.y() - lo.y()) / cell), 1, max_cells);
    return f;
}

void fillPolygon(cv::Mat &grid, const RasterFrame &frame, const std::vector<Eigen::Vector2d> &polygon, uchar value) {
    if (polygon.size() < 3) return;
    std::vector<Eigen::Vector2d> cells;
    for (const auto &p : polygon) cells.push_back(frame.toCell(p));
    std::vector<double> xs;
    for (int r = 0; r < grid.rows; ++r) {
        const double y = r + 0.5;
        xs.clear();
        for (std::size_t i = 0; i < cells.size(); ++i) {
            const Eigen::Vector2d &a = cells[i], &b = cells[(i + 1) % cells.size()];
            if ((a.y() <= y) == (b.y() <= y)) continue;
            xs.push_back(a.x() + (y - a.y()) / (b.y() - a.y()) * (b.x() - a.x()));
        }
        std::sort(xs.begin(), xs.end());
        uchar *row = grid.ptr<uchar>(r);
        for (std::size_t i = 0; i + 1 < xs.size(); i += 2) {
            const int c0 = clampToInt(std::ceil(xs[i] - 0.5), 0, grid.cols);
            const int c1 = clampToInt(std::floor(xs[i + 1] - 0.5), -1, grid.cols - 1);
            for (int c = c0; c <= c1; ++c) row[c] = value;
        }
    }
}

std::vector<Eigen::Vector2d> insetConvexPolygon(const std::vector<Eigen::Vector2d> &poly, double distance) {
    const std::size_t n = poly.size();
    if (n < 3) return poly;
    double area2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        const auto &a = poly[i], &b = poly[(i + 1) % n];
        area2 += a.x() * b.y() - b.x() * a.y();
    }
    const double side = area2 > 0 ? 1.0 : -1.0;  // inward normal of edge a->b is side * (-dy, dx)
    std::vector<Eigen::Vector2d> out;
    for (std::size_t i = 0; i < n; ++i) {
        // Corner i is where the moved edges (i-1 -> i) and (i -> i+1) meet.
        const auto &p0 = poly[(i + n - 1) % n], &p1 = poly[i], &p2 = poly[(i + 1) % n];
        const Eigen::Vector2d d1 = (p1 - p0).normalized(), d2 = (p2 - p1).normalized();
        const Eigen::Vector2d n1 = side * Eigen::Vector2d(-d1.y(), d1.x()),
                              n2 = side * Eigen::Vector2d(-d2.y(), d2.x());
        const Eigen::Vector2d a = p0 + distance * n1, b = p1 + distance * n2;
        const double det = d1.x() * (-d2.y()) - d1.y() * (-d2.x());
        if (std::abs(det) < 1e-12) {
            out.push_back(p1 + distance * n1);
            continue;
        }
        const Eigen::Vector2d rhs = b - a;
        const double t = (rhs.x() * (-d2.y()) - rhs.y() * (-d2.x())) / det;
        out.push_back(a + t * d1);
    }
    return out;
}

cv::Mat footprintCells(const RasterFrame &raster, const std::array<Eigen::Vector2d, 4> &footprint_uv) {
    cv::Mat cells = cv::Mat::zeros(raster.rows, raster.cols, CV_8UC1);
    // Whole cells inside: the footprint's edges moved in by half a cell diagonal.
    fillPolygon(cells, raster, insetConvexPolygon({footprint_uv.begin(), footprint_uv.end()}, 0.7072 * raster.cell),
                255);
    return cells;
}

}  // namespace projsurf
