#include "projsurf/types/plane_frame.hpp"

#include <Eigen/Geometry>

namespace projsurf {

PlaneFrame makePlaneFrame(const Plane &plane, const Eigen::Vector3d &gravity, const Eigen::Vector3d &anchor) {
    PlaneFrame f;
    f.normal = plane.normal;
    f.origin = plane.project(anchor);
    const Eigen::Vector3d g = gravity.normalized();
    Eigen::Vector3d up = -(g - g.dot(f.normal) * f.normal);
    if (up.norm() < 1e-9) up = -Eigen::Vector3d::UnitY();  // horizontal plane: not used by the pipeline
    f.up = up.normalized();
    f.right = f.up.cross(f.normal).normalized();
    return f;
}

Rectangle makeRectangle(const PlaneFrame &frame, const Eigen::Vector2d &min, const Eigen::Vector2d &max) {
    Rectangle r;
    r.corners = {frame.toCamera({min.x(), max.y()}), frame.toCamera({max.x(), max.y()}),
                 frame.toCamera({max.x(), min.y()}), frame.toCamera({min.x(), min.y()})};
    r.width = max.x() - min.x();
    r.height = max.y() - min.y();
    return r;
}

}  // namespace projsurf
