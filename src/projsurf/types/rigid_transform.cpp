#include "projsurf/types/rigid_transform.hpp"

namespace projsurf {

Plane transformPlane(const Plane &plane, const Eigen::Isometry3d &T) {
    // n.x + d = 0 with x = T^-1 y  ->  (R n).y + d - (R n).t = 0
    const Eigen::Vector3d n = T.linear() * plane.normal;
    Plane out;
    out.normal = n;
    out.d = plane.d - n.dot(T.translation());
    return out;
}

Rectangle transformRectangle(const Rectangle &rect, const Eigen::Isometry3d &T) {
    Rectangle out = rect;
    for (auto &c : out.corners) c = T * c;
    return out;
}

}  // namespace projsurf
