#pragma once
// A 2-D frame on a vertical plane: "right" and "up" as seen by someone facing the wall.
#include <Eigen/Core>
#include <array>

#include "projsurf/types/plane.hpp"

namespace projsurf {

struct PlaneFrame {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();    ///< a point of the plane
    Eigen::Vector3d right = Eigen::Vector3d::UnitX();    ///< in-plane, perpendicular to gravity
    Eigen::Vector3d up = -Eigen::Vector3d::UnitY();      ///< in-plane, -gravity projected on the plane
    Eigen::Vector3d normal = -Eigen::Vector3d::UnitZ();  ///< towards the camera

    Eigen::Vector2d toPlane(const Eigen::Vector3d &p) const {
        const Eigen::Vector3d q = p - origin;
        return {q.dot(right), q.dot(up)};
    }
    Eigen::Vector3d toCamera(const Eigen::Vector2d &uv) const { return origin + uv.x() * right + uv.y() * up; }
    /// Height of p above (positive, towards the camera) the plane.
    double height(const Eigen::Vector3d &p) const { return (p - origin).dot(normal); }
};

/// Frame on `plane` whose up is -gravity projected onto it and whose right is up x normal
/// (so right, up, normal is right-handed and "right" is the viewer's right when facing the
/// wall). `anchor` is projected onto the plane to give the origin.
PlaneFrame makePlaneFrame(const Plane &plane, const Eigen::Vector3d &gravity, const Eigen::Vector3d &anchor);

/// An upright rectangle on a plane: corners top-left, top-right, bottom-right, bottom-left
/// as seen facing the wall, in the camera frame.
struct Rectangle {
    std::array<Eigen::Vector3d, 4> corners{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero(),
                                           Eigen::Vector3d::Zero()};  ///< m, camera frame; zero until set
    double width = 0.0;   ///< m
    double height = 0.0;  ///< m
    double area() const { return width * height; }
    Eigen::Vector3d center() const { return 0.25 * (corners[0] + corners[1] + corners[2] + corners[3]); }
};

/// Rectangle from its lower-left corner (min) and upper-right corner (max) in plane coordinates.
Rectangle makeRectangle(const PlaneFrame &frame, const Eigen::Vector2d &min, const Eigen::Vector2d &max);

}  // namespace projsurf
