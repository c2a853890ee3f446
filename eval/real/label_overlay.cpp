#include "eval/real/label_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "projsurf/types/plane.hpp"

namespace projsurf::eval {
namespace {

const cv::Scalar kUnsuitable{0, 150, 255};  ///< BGR orange: unsuitable by its colour

std::vector<cv::Point> toPoints(const std::vector<Eigen::Vector2d> &px) {
    std::vector<cv::Point> out;
    for (const auto &p : px)
        out.emplace_back(static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y())));
    return out;
}

/// Draws the camera-frame segment a-b, clipped to z > 5 cm, in pixels.
void segment3(cv::Mat &img, const CameraIntrinsics &cam, Eigen::Vector3d a, Eigen::Vector3d b, const cv::Scalar &colour,
              int thickness) {
    const double zmin = 0.05;
    if (a.z() < zmin && b.z() < zmin) return;
    if (a.z() < zmin) a = a + (zmin - a.z()) / (b.z() - a.z()) * (b - a);
    if (b.z() < zmin) b = b + (zmin - b.z()) / (a.z() - b.z()) * (a - b);
    const Eigen::Vector2d pa = cam.project(a), pb = cam.project(b);
    const auto clampPx = [](double v) { return static_cast<int>(std::clamp(v, -1e5, 1e5)); };
    cv::line(img, {clampPx(pa.x()), clampPx(pa.y())}, {clampPx(pb.x()), clampPx(pb.y())}, colour, thickness,
             cv::LINE_AA);
}

void quad3(cv::Mat &img, const CameraIntrinsics &cam, const std::array<Eigen::Vector3d, 4> &c, const cv::Scalar &colour,
           int thickness) {
    for (int i = 0; i < 4; ++i) segment3(img, cam, c[i], c[(i + 1) % 4], colour, thickness);
}

}  // namespace

cv::Mat depthColour(const Cloud &cloud) {
    cv::Mat grey(cloud.height, cloud.width, CV_8U, cv::Scalar(0)),
        valid(cloud.height, cloud.width, CV_8U, cv::Scalar(0));
    for (int v = 0; v < cloud.height; ++v)
        for (int u = 0; u < cloud.width; ++u) {
            const Point &p = cloud.points[static_cast<std::size_t>(v) * cloud.width + u];
            if (!isFinite(p)) continue;
            grey.at<uchar>(v, u) = static_cast<uchar>(std::clamp((p.z() - 0.5) / 4.5 * 255.0, 0.0, 255.0));
            valid.at<uchar>(v, u) = 255;
        }
    cv::Mat out;
    cv::applyColorMap(grey, out, cv::COLORMAP_TURBO);
    out.setTo(cv::Scalar(0, 0, 0), valid == 0);
    return out;
}

cv::Mat renderLabelOverlay(const cv::Mat &background, const RealLabel &label, const CameraIntrinsics &camera,
                           const Rectangle *detected, double tint_alpha) {
    cv::Mat img = background.clone();
    cv::Mat tint = img.clone();
    for (const auto &s : label.surfaces)
        for (const auto &r : s.regions)
            cv::fillPoly(tint, std::vector<std::vector<cv::Point>>{toPoints(r.pixels)}, {60, 200, 60});
    for (const auto &o : label.obstacles)
        cv::fillPoly(tint, std::vector<std::vector<cv::Point>>{toPoints(o.pixels)}, {40, 40, 230});
    for (const auto &u : label.colour.unsuitable)
        cv::fillPoly(tint, std::vector<std::vector<cv::Point>>{toPoints(u.polygon.pixels)}, kUnsuitable);
    cv::addWeighted(img, 1.0 - tint_alpha, tint, tint_alpha, 0.0, img);
    for (const auto &s : label.surfaces)
        for (const auto &r : s.regions) {
            cv::polylines(img, std::vector<std::vector<cv::Point>>{toPoints(r.pixels)}, true, {0, 230, 0}, 1,
                          cv::LINE_AA);
            if (!r.pixels.empty())
                cv::putText(img, s.name, toPoints({r.pixels[0]})[0] + cv::Point(3, 12), cv::FONT_HERSHEY_SIMPLEX, 0.4,
                            {0, 255, 0}, 1, cv::LINE_AA);
        }
    for (const auto &o : label.obstacles)
        cv::polylines(img, std::vector<std::vector<cv::Point>>{toPoints(o.pixels)}, true, {0, 0, 255}, 1, cv::LINE_AA);
    for (const auto &u : label.colour.unsuitable) {
        cv::polylines(img, std::vector<std::vector<cv::Point>>{toPoints(u.polygon.pixels)}, true, kUnsuitable, 1,
                      cv::LINE_AA);
        if (!u.polygon.pixels.empty())
            cv::putText(img, u.why, toPoints({u.polygon.pixels[0]})[0] + cv::Point(3, 12), cv::FONT_HERSHEY_SIMPLEX,
                        0.4, kUnsuitable, 1, cv::LINE_AA);
    }
    // Projector footprint on the surface of the best rectangle.
    for (const auto &s : label.surfaces) {
        if (!s.has_plane || (label.best.found && s.name != label.best.surface)) continue;
        std::array<Eigen::Vector3d, 4> foot;
        bool ok = true;
        int k = 0;
        for (const auto &ray : label.projector.cornerRays()) {
            const auto hit = intersectRay(s.plane, label.projector.origin, ray);
            if (!hit)
                ok = false;
            else
                foot[k] = *hit;
            ++k;
        }
        if (ok) quad3(img, camera, foot, {0, 220, 255}, 1);
        if (label.best.found) break;
    }
    if (label.best.found) quad3(img, camera, label.best.corners, {255, 120, 0}, 2);
    if (detected) quad3(img, camera, detected->corners, {255, 0, 255}, 2);
    return img;
}

cv::Mat renderColourLabelOverlay(const cv::Mat &background, const RealLabel &label, const CameraIntrinsics &camera,
                                 const Rectangle *with_colour, const Rectangle *depth_only, double tint) {
    RealLabel l = label;
    l.best = label.colour.best;
    cv::Mat img = renderLabelOverlay(background, l, camera, nullptr, tint);
    if (depth_only) quad3(img, camera, depth_only->corners, {255, 255, 255}, 1);
    if (with_colour) quad3(img, camera, with_colour->corners, {255, 0, 255}, 2);
    const std::vector<std::pair<std::string, cv::Scalar>> legend{
        {"usable", {0, 230, 0}},        {"obstacle", {0, 0, 255}},           {"unsuitable (colour)", kUnsuitable},
        {"colour best", {255, 120, 0}}, {"detector, colour", {255, 0, 255}}, {"detector, depth only", {255, 255, 255}}};
    int y = img.rows - 8 - 14 * static_cast<int>(legend.size() - 1);
    for (const auto &[text, colour] : legend) {
        cv::rectangle(img, {6, y - 9}, {16, y + 1}, colour, cv::FILLED);
        cv::putText(img, text, {21, y}, cv::FONT_HERSHEY_SIMPLEX, 0.38, {0, 0, 0}, 3, cv::LINE_AA);
        cv::putText(img, text, {21, y}, cv::FONT_HERSHEY_SIMPLEX, 0.38, colour, 1, cv::LINE_AA);
        y += 14;
    }
    return img;
}

}  // namespace projsurf::eval
