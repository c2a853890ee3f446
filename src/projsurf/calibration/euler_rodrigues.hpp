#pragma once
// The paper's corner-ray construction (section 3.1.2 and Appendix, eqs. 3-4, A.1-A.9).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>

namespace projsurf {

/// Rotates v by `angle` (rad) about the unit `axis` with the Euler-Rodrigues formula (eq. 4):
/// v + 2a (w x v) + 2 w x (w x v), with a = cos(angle/2), w = axis sin(angle/2).
/// (The paper's eq. 3 writes cos(theta) and sin(theta) with theta the half angle.)
Eigen::Vector3d eulerRodriguesRotate(const Eigen::Vector3d &v, const Eigen::Vector3d &axis, double angle);

/// The four corner rays of the projector workspace from the central axis direction and the
/// full fields of view (rad), as in the Appendix: rotate by +-fov_h/2 about R1 (perpendicular
/// to the axis in the Y-Z plane), then by +-fov_v/2 about R2 (the x axis carried by the first
/// rotation). Returned unit directions, ordered top-left, top-right, bottom-right, bottom-left.
/// Note: R1 is written (0, cos g, sin g) in eq. A.3; the perpendicular the text asks for is
/// (0, cos g, -sin g) with g = atan(y/z), which is what is used here.
std::array<Eigen::Vector3d, 4> paperCornerRays(const Eigen::Vector3d &direction, double fov_h, double fov_v);

/// Lens origin as in (A.1): the point of the axis line with z = 0.
Eigen::Vector3d axisPointAtZeroZ(const Eigen::Vector3d &point_on_axis, const Eigen::Vector3d &direction);

}  // namespace projsurf
