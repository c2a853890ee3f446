#include "projsurf/core/point_grid.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace projsurf {

cv::Rect PointGrid::gridBox(const cv::Rect &pixels) const {
    const cv::Rect all(0, 0, cols, rows);
    if (!organized || pixels.area() <= 0) return all;
    // Grid column c sits on pixel c * step: the first at or after x, the last before x + width.
    auto first = [&](int p) { return (std::max(p, 0) + step - 1) / step; };
    const int c0 = first(pixels.x), c1 = first(pixels.x + pixels.width);
    const int r0 = first(pixels.y), r1 = first(pixels.y + pixels.height);
    return cv::Rect(c0, r0, c1 - c0, r1 - r0) & all;
}

void fillPointGrid(const Cloud &cloud, int step, PointGrid &grid) {
    grid.organized = cloud.organized();
    grid.step = grid.organized ? std::max(1, step) : 1;
    grid.cloud_width = cloud.width;
    grid.cols = grid.organized ? (cloud.width + grid.step - 1) / grid.step : static_cast<int>(cloud.points.size());
    grid.rows = grid.organized ? (cloud.height + grid.step - 1) / grid.step : 1;
    const std::size_t n = static_cast<std::size_t>(grid.cols) * grid.rows;
    grid.x.resize(n);
    grid.y.resize(n);
    grid.z.resize(n);
    constexpr float nan = std::numeric_limits<float>::quiet_NaN();
    std::size_t k = 0;
    for (int r = 0; r < grid.rows; ++r)
        for (int c = 0; c < grid.cols; ++c, ++k) {
            const Point &p = cloud.points[grid.cloudIndex(r, c)];
            const bool ok = isFinite(p);
            grid.x[k] = ok ? p.x() : nan;
            grid.y[k] = ok ? p.y() : nan;
            grid.z[k] = ok ? p.z() : nan;
        }
}

}  // namespace projsurf
