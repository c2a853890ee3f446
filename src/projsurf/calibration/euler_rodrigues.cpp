#include "projsurf/calibration/euler_rodrigues.hpp"

#include <cmath>

namespace projsurf {

Eigen::Vector3d eulerRodriguesRotate(const Eigen::Vector3d &v, const Eigen::Vector3d &axis, double angle) {
    const double a = std::cos(0.5 * angle);
    const Eigen::Vector3d w = axis.normalized() * std::sin(0.5 * angle);
    const Eigen::Vector3d wxv = w.cross(v);
    return v + 2.0 * a * wxv + 2.0 * w.cross(wxv);
}

std::array<Eigen::Vector3d, 4> paperCornerRays(const Eigen::Vector3d &direction, double fov_h, double fov_v) {
    const Eigen::Vector3d v = direction.normalized();                  // step 1 (A.1): v' starts at the origin
    const double gamma = std::atan2(v.y(), v.z());                     // (A.2)
    const Eigen::Vector3d r1(0.0, std::cos(gamma), -std::sin(gamma));  // (A.3), perpendicular to v
    // Positive rotation about R1 (about +y for a forward axis) turns the ray to the right;
    // positive rotation about R2 (about +x) turns it up (-y).
    const double sx[4] = {-1.0, 1.0, 1.0, -1.0};  // TL, TR, BR, BL: left/right
    const double sy[4] = {1.0, 1.0, -1.0, -1.0};  // up/down
    std::array<Eigen::Vector3d, 4> rays;
    for (int i = 0; i < 4; ++i) {
        const double alpha = sx[i] * 0.5 * fov_h;
        const double beta = sy[i] * 0.5 * fov_v;
        const Eigen::Vector3d v2 = eulerRodriguesRotate(v, r1, alpha);                         // (A.4-A.5)
        const Eigen::Vector3d r2 = eulerRodriguesRotate(Eigen::Vector3d::UnitX(), r1, alpha);  // (A.6)
        rays[i] = eulerRodriguesRotate(v2, r2, beta).normalized();                             // (A.7-A.8)
    }
    return rays;  // step 4 (A.9): the rays start again at the lens origin
}

Eigen::Vector3d axisPointAtZeroZ(const Eigen::Vector3d &point_on_axis, const Eigen::Vector3d &direction) {
    const double t = -point_on_axis.z() / direction.z();
    return point_on_axis + t * direction;
}

}  // namespace projsurf
