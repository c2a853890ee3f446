#pragma once
// Gravity from the floor, for clouds recorded without an IMU (hand-held or tilted cameras).
#include <Eigen/Core>
#include <optional>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

struct GravityEstimate {
    Eigen::Vector3d gravity;      ///< unit, camera frame, pointing down (from the camera to the floor)
    int floor_points = 0;         ///< sampled points on the floor plane
    double angle_to_prior = 0.0;  ///< rad
};

/// The biggest plane whose normal is within `max_angle` (rad) of `prior` and that lies on
/// the far side of the camera along `prior` (a floor, not a ceiling) gives gravity = its
/// normal pointing away from the camera. nullopt when no such plane holds at least
/// `min_share` of the sampled points.
std::optional<GravityEstimate> estimateGravityFromFloor(const Cloud &cloud, const Eigen::Vector3d &prior,
                                                        double max_angle = 0.6, double min_share = 0.03,
                                                        unsigned seed = 7);

}  // namespace projsurf
