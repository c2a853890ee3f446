#pragma once
// A wall's shape (detection/wall_height.hpp) in the raster's (column, row) coordinates,
// in float: what the per-point passes over a raster evaluate at a point's foot (column =
// (u - top_left.x) / cell, row = (top_left.y - v) / cell, fractional): the quadratic as a
// polynomial, the relief looked up at the centre of the cell (it changes by far less than a
// millimetre over a cell).
#include <algorithm>
#include <vector>

#include "projsurf/detection/raster_frame.hpp"
#include "projsurf/detection/wall_height.hpp"

namespace projsurf {

struct RasterShape {
    float k[6];                 ///< 1, col, row, col^2, col row, row^2
    std::vector<float> relief;  ///< rows x cols, the relief at each cell's centre (empty: none)
    float last_col = 0.0f, last_row = 0.0f;
    int cols = 0;

    RasterShape(const WallShape &s, const RasterFrame &raster) {
        // u = a + e col, v = b - e row about the shape's centre.
        const double a = raster.top_left.x() - s.centre.x(), b = raster.top_left.y() - s.centre.y(), e = raster.cell;
        const auto &c = s.c;
        const double k0 = c[0] + c[1] * a + c[2] * b + c[3] * a * a + c[4] * a * b + c[5] * b * b;
        const double k1 = (c[1] + 2.0 * c[3] * a + c[4] * b) * e, k2 = -(c[2] + c[4] * a + 2.0 * c[5] * b) * e;
        const double k3 = c[3] * e * e, k4 = -c[4] * e * e, k5 = c[5] * e * e;
        const double all[6] = {k0, k1, k2, k3, k4, k5};
        for (int i = 0; i < 6; ++i) k[i] = static_cast<float>(all[i]);
        if (s.relief.empty()) return;
        cols = raster.cols;
        last_col = static_cast<float>(raster.cols - 1);
        last_row = static_cast<float>(raster.rows - 1);
        relief.resize(static_cast<std::size_t>(raster.rows) * raster.cols);
        // The column intervals once, then each row from two node rows.
        const WallRelief &g = s.relief;
        std::vector<WallRelief::Axis> u(raster.cols);
        for (int c = 0; c < raster.cols; ++c) u[c] = g.uAxis(raster.top_left.x() + (c + 0.5) * raster.cell);
        for (int r = 0; r < raster.rows; ++r) {
            const WallRelief::Axis v = g.vAxis(raster.top_left.y() - (r + 0.5) * raster.cell);
            float *out = relief.data() + static_cast<std::size_t>(r) * cols;
            for (int c = 0; c < raster.cols; ++c) out[c] = static_cast<float>(g.at(u[c], v));
        }
    }
    /// Height (m) above the plane at raster position (col, row); beyond the raster the relief
    /// of its border cell (NaN positions read cell 0).
    float at(float col, float row) const {
        const float q = k[0] + col * (k[1] + k[3] * col + k[4] * row) + row * (k[2] + k[5] * row);
        if (relief.empty()) return q;
        const int c = static_cast<int>(std::min(last_col, std::max(0.0f, col)));
        const int r = static_cast<int>(std::min(last_row, std::max(0.0f, row)));
        return q + relief[static_cast<std::size_t>(r) * cols + c];
    }
};

}  // namespace projsurf
