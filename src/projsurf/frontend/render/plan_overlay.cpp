#include "projsurf/frontend/render/plan_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "projsurf/frontend/render/overlay.hpp"

namespace projsurf {
namespace {

const cv::Scalar kToday(255, 0, 255), kProposed(80, 255, 80), kText(255, 255, 255), kRobot(255, 200, 0);
/// The segment a-b (px), solid, or dashed (12 px on, 12 off) for a picture that relies on wall
/// not seen (detect's overlay already uses every plain colour for something else).
void drawSegment(cv::Mat &img, const cv::Point2d &a, const cv::Point2d &b, const cv::Scalar &colour, int thickness,
                 bool dashed) {
    auto at = [](const cv::Point2d &p) { return cv::Point(cvRound(p.x * 16), cvRound(p.y * 16)); };
    const double length = cv::norm(b - a), dash = 12.0;
    if (!dashed || length <= dash) {
        cv::line(img, at(a), at(b), colour, thickness, cv::LINE_AA, 4);
        return;
    }
    for (double t = 0.0; t < length; t += 2.0 * dash)
        cv::line(img, at(a + (b - a) * (t / length)), at(a + (b - a) * (std::min(t + dash, length) / length)), colour,
                 thickness, cv::LINE_AA, 4);
}

/// The proposed rectangle drawn on detect's overlay (whose picture part is the camera's image
/// scaled), dashed when it relies on wall not seen.
void drawProposed(cv::Mat &img, const CameraIntrinsics &cam, const Rectangle &r, bool dashed) {
    const double scale = static_cast<double>(img.cols) / cam.width;
    std::vector<cv::Point2d> px;
    for (const auto &c : r.corners) {
        const double z = std::max(c.z(), 1e-3);
        auto fit = [](double v) { return std::clamp(v, -1e5, 1e5); };
        px.emplace_back(fit((cam.fx * c.x() / z + cam.cx + 0.5) * scale - 0.5),
                        fit((cam.fy * c.y() / z + cam.cy + 0.5) * scale - 0.5));
    }
    for (std::size_t k = 0; k < px.size(); ++k) drawSegment(img, px[k], px[(k + 1) % px.size()], kProposed, 4, dashed);
}

/// Top-down: left/right across, forward up; 1 px per `mpp` m about the camera's foot.
struct TopView {
    LevelledFrame f;
    double mpp = 0.01;
    cv::Point2f origin;
    cv::Point2f operator()(const Eigen::Vector3d &p) const {
        return {static_cast<float>(origin.x - p.dot(f.left) / mpp),
                static_cast<float>(origin.y - p.dot(f.forward) / mpp)};
    }
};

void drawRobot(cv::Mat &img, const TopView &v, const Eigen::Vector3d &at, const Eigen::Vector3d &forward, double radius,
               const cv::Scalar &colour, const char *label) {
    const cv::Point2f c = v(at);
    cv::circle(img, c, static_cast<int>(std::lround(radius / v.mpp)), colour, 2, cv::LINE_AA);
    cv::arrowedLine(img, c, v(at + 1.5 * radius * forward), colour, 2, cv::LINE_AA, 0, 0.25);
    cv::putText(img, label, c + cv::Point2f(6, -6), cv::FONT_HERSHEY_SIMPLEX, 0.5, colour, 1, cv::LINE_AA);
}

cv::Mat topDown(const Cloud &cloud, const PlanResult &plan, const Eigen::Vector3d &gravity, double radius, int size) {
    cv::Mat img(size, size, CV_8UC3, cv::Scalar(30, 30, 30));
    TopView v;
    v.f = levelledFrame(gravity);
    // Framed on the robot now and after, and both pictures, with a metre about them.
    std::vector<Eigen::Vector3d> keep{Eigen::Vector3d::Zero(), plan.translation};
    for (const Rectangle *r : {&plan.today.rectangle, &plan.predicted})
        if (r->area() > 0) keep.insert(keep.end(), r->corners.begin(), r->corners.end());
    Eigen::Vector2d lo = Eigen::Vector2d::Constant(1e9), hi = -lo;
    for (const auto &p : keep) {
        const Eigen::Vector2d q(-p.dot(v.f.left), -p.dot(v.f.forward));
        lo = lo.cwiseMin(q);
        hi = hi.cwiseMax(q);
    }
    lo -= Eigen::Vector2d::Constant(1.0);
    hi += Eigen::Vector2d::Constant(1.0);
    v.mpp = std::clamp((hi - lo).maxCoeff(), 2.0, 20.0) / size;
    const Eigen::Vector2d mid = 0.5 * (lo + hi);
    v.origin = {static_cast<float>(0.5 * size - mid.x() / v.mpp), static_cast<float>(0.5 * size - mid.y() / v.mpp)};
    for (std::size_t i = 0; i < cloud.points.size(); i += 3) {
        if (!isFinite(cloud.points[i])) continue;
        const cv::Point2f q = v(cloud.points[i].cast<double>());
        if (q.x < 0 || q.y < 0 || q.x >= size || q.y >= size) continue;
        cv::Vec3b &px = img.at<cv::Vec3b>(static_cast<int>(q.y), static_cast<int>(q.x));
        px = cv::Vec3b(std::min(255, px[0] + 40), std::min(255, px[1] + 40), std::min(255, px[2] + 40));
    }
    auto bottom = [&](const Rectangle &r, const cv::Scalar &c) {
        if (r.area() > 0) cv::line(img, v(r.corners[3]), v(r.corners[2]), c, 4, cv::LINE_AA);
    };
    if (plan.today.found) bottom(plan.today.rectangle, kToday);
    if (plan.found && plan.predicted.area() > 0)
        drawSegment(img, v(plan.predicted.corners[3]), v(plan.predicted.corners[2]), kProposed, 4, plan.assumed());
    drawRobot(img, v, Eigen::Vector3d::Zero(), v.f.forward, radius, kRobot, "now");
    if (plan.found && plan.moves())
        drawRobot(img, v, plan.translation, plan.rotation * v.f.forward, radius, kProposed, "after");
    const int metre = static_cast<int>(std::lround(1.0 / v.mpp));
    cv::line(img, {10, size - 14}, {10 + metre, size - 14}, kText, 2);
    cv::putText(img, "1 m", {14 + metre, size - 9}, cv::FONT_HERSHEY_SIMPLEX, 0.5, kText, 1, cv::LINE_AA);
    return img;
}

}  // namespace

cv::Mat renderPlanOverlay(const Cloud &cloud, const PlanResult &plan, const DetectorConfig &config,
                          const CameraIntrinsics *camera, const Eigen::Vector3d &gravity, double robot_radius,
                          const cv::Mat &colour) {
    CameraIntrinsics cam = camera ? *camera : estimateIntrinsics(cloud);
    if (!(cam.fx > 0)) cam = CameraIntrinsics{};
    cv::Mat left = renderOverlay(cloud, plan.today, config, camera, colour);
    if (plan.found && plan.moves()) drawProposed(left, cam, plan.predicted, plan.assumed());
    cv::Mat sketch = topDown(cloud, plan, gravity, robot_radius, left.rows);
    cv::Mat out;
    cv::hconcat(left, sketch, out);
    char line[400];
    if (plan.assumed())
        std::snprintf(line, sizeof line,
                      "plan: %s: %.2f m^2 (green, dashed: assumed, %.0f %% on wall not seen), %.2f m^2 "
                      "today (magenta)",
                      moveInWords(plan.move).c_str(), plan.predicted.area(), 100.0 * plan.assumed_share,
                      plan.todayArea());
    else if (plan.found)
        std::snprintf(line, sizeof line, "plan: %s: %.2f m^2 (green), %.2f m^2 today (magenta)",
                      moveInWords(plan.move).c_str(), plan.predicted.area(), plan.todayArea());
    else
        std::snprintf(line, sizeof line, "plan: not found: %s", plan.reason.c_str());
    cv::Mat bar(36, out.cols, CV_8UC3, cv::Scalar(32, 32, 32));
    cv::putText(bar, line, {10, 24}, cv::FONT_HERSHEY_SIMPLEX, 0.6, kText, 1, cv::LINE_AA);
    cv::vconcat(bar, out, out);
    return out;
}

}  // namespace projsurf
