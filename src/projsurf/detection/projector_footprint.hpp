#pragma once
// Where the projector's picture falls on a plane (paper eqs. 5-6, section 3.2.2's workspace).
#include <Eigen/Core>
#include <array>
#include <optional>

#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// The footprint's corners, on the plane (camera frame) and in the plane frame's coordinates,
/// in the order of the rays.
struct Footprint {
    std::array<Eigen::Vector3d, 4> corners;
    std::array<Eigen::Vector2d, 4> uv;
};

/// The four corner rays from `origin` meet the plane; nullopt when one of them misses it.
std::optional<Footprint> footprintOnPlane(const Plane &plane, const PlaneFrame &frame, const Eigen::Vector3d &origin,
                                          const std::array<Eigen::Vector3d, 4> &rays);

/// The mean of the quadrilateral's four corners: where the rectangle search starts.
Eigen::Vector2d quadCentre(const std::array<Eigen::Vector2d, 4> &quad);

/// Whether p lies inside (or on) the convex quadrilateral `quad` (either orientation).
bool insideConvex(const std::array<Eigen::Vector2d, 4> &quad, const Eigen::Vector2d &p);

}  // namespace projsurf
