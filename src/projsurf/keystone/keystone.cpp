#include "projsurf/keystone/keystone.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>

#include "projsurf/keystone/keystone_remap.hpp"
#include "projsurf/keystone/keystone_warper.hpp"

namespace projsurf {

std::optional<Eigen::Vector2d> pixelFromWorkspace(const Projector &projector, const Eigen::Vector3d &point,
                                                  const Corners3 &rays) {
    const Eigen::Vector3d axis = projector.axis();
    const Eigen::Vector3d right = projector.right(), down = projector.down();
    const Eigen::Vector3d rel = point - projector.origin;
    const double depth = rel.dot(axis);  // the plane perpendicular to the axis through the point
    if (!(depth > 1e-9)) return std::nullopt;
    double x_min = 0, x_max = 0, y_min = 0, y_max = 0;
    for (int i = 0; i < 4; ++i) {
        const double along = rays[i].dot(axis);
        if (!(along > 1e-9)) return std::nullopt;
        const Eigen::Vector3d hit = (depth / along) * rays[i];  // eq. (6) with the plane above
        const double x = hit.dot(right), y = hit.dot(down);
        x_min = i == 0 ? x : std::min(x_min, x);
        x_max = i == 0 ? x : std::max(x_max, x);
        y_min = i == 0 ? y : std::min(y_min, y);
        y_max = i == 0 ? y : std::max(y_max, y);
    }
    // Eq. (7); the workspace spans the framebuffer's outer edges, -0.5 .. W-0.5.
    const double u = -0.5 + (rel.dot(right) - x_min) / (x_max - x_min) * projector.width;
    const double v = -0.5 + (rel.dot(down) - y_min) / (y_max - y_min) * projector.height;
    return Eigen::Vector2d(u, v);
}

std::optional<Eigen::Vector2d> pixelFromWorkspace(const Projector &projector, const Eigen::Vector3d &point) {
    return pixelFromWorkspace(projector, point, projector.cornerRays());
}

Rectangle letterbox(const Rectangle &rect, double picture_aspect) {
    const auto &c = rect.corners;
    const double width = 0.5 * ((c[1] - c[0]).norm() + (c[2] - c[3]).norm());
    const double height = 0.5 * ((c[0] - c[3]).norm() + (c[1] - c[2]).norm());
    const Eigen::Vector3d right = ((c[1] - c[0]) + (c[2] - c[3])).normalized();
    const Eigen::Vector3d up = ((c[0] - c[3]) + (c[1] - c[2])).normalized();
    const Eigen::Vector3d centre = rect.center();
    double w = width, h = height;
    if (picture_aspect >= width / height)
        h = width / picture_aspect;  // wider picture: bars above and below
    else
        w = height * picture_aspect;  // narrower: bars left and right
    Rectangle out;
    out.width = w;
    out.height = h;
    out.corners = {centre - 0.5 * w * right + 0.5 * h * up, centre + 0.5 * w * right + 0.5 * h * up,
                   centre + 0.5 * w * right - 0.5 * h * up, centre - 0.5 * w * right - 0.5 * h * up};
    return out;
}

KeystoneResult computeKeystone(const Projector &projector, const Rectangle &rect, cv::Size picture,
                               double tolerance_px) {
    KeystoneResult result;
    if (picture.width < 1 || picture.height < 1) {
        result.problem = "empty picture";
        return result;
    }
    Keystone k;
    k.picture = picture;
    k.framebuffer = cv::Size(projector.width, projector.height);
    k.shown = letterbox(rect, static_cast<double>(picture.width) / picture.height);
    const Corners3 rays = projector.cornerRays();
    const char *names[4] = {"top-left", "top-right", "bottom-right", "bottom-left"};
    double overshoot = 0.0;
    const bool full_model = projector.fullModel();
    Corners2 ideal_px;
    for (int i = 0; i < 4; ++i) {
        const auto full =
            full_model ? projector.toPixel(rect.corners[i]) : pixelFromWorkspace(projector, rect.corners[i], rays);
        const auto shown = full_model ? projector.toPixel(k.shown.corners[i])
                                      : pixelFromWorkspace(projector, k.shown.corners[i], rays);
        const auto ideal = full_model ? projector.toIdealPixel(k.shown.corners[i]) : shown;
        if (!full || !shown || !ideal) {
            result.problem = std::string("the rectangle's ") + names[i] + " corner is behind the projector";
            return result;
        }
        k.rectangle_px[i] = *full;
        k.picture_px[i] = *shown;
        ideal_px[i] = *ideal;
        const double lo = -0.5, wr = projector.width - 0.5, hr = projector.height - 0.5;
        overshoot = std::max({overshoot, lo - full->x(), full->x() - wr, lo - full->y(), full->y() - hr});
    }
    if (overshoot > tolerance_px) {
        char buf[200];
        std::snprintf(buf, sizeof buf,
                      "the rectangle leaves the projector's framebuffer by %.1f px: the detection does not fit this "
                      "calibration",
                      overshoot);
        result.problem = buf;
        return result;
    }
    const double w = picture.width, h = picture.height;
    const std::vector<cv::Point2f> src = {{-0.5f, -0.5f},
                                          {static_cast<float>(w - 0.5), -0.5f},
                                          {static_cast<float>(w - 0.5), static_cast<float>(h - 0.5)},
                                          {-0.5f, static_cast<float>(h - 0.5)}};
    std::vector<cv::Point2f> dst;
    for (const auto &p : ideal_px) dst.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
    // getPerspectiveTransform solves in double but takes float points; refine the solution in
    // double so the homography maps the corners to well under 1e-3 px.
    cv::Mat H = cv::getPerspectiveTransform(src, dst);
    {
        cv::Mat A(8, 8, CV_64F, cv::Scalar(0)), b(8, 1, CV_64F);
        const double sx[4] = {-0.5, w - 0.5, w - 0.5, -0.5}, sy[4] = {-0.5, -0.5, h - 0.5, h - 0.5};
        for (int i = 0; i < 4; ++i) {
            const double X = sx[i], Y = sy[i], u = ideal_px[i].x(), v = ideal_px[i].y();
            double *r0 = A.ptr<double>(2 * i), *r1 = A.ptr<double>(2 * i + 1);
            r0[0] = X, r0[1] = Y, r0[2] = 1, r0[6] = -u * X, r0[7] = -u * Y;
            r1[3] = X, r1[4] = Y, r1[5] = 1, r1[6] = -v * X, r1[7] = -v * Y;
            b.at<double>(2 * i) = u;
            b.at<double>(2 * i + 1) = v;
        }
        cv::Mat x;
        if (cv::solve(A, b, x, cv::DECOMP_LU)) {
            H = cv::Mat::ones(3, 3, CV_64F);
            for (int i = 0; i < 8; ++i) H.at<double>(i / 3, i % 3) = x.at<double>(i);
        }
    }
    k.homography = cv::Matx33d(H);
    if (projector.distorted()) k.remap = keystoneRemap(projector, k);
    result.keystone = k;
    return result;
}

cv::Mat warpToFramebuffer(const cv::Mat &picture, const Keystone &k) {
    if (picture.empty()) return cv::Mat(k.framebuffer, picture.type(), cv::Scalar::all(0));
    if (!k.remap.empty()) return remapToFramebuffer(picture, k);
    if (picture.depth() == CV_8U) return KeystoneWarper::warpOnce(picture, k);
    // Other depths: OpenCV's warp after the same area-averaging prepass.
    const ReducedSource source = reducedSource(picture, k);
    cv::Mat fb(k.framebuffer, picture.type(), cv::Scalar::all(0));
    cv::warpPerspective(source.image, fb, cv::Mat(source.homography), k.framebuffer, cv::INTER_LINEAR,
                        cv::BORDER_CONSTANT, cv::Scalar::all(0));
    return fb;
}

std::optional<Corners2> framebufferCornersFor(const Projector &projector, const Rectangle &rect, cv::Size picture) {
    const auto r = computeKeystone(projector, rect, picture);
    if (!r.keystone) return std::nullopt;
    return r.keystone->picture_px;
}

std::optional<Eigen::Vector3d> castToWall(const Projector &projector, const Eigen::Vector2d &pixel, const Plane &wall) {
    return intersectRay(wall, projector.origin, projector.ray(pixel));
}

double ShapeErrors::worst_pct() const { return std::max({horizontal_pct, vertical_pct, diagonal_pct}); }

ShapeErrors shapeErrors(const Corners3 &c) {
    ShapeErrors e;
    e.top = (c[1] - c[0]).norm();
    e.bottom = (c[2] - c[3]).norm();
    e.left = (c[3] - c[0]).norm();
    e.right = (c[2] - c[1]).norm();
    e.diagonal1 = (c[2] - c[0]).norm();
    e.diagonal2 = (c[3] - c[1]).norm();
    e.horizontal_pct = std::abs(e.top - e.bottom) / std::min(e.top, e.bottom) * 100.0;
    e.vertical_pct = std::abs(e.left - e.right) / std::min(e.left, e.right) * 100.0;
    e.diagonal_pct = std::abs(e.diagonal1 - e.diagonal2) / std::max(e.diagonal1, e.diagonal2) * 100.0;
    return e;
}

}  // namespace projsurf
