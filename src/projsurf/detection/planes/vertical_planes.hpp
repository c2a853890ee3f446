#pragma once
// Every vertical plane in a set of points, biggest first (the default method's 3.2.1):
// sequential RANSAC, each plane refitted by least squares on its inliers, and a slice of a
// plane already found (depth quantisation ribs, the depth camera's lens distortion) merged
// into it instead of counting as a surface of its own.
#include <random>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/detection/planes/vertical_ransac.hpp"
#include "projsurf/types/depth_tolerance.hpp"

namespace projsurf {

struct VerticalPlaneOptions {
    RansacOptions ransac;  ///< per plane (max_tilt is the vertical tolerance)
    // The defaults are the detector's (PlaneSearchConfig), written there once.
    int max_planes = PlaneSearchConfig{}.max_planes;        ///< planes returned at most
    int min_points = PlaneSearchConfig{}.min_plane_points;  ///< inliers for a plane to count
    int refine_rounds = PlaneSearchConfig{}.refine_rounds;  ///< least-squares refits on the inliers
    double merge_angle =
        PlaneSearchConfig{}.merge_angle;  ///< rad, normals this parallel (and offsets within the margin) merge
};

/// `band[i]` is the inlier distance of points[i]; `tolerance` gives the margin within which two
/// parallel planes are slices of one. Planes in the order found; `inliers` index `points`.
std::vector<PlaneInliers> findVerticalPlanes(const std::vector<Point> &points, const std::vector<float> &band,
                                             const Eigen::Vector3d &gravity, const DepthTolerance &tolerance,
                                             const VerticalPlaneOptions &options, std::mt19937 &rng);

/// Mean of points[indices] (zero for none).
Eigen::Vector3d centroid(const std::vector<Point> &points, const std::vector<int> &indices);

}  // namespace projsurf
