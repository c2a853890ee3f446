#pragma once
// Planes and rectangles carried from one frame to another by a rigid transform T
// (y = T x: T is the pose of the source frame in the target frame, e.g. fixed_from_camera).
#include <Eigen/Geometry>

#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// The plane n.x + d = 0 of the source frame, written in the target frame (n stays unit).
Plane transformPlane(const Plane &plane, const Eigen::Isometry3d &T);
/// The rectangle's corners carried by T; width and height (m) do not change.
Rectangle transformRectangle(const Rectangle &rect, const Eigen::Isometry3d &T);

}  // namespace projsurf
