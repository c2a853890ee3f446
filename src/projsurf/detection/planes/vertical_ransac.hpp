#pragma once
// RANSAC for the plane with the most points among the vertical ones (paper 3.2.1): planes
// whose normal is within `max_tilt` of horizontal (perpendicular to gravity).
#include <Eigen/Core>
#include <optional>
#include <random>
#include <vector>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/plane.hpp"

namespace projsurf {

struct RansacOptions {
    double max_tilt = kVerticalTolerance;  ///< rad, normal vs horizontal (paper 3.2.1)
    int max_iterations = 1000;             ///< upper bound on hypotheses (PCL's default)
    double probability = 0.99;             ///< stop when an all-inlier sample was drawn with this probability
    int score_subset = 0;                  ///< score hypotheses on this many points (0 = all)
    double max_sample_span = 0.0;          ///< m; > 0 draws the 2nd and 3rd point within this of the 1st
};

struct PlaneInliers {
    Plane plane;
    std::vector<int> inliers;  ///< indices into the point array
};

/// Searches the points listed in `active`; a point is an inlier when its distance to the
/// plane is at most band[i] (band has one entry per point of `points`).
std::optional<PlaneInliers> findVerticalPlane(const std::vector<Point> &points, const std::vector<int> &active,
                                              const std::vector<float> &band, const Eigen::Vector3d &gravity,
                                              const RansacOptions &options, std::mt19937 &rng);

/// Indices of `active` within band of the plane.
std::vector<int> planeInliers(const std::vector<Point> &points, const std::vector<int> &active,
                              const std::vector<float> &band, const Plane &plane);

}  // namespace projsurf
