#pragma once
// A wall's shape (detection/default/wall_shape.hpp) as a quadratic in the raster's (column, row)
// coordinates, in float: what the per-point passes over a raster evaluate at a point's foot
// (column = (u - top_left.x) / cell, row = (top_left.y - v) / cell, fractional).
#include "projsurf/detection/outline_raster.hpp"
#include "projsurf/detection/default/wall_shape.hpp"

namespace projsurf {

struct RasterShape {
    float k[6];  ///< 1, col, row, col^2, col row, row^2

    RasterShape(const WallShape &s, const RasterFrame &raster) {
        // u = a + e col, v = b - e row about the shape's centre.
        const double a = raster.top_left.x() - s.centre.x(), b = raster.top_left.y() - s.centre.y(), e = raster.cell;
        const auto &c = s.c;
        const double k0 = c[0] + c[1] * a + c[2] * b + c[3] * a * a + c[4] * a * b + c[5] * b * b;
        const double k1 = (c[1] + 2.0 * c[3] * a + c[4] * b) * e, k2 = -(c[2] + c[4] * a + 2.0 * c[5] * b) * e;
        const double k3 = c[3] * e * e, k4 = -c[4] * e * e, k5 = c[5] * e * e;
        const double all[6] = {k0, k1, k2, k3, k4, k5};
        for (int i = 0; i < 6; ++i) k[i] = static_cast<float>(all[i]);
    }
    /// Height (m) above the plane at raster position (col, row).
    float at(float col, float row) const {
        return k[0] + col * (k[1] + k[3] * col + k[4] * row) + row * (k[2] + k[5] * row);
    }
};

}  // namespace projsurf
