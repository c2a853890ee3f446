#include "projsurf/types/point_grid.hpp"

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
    const int src_step = grid.organized ? grid.step : 1;
    for (int r = 0; r < grid.rows; ++r) {
        const Point *src = cloud.points.data() + grid.cloudIndex(r, 0);
        const std::size_t k = static_cast<std::size_t>(r) * grid.cols;
        float *x = grid.x.data() + k, *y = grid.y.data() + k, *z = grid.z.data() + k;
        for (int c = 0; c < grid.cols; ++c) {
            const Point &p = src[c * src_step];
            // v - v is 0 for a finite v and NaN for an infinite or NaN one.
            const bool ok = (p.x() - p.x() == 0.0f) & (p.y() - p.y() == 0.0f) & (p.z() - p.z() == 0.0f);
            x[c] = ok ? p.x() : nan;
            y[c] = ok ? p.y() : nan;
            z[c] = ok ? p.z() : nan;
        }
    }
}

}  // namespace projsurf
