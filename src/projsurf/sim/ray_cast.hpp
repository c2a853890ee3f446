#pragma once
// Per-pixel ray casting of a scene from a pinhole viewpoint (the camera, the projector, the
// Kinect's IR emitter). Each quad is tested only on the pixels of its projected bounding box,
// so a VGA frame of a few dozen quads costs a few milliseconds.
#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "projsurf/sim/scenes/scene.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/projector.hpp"

namespace projsurf::sim {

/// A pinhole looking from `origin`; rows of `rotation` are its image right, image down and
/// forward axes in the camera frame. Pixel centres are at integer coordinates.
struct PinholeView {
    Eigen::Vector3d origin = Eigen::Vector3d::Zero();
    Eigen::Matrix3d rotation = Eigen::Matrix3d::Identity();
    double fx = 525.0, fy = 525.0, cx = 319.5, cy = 239.5;  // px
    int width = 640, height = 480;

    /// Point in the view's own frame (x right, y down, z forward).
    Eigen::Vector3d toView(const Eigen::Vector3d &p) const { return rotation * (p - origin); }
    /// Pixel of a view-frame point (z > 0).
    Eigen::Vector2d pixelOf(const Eigen::Vector3d &v) const {
        return {fx * v.x() / v.z() + cx, fy * v.y() / v.z() + cy};
    }
    /// Camera-frame direction through pixel (u, v), scaled so that its forward component is 1.
    Eigen::Vector3d rayDirection(double u, double v) const {
        return rotation.transpose() * Eigen::Vector3d((u - cx) / fx, (v - cy) / fy, 1.0);
    }
    /// True when (u, v) lies inside the image's outer edges [-0.5, W - 0.5) x [-0.5, H - 0.5).
    bool inside(const Eigen::Vector2d &px) const {
        return px.x() >= -0.5 && px.x() < width - 0.5 && px.y() >= -0.5 && px.y() < height - 0.5;
    }
    /// The same view with its image scaled by s (fewer pixels, same field of view).
    PinholeView scaled(double s) const;
    /// The same view with `pad_px` more pixels on every side (wider field of view, same pixels).
    PinholeView padded(int pad_px) const;

    /// A view with these intrinsics (px) and image size, at the camera frame's origin and axes.
    static PinholeView fromIntrinsics(double fx, double fy, double cx, double cy, int width, int height);
    /// The same view looking from `at` (camera frame, m) with its image right, image down and
    /// forward along these camera-frame unit vectors.
    PinholeView placed(const Eigen::Vector3d &at, const Eigen::Vector3d &right, const Eigen::Vector3d &down,
                       const Eigen::Vector3d &forward) const;
};

/// The RGB-D camera at the origin of its own frame.
PinholeView cameraView(const CameraIntrinsics &camera);
/// The projector as a pinhole view (its intrinsics and axes). With distortion it is the ideal
/// pinhole widened to every lit direction (for shadow maps); framebuffer pixels of points then
/// come from Projector::toPixel, not from the view.
PinholeView projectorView(const Projector &projector);

/// A viewer `distance` metres in front of `target` on `plane`, looking straight at it, image
/// upright for `gravity` (camera frame), with a horizontal field of view of `fov_h_deg`.
PinholeView facingView(const Plane &plane, const Eigen::Vector3d &target, double distance,
                       const Eigen::Vector3d &gravity, int width = 640, int height = 480, double fov_h_deg = 60.0);

/// Nearest surface per pixel.
struct DepthBuffer {
    cv::Mat z;     ///< CV_64F, depth along the view's forward axis, m; +inf where nothing is hit
    cv::Mat quad;  ///< CV_32S, index of the quad hit, -1 where nothing is hit
};

/// Ray-casts every pixel of the view; hits closer than `near` (m, along the axis) are ignored.
DepthBuffer castView(const Scene &scene, const PinholeView &view, double near = 0.05);

/// Light (or IR pattern) sent from a view's origin: which scene points it reaches.
struct ShadowMap {
    PinholeView view;
    DepthBuffer buffer;
    /// True when the point `p` (camera frame) on quad `quad` is reached from the view's
    /// origin, i.e. nothing else lies between; points outside the view are not reached.
    bool reaches(const Eigen::Vector3d &p, int quad) const;
};
/// Casts the view (scaled by `scale` for speed) into a shadow map.
ShadowMap makeShadowMap(const Scene &scene, const PinholeView &view, double scale = 1.0);

}  // namespace projsurf::sim
