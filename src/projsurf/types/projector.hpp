#pragma once
// The projector as the contract defines it. Without the optional full-model fields it is the
// paper's pinhole: principal point at the framebuffer centre, focal lengths from the field of
// view, zero roll with respect to the camera it is mounted on. With them (contract,
// "Full projector model"): intrinsics in framebuffer pixels (the principal point may lie on
// or beyond the framebuffer's edge: lens offset), OpenCV distortion k1 k2 p1 p2 k3 (as
// cv::projectPoints) and a rotation of any roll. Camera frame, metres; pixel centres at
// integers. Framebuffer pixel (u, v) lights P whose projector coordinates R^T (P - origin)
// project to (u, v).
#include <Eigen/Core>
#include <Eigen/Geometry>
#include <array>
#include <optional>

namespace projsurf {

struct ProjectorIntrinsics {
    double fx = 0, fy = 0;  ///< focal lengths, framebuffer px
    double cx = 0, cy = 0;  ///< principal point, framebuffer px (pixel centres at integers)
};

struct Projector {
    int width = 1280;                                      ///< framebuffer width, px
    int height = 800;                                      ///< framebuffer height, px
    double fov_h = 39.3 * 3.14159265358979323846 / 180.0;  ///< full horizontal FOV, rad (paper 3.1.2)
    double fov_v = 24.0 * 3.14159265358979323846 / 180.0;  ///< full vertical FOV, rad (paper 3.1.2)
    Eigen::Vector3d origin{0.0, 0.12, 0.0};                ///< lens centre, camera frame, m
    /// Central axis, unit. With `rotation` set it is that rotation's third column (setRotation).
    Eigen::Vector3d direction{0.0, 0.0, 1.0};

    /// Optional: when set, fx()..cy() are these and fov_h, fov_v are informative only.
    std::optional<ProjectorIntrinsics> intrinsics;
    /// OpenCV k1 k2 p1 p2 k3 on normalised projector coordinates; all zero = none.
    std::array<double, 5> distortion{{0, 0, 0, 0, 0}};
    /// Optional: columns = image right, image down, optical axis, in the camera frame.
    std::optional<Eigen::Matrix3d> rotation;

    /// Sets `rotation` and keeps `direction` equal to its third column.
    void setRotation(const Eigen::Matrix3d &r);

    /// Image right: rotation's first column, else normalise([0,1,0] x direction).
    Eigen::Vector3d right() const;
    /// Image down: rotation's second column, else direction x right.
    Eigen::Vector3d down() const;
    /// Optical axis, unit: rotation's third column, else direction normalised.
    Eigen::Vector3d axis() const;

    /// Focal lengths in pixels: the intrinsics, else the FOV spans the framebuffer's outer edges.
    double fx() const;
    double fy() const;
    /// Principal point: the intrinsics, else the centre (W-1)/2, (H-1)/2.
    double cx() const { return intrinsics ? intrinsics->cx : 0.5 * (width - 1); }
    double cy() const { return intrinsics ? intrinsics->cy : 0.5 * (height - 1); }
    double aspect() const { return static_cast<double>(width) / height; }

    /// True when any distortion coefficient is non-zero.
    bool distorted() const;
    /// True when any of the optional full-model fields is set.
    bool fullModel() const { return intrinsics.has_value() || rotation.has_value() || distorted(); }

    /// Normalised projector coordinates (x/z, y/z) -> distorted ones (OpenCV's model).
    Eigen::Vector2d distort(const Eigen::Vector2d &ideal) const;
    /// The inverse of distort (Newton iteration); the input itself when not distorted.
    Eigen::Vector2d undistort(const Eigen::Vector2d &distorted_xy) const;

    /// Framebuffer pixel that lights a camera-frame point; nullopt behind the lens (or, with
    /// distortion, beyond the radius where the radial distortion stops growing).
    std::optional<Eigen::Vector2d> toPixel(const Eigen::Vector3d &point) const;
    /// The same without the distortion: the pinhole ("ideal") pixel. Equals toPixel when
    /// not distorted. Points on a plane map to ideal pixels by a homography.
    std::optional<Eigen::Vector2d> toIdealPixel(const Eigen::Vector3d &point) const;
    /// Framebuffer pixel -> ideal pixel (undistorted) and back.
    Eigen::Vector2d idealFromPixel(const Eigen::Vector2d &pixel) const;
    Eigen::Vector2d pixelFromIdeal(const Eigen::Vector2d &ideal) const;
    /// Unit direction (camera frame) of the ray through framebuffer coordinates (u, v).
    Eigen::Vector3d ray(const Eigen::Vector2d &pixel) const;
    /// The four rays through the framebuffer's outer corners, ordered top-left,
    /// top-right, bottom-right, bottom-left (as seen facing the wall).
    std::array<Eigen::Vector3d, 4> cornerRays() const;
    /// Rays of a quadrilateral that lies inside the lit area: cornerRays() without distortion;
    /// with it, the largest axis-aligned rectangle of ideal pixels inside the image of the
    /// framebuffer's edges (sampled), whose image on any plane is inside the lit outline.
    std::array<Eigen::Vector3d, 4> footprintRays() const;
    /// Outer corners of the framebuffer in pixel coordinates, same order.
    std::array<Eigen::Vector2d, 4> framebufferCorners() const;
};

/// True when the model is usable: finite axis not along camera y (without rotation), positive
/// FOV or focal lengths, a proper rotation when one is given.
bool isValidProjector(const Projector &projector);

/// The full horizontal and vertical field of view (rad) spanned by the framebuffer's outer
/// edges through the pinhole (offsets included; distortion ignored).
std::array<double, 2> fieldOfView(const Projector &projector);

}  // namespace projsurf
