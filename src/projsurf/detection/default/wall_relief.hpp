#pragma once
// The part of a seen wall's departure from its plane that a quadratic cannot follow: the
// low-frequency distortion of a depth camera, whose features are about a hundred pixels across
// (Kinect v1: Smisek et al. 2011, Herrera et al. 2012; fixed per unit), so several of them lie
// on one wall. A robust smoothing of the residuals over the wall: weighted residuals binned on
// a grid of nodes, both sums blurred with a Gaussian, their ratio the height at the nodes,
// bilinear between them; Tukey weights keep what stands proud of the wall out of it.
#include <Eigen/Core>
#include <algorithm>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/detection/wall_height.hpp"

namespace projsurf {

/// One sample of the wall: its plane coordinates, its height above the quadratic, its inlier
/// band (m) and its depth (m).
struct ReliefSample {
    Eigen::Vector2d uv;
    double r, band, z;
};

/// The relief of `samples` (at least a few hundred for a meaningful result), `focal_px` the
/// depth camera's focal length (px) that turns node_px and sigma_px into metres at the samples'
/// median depth. Empty when disabled or too few samples.
WallRelief fitWallRelief(const std::vector<ReliefSample> &samples, double focal_px, const WallReliefOptions &options);

}  // namespace projsurf
