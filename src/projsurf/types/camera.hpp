#pragma once
// Pinhole intrinsics of an RGB-D camera and the depth image <-> cloud conversion.
#include <Eigen/Core>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

struct CameraIntrinsics {
    int width = 640;
    int height = 480;
    double fx = 525.0;            // px
    double fy = 525.0;            // px
    double cx = 319.5;            // px
    double cy = 239.5;            // px
    double depth_scale = 1000.0;  ///< depth PNG units per metre (1000 = mm)

    /// Pixel (u, v) of a camera-frame point; z must be > 0.
    Eigen::Vector2d project(const Eigen::Vector3d &p) const {
        return {fx * p.x() / p.z() + cx, fy * p.y() / p.z() + cy};
    }
    /// Camera-frame point at pixel (u, v) with depth z (metres).
    Eigen::Vector3d backProject(double u, double v, double z) const {
        return {(u - cx) * z / fx, (v - cy) * z / fy, z};
    }
};

/// Organized cloud from a CV_16UC1 depth image; 0 means no reading and gives NaN.
/// The image size must match the intrinsics (checked by the caller).
Cloud depthToCloud(const cv::Mat &depth, const CameraIntrinsics &camera);

/// The pinhole (fx, fy, cx, cy; size of the cloud) that maps the points `indices` of an
/// organized cloud to their pixels, fitted by least squares; nullopt when the cloud is not
/// organized, too few of those points are finite, or the fit leaves more than `max_error_px`
/// (a cloud that is not a pinhole image, e.g. a resampled or merged one).
std::optional<CameraIntrinsics> fitIntrinsics(const Cloud &cloud, const std::vector<int> &indices,
                                              double max_error_px = 1.0);

}  // namespace projsurf
