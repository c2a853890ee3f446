#pragma once
// What the projector lights from one stance on one surface: its footprint there, a quick
// upper bound of the picture it could hold, and the picture itself, with the shadows of
// what stands in front judged from that stance (the moved projector's and the moved
// camera's: the camera must see the wall to detect it), within the depth camera's range.
#include <Eigen/Core>
#include <array>
#include <opencv2/core.hpp>
#include <optional>

#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"
#include "projsurf/planning/levelled_frame.hpp"
#include "projsurf/planning/plan_surfaces.hpp"

namespace projsurf {

/// A robot pose on the floor: a move in the levelled frame of today's, then a turn.
struct Stance {
    double forward = 0.0, left = 0.0;  ///< m
    double turn = 0.0;                 ///< rad, left positive
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();  ///< P_today = rotation * P_moved + translation
    Eigen::Vector3d translation = Eigen::Vector3d::Zero();
    double move() const { return std::hypot(forward, left); }
};

Stance makeStance(const LevelledFrame &frame, double forward, double left, double turn);

struct StanceLimits {
    double robot_radius = 0.3;  ///< m, the surface must be farther than this from the lens
    double max_distance = 3.5;  ///< m, the picture's corners from the moved camera at most
    double aspect = 16.0 / 10.0;
};

/// The footprint of the moved projector on a surface and what bounds the picture in it.
struct StanceFootprint {
    std::array<Eigen::Vector2d, 4> uv;  ///< plane coordinates
    cv::Rect cells;                     ///< the raster cells of its bounding box (clipped)
    double bound_area = 0.0;            ///< m^2, no picture from here is larger
    double bound_width = 0.0;           ///< m, nor wider
};

/// nullopt when a corner ray misses the plane, the lens is too near it, or the box is empty.
std::optional<StanceFootprint> stanceFootprint(const PlanSurface &surface, const Projector &projector,
                                               const std::array<Eigen::Vector3d, 4> &rays, const Stance &stance,
                                               const StanceLimits &limits);

/// The largest picture from the stance (today's camera frame), nullopt when none fits, or when
/// even without the shadows it would be smaller than `min_area` or narrower than `min_width`
/// (the shadows, the costly part, are cast only for a picture that may matter).
/// `mask`: scratch, reused.
std::optional<Rectangle> pictureFromStance(const PlanSurface &surface, const Projector &projector,
                                           const StanceFootprint &footprint, const Stance &stance,
                                           const StanceLimits &limits, cv::Mat &mask, double min_area = 0.0,
                                           double min_width = 0.0);

}  // namespace projsurf
