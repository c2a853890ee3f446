#pragma once
// The height of a seen wall above its plane: a quadratic for the broad bend and a relief for
// the depth camera's distortion features (fitted in detection/default/wall_shape.cpp and
// wall_relief.cpp; read by the free-space pass and the colour judgement).
#include <Eigen/Core>
#include <algorithm>
#include <vector>

namespace projsurf {

/// Heights (m) at the nodes of a regular grid over plane coordinates (u, v); node (i, j) is at
/// origin + spacing * (i, j); bilinear between nodes, the border node's value beyond the grid.
struct WallRelief {
    Eigen::Vector2d origin = Eigen::Vector2d::Zero();
    double spacing = 0.0;  ///< m; 0 = no relief (height 0 everywhere)
    int nu = 0, nv = 0;
    std::vector<float> h;  ///< nv x nu, row j = v index

    /// Where a coordinate falls along one axis of `n` nodes (`f` in node units): the node
    /// interval `i` and the fraction `a` into it, clamped to the grid (NaN reads node 0).
    struct Axis {
        int i;
        double a;
    };
    static Axis axis(double f, int n) {
        f = std::min(double(n - 1), std::max(0.0, f));  // max before min, the constant first: NaN -> 0
        const int i = std::min(static_cast<int>(f), n - 2);
        return {i, f - i};
    }
    Axis uAxis(double u) const { return axis((u - origin.x()) / spacing, nu); }
    Axis vAxis(double v) const { return axis((v - origin.y()) / spacing, nv); }
    /// The bilinear value in node interval (u.i, v.i).
    double at(const Axis &u, const Axis &v) const {
        const float *r0 = h.data() + static_cast<std::size_t>(v.i) * nu + u.i, *r1 = r0 + nu;
        return (1.0 - v.a) * ((1.0 - u.a) * r0[0] + u.a * r0[1]) + v.a * ((1.0 - u.a) * r1[0] + u.a * r1[1]);
    }

    bool empty() const { return h.empty(); }
    double at(const Eigen::Vector2d &uv) const { return h.empty() ? 0.0 : at(uAxis(uv.x()), vAxis(uv.y())); }
};

/// Height of the seen wall above its plane (towards the camera), m: a quadratic in the plane
/// coordinates (u, v) taken about `centre`,
/// s = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2, (x, y) = (u, v) - centre,
/// plus the relief.
struct WallShape {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    Eigen::Matrix<double, 6, 1> c = Eigen::Matrix<double, 6, 1>::Zero();
    double noise_k =
        0.0;  ///< 1/m, measured sigma_z / z^2 (0 = not measured): residual about the shape, or local (localNoiseK)

    WallRelief relief;

    double quadratic(const Eigen::Vector2d &uv) const {
        const double x = uv.x() - centre.x(), y = uv.y() - centre.y();
        return c[0] + c[1] * x + c[2] * y + c[3] * x * x + c[4] * x * y + c[5] * y * y;
    }
    double height(const Eigen::Vector2d &uv) const { return quadratic(uv) + relief.at(uv); }
    bool flat() const { return c.isZero(0.0) && relief.empty(); }
};

}  // namespace projsurf
