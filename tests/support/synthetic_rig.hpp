#pragma once
// A small synthetic rig for the calibration and keystone tests: a Kinect-like camera at the
// origin, a projector (the contract's pinhole) next to it, and a flat wall. Renders
// calibration captures (colour + registered depth) and noisy wall clouds.
#include <Eigen/Core>
#include <cmath>
#include <random>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "projsurf/calibration/calibration.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/keystone/keystone.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/types/projector.hpp"

namespace rig {

using namespace projsurf;
constexpr double kDeg = 3.14159265358979323846 / 180.0;

/// Kinect v1 depth noise (Khoshelham & Elberink): sigma_z = 1.425e-3 z^2, m.
inline double kinectSigma(double z) { return 1.425e-3 * z * z; }

/// The projector the tests treat as the truth: lens 10 cm below the camera at z = 0 (the
/// paper's convention for the lens origin, A.1), axis slightly up and to the right.
inline Projector trueProjector() {
    Projector p;  // 1280x800, 39.3 x 24.0 deg (Aaxa P300)
    p.origin = Eigen::Vector3d(0.03, 0.10, 0.0);
    p.direction = Eigen::Vector3d(0.02, -0.06, 1.0).normalized();
    return p;
}

/// A wall `distance` m ahead along the camera's z axis, turned about the vertical by
/// `angle_deg` (the paper's orientation: angle between its normal and the camera z axis).
inline Plane wall(double distance, double angle_deg) {
    const double a = angle_deg * kDeg;
    const Eigen::Vector3d n(std::sin(a), 0.0, -std::cos(a));
    return makePlane(n, -n.dot(Eigen::Vector3d(0, 0, distance)));
}

/// An upright rectangle of the framebuffer's aspect ratio on `plane`, inside the projector's
/// workspace on it (its inscribed axis-aligned box, shrunk by `fill`).
inline Rectangle rectangleInWorkspace(const Projector &proj, const Plane &plane, double fill = 0.85) {
    const Eigen::Vector3d gravity(0, 1, 0);
    const auto centre = castToWall(proj, Eigen::Vector2d(proj.cx(), proj.cy()), plane);
    const PlaneFrame frame = makePlaneFrame(plane, gravity, *centre);
    Eigen::Vector2d q[4];
    const auto corners = proj.framebufferCorners();
    for (int i = 0; i < 4; ++i) q[i] = frame.toPlane(*castToWall(proj, corners[i], plane));
    const double x0 = std::max(q[0].x(), q[3].x()), x1 = std::min(q[1].x(), q[2].x());
    const double y1 = std::min(q[0].y(), q[1].y()), y0 = std::max(q[2].y(), q[3].y());
    const Eigen::Vector2d c(0.5 * (x0 + x1), 0.5 * (y0 + y1));
    double w = fill * (x1 - x0), h = fill * (y1 - y0);
    const double aspect = proj.aspect();
    if (w / h > aspect)
        w = h * aspect;
    else
        h = w / aspect;
    return makeRectangle(frame, c - Eigen::Vector2d(w / 2, h / 2), c + Eigen::Vector2d(w / 2, h / 2));
}

/// Wall points seen by a 640x480 Kinect (every `step`-th pixel) with noise along the depth.
inline std::vector<Point> noisyWallCloud(const Plane &plane, const CameraIntrinsics &cam, std::mt19937 &rng,
                                         int step = 4) {
    std::vector<Point> pts;
    std::normal_distribution<double> unit(0.0, 1.0);
    for (int v = 0; v < cam.height; v += step)
        for (int u = 0; u < cam.width; u += step) {
            const Eigen::Vector3d ray = cam.backProject(u, v, 1.0);
            const auto hit = intersectRay(plane, Eigen::Vector3d::Zero(), ray);
            if (!hit || hit->z() > 5.0) continue;
            const double z = hit->z() + kinectSigma(hit->z()) * unit(rng);
            pts.push_back(cam.backProject(u, v, z).cast<float>());
        }
    return pts;
}

struct CaptureOptions {
    double disc_radius_px = 100.0;    ///< radius of the white disc in the projector framebuffer
    bool noise = true;                ///< Kinect depth noise + colour noise
    double hole_fraction = 0.05;      ///< random pixels with no depth reading
    double disc_hole_fraction = 0.4;  ///< extra missing readings inside the bright disc
    bool drop_disc_depth = false;     ///< no depth at all around the disc (a refusal case)
    bool no_disc = false;             ///< nothing projected (a refusal case)
};

/// One calibration capture: the calibration picture (black, white disc at the framebuffer
/// centre) projected on `plane`, seen by the camera; depth in mm, registered.
inline CaptureImages renderCapture(const Projector &proj, const Plane &plane, const CameraIntrinsics &cam,
                                   std::mt19937 &rng, const CaptureOptions &opt = {}) {
    CaptureImages c;
    c.color = cv::Mat(cam.height, cam.width, CV_8UC3);
    c.depth = cv::Mat(cam.height, cam.width, CV_16UC1, cv::Scalar(0));
    std::normal_distribution<double> unit(0.0, 1.0);
    std::uniform_real_distribution<double> uni(0.0, 1.0);
    const Eigen::Vector2d centre(proj.cx(), proj.cy());
    for (int v = 0; v < cam.height; ++v)
        for (int u = 0; u < cam.width; ++u) {
            int lit = 0;  // 2x2 supersampling for the colour
            for (int sy = 0; sy < 2; ++sy)
                for (int sx = 0; sx < 2; ++sx) {
                    const auto hit = intersectRay(plane, Eigen::Vector3d::Zero(),
                                                  cam.backProject(u - 0.25 + 0.5 * sx, v - 0.25 + 0.5 * sy, 1.0));
                    if (!hit) continue;
                    const auto px = proj.toPixel(*hit);
                    if (!opt.no_disc && px && (*px - centre).norm() <= opt.disc_radius_px) ++lit;
                }
            double grey = 12.0 + 210.0 * lit / 4.0 + (opt.noise ? 4.0 * unit(rng) : 0.0);
            const auto g = cv::saturate_cast<uchar>(grey);
            c.color.at<cv::Vec3b>(v, u) = cv::Vec3b(g, g, g);
            const auto hit = intersectRay(plane, Eigen::Vector3d::Zero(), cam.backProject(u, v, 1.0));
            if (!hit) continue;
            if (opt.noise && uni(rng) < opt.hole_fraction) continue;
            if (opt.noise && lit > 0 && uni(rng) < opt.disc_hole_fraction) continue;
            const double z = hit->z() + (opt.noise ? kinectSigma(hit->z()) * unit(rng) : 0.0);
            c.depth.at<std::uint16_t>(v, u) = cv::saturate_cast<std::uint16_t>(std::lround(z * 1000.0));
        }
    if (opt.drop_disc_depth) {
        // The whole neighbourhood of the disc reads nothing (e.g. a black absorbing surface).
        const auto hit = castToWall(proj, centre, plane);
        const Eigen::Vector2d p = cam.project(*hit);
        cv::circle(c.depth, cv::Point(static_cast<int>(p.x()), static_cast<int>(p.y())), 150, cv::Scalar(0), -1);
    }
    return c;
}

/// Robot positions for a calibration: facing the wall at several distances, slightly turned.
inline std::vector<Plane> calibrationWalls() {
    return {wall(1.0, 0.0), wall(1.5, 4.0), wall(2.0, -3.0), wall(2.5, 2.0), wall(3.0, -5.0)};
}

}  // namespace rig
