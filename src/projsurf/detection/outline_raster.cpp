#include "projsurf/detection/outline_raster.hpp"

#include <algorithm>
#include <cmath>

#include "projsurf/types/clamp_to_int.hpp"

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

RasterFrame makeRasterFrame(const Eigen::Vector2d &lo, const Eigen::Vector2d &hi, double cell, int max_cells) {
    RasterFrame f;
    f.cell = cell;
    f.top_left = {lo.x(), hi.y()};
    // Clamped before converting: a far point (or NaN) must not overflow the int.
    f.cols = clampToInt(std::ceil((hi.x() - lo.x()) / cell), 1, max_cells);
    f.rows = clampToInt(std::ceil((hi.y() - lo.y()) / cell), 1, max_cells);
    return f;
}

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

cv::Mat footprintCells(const RasterFrame &raster, const std::array<Eigen::Vector2d, 4> &footprint_uv) {
    cv::Mat cells = cv::Mat::zeros(raster.rows, raster.cols, CV_8UC1);
    // Whole cells inside: the footprint's edges moved in by half a cell diagonal.
    fillPolygon(cells, raster, insetConvexPolygon({footprint_uv.begin(), footprint_uv.end()}, 0.7072 * raster.cell),
                255);
    return cells;
}

}  // namespace projsurf
