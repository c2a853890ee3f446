#pragma once
// The projector as the contract defines it: a pinhole whose principal point is the
// framebuffer centre and whose roll is zero with respect to the camera it is mounted on.
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>

namespace projsurf {

struct Projector {
    int width = 1280;                          ///< framebuffer width, px
    int height = 800;                          ///< framebuffer height, px
    double fov_h = 39.3 * 3.14159265358979323846 / 180.0;  ///< full horizontal FOV, rad (paper 3.1.2)
    double fov_v = 24.0 * 3.14159265358979323846 / 180.0;  ///< full vertical FOV, rad (paper 3.1.2)
    Eigen::Vector3d origin{0.0, 0.12, 0.0};    ///< lens centre, camera frame, m
    Eigen::Vector3d direction{0.0, 0.0, 1.0};  ///< central axis, unit

    /// Image right = normalise([0,1,0] x direction).
    Eigen::Vector3d right() const;
    /// Image down = direction x right.
    Eigen::Vector3d down() const;

    /// Focal lengths in pixels: the FOV spans the framebuffer's outer edges.
    double fx() const;
    double fy() const;
    /// Principal point: pixel centres are integers, so the centre is (W-1)/2, (H-1)/2.
    double cx() const { return 0.5 * (width - 1); }
    double cy() const { return 0.5 * (height - 1); }
    double aspect() const { return static_cast<double>(width) / height; }

    /// Framebuffer pixel that lights a camera-frame point; nullopt behind the lens.
    std::optional<Eigen::Vector2d> toPixel(const Eigen::Vector3d &point) const;
    /// Unit direction (camera frame) of the ray through framebuffer coordinates (u, v).
    Eigen::Vector3d ray(const Eigen::Vector2d &pixel) const;
    /// The four rays through the framebuffer's outer corners, ordered top-left,
    /// top-right, bottom-right, bottom-left (as seen facing the wall).
    std::array<Eigen::Vector3d, 4> cornerRays() const;
    /// Outer corners of the framebuffer in pixel coordinates, same order.
    std::array<Eigen::Vector2d, 4> framebufferCorners() const;
};

/// True when the axis is a usable direction (finite, non-zero, not parallel to camera y).
bool isValidProjector(const Projector &projector);

}  // namespace projsurf
