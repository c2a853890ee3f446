#include "projsurf/calibration/pose_spread.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <Eigen/Geometry>

namespace projsurf {

namespace {

constexpr double kDeg = 180.0 / 3.14159265358979323846;

double angleDeg(const Eigen::Matrix3d &a, const Eigen::Matrix3d &b) {
    const Eigen::Matrix3d d = a * b.transpose();
    return std::acos(std::clamp(0.5 * (d.trace() - 1), -1.0, 1.0)) * kDeg;
}

double directionDeg(const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
    if (!(a.norm() > 0 && b.norm() > 0)) return 0;
    return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * kDeg;
}

double jackknifeError(const std::vector<double> &x) {
    const double n = static_cast<double>(x.size());
    if (x.size() < 2) return 0;
    double mean = 0;
    for (double v : x) mean += v;
    mean /= n;
    double ss = 0;
    for (double v : x) ss += (v - mean) * (v - mean);
    return std::sqrt((n - 1) / n * ss);
}

}  // namespace

ProjectorEstimate projectorEstimate(const Projector &p) {
    ProjectorEstimate e;
    e.fx = p.fx();
    e.fy = p.fy();
    e.cx = p.cx();
    e.cy = p.cy();
    Eigen::Matrix3d axes;
    axes.col(0) = p.right();
    axes.col(1) = p.down();
    axes.col(2) = p.axis();
    e.rotation = axes.transpose();
    e.translation = -e.rotation * p.origin;
    return e;
}

PoseSpread poseSpread(const ProjectorEstimate &all, const std::vector<std::optional<ProjectorEstimate>> &loo) {
    PoseSpread s;
    s.poses = static_cast<int>(loo.size());
    std::vector<double> fx, fy, cx, cy;
    for (const auto &e : loo) {
        if (!e) {
            ++s.failed;
            continue;
        }
        fx.push_back(100 * (e->fx - all.fx) / all.fx);
        fy.push_back(100 * (e->fy - all.fy) / all.fy);
        cx.push_back(e->cx - all.cx);
        cy.push_back(e->cy - all.cy);
        s.fx_pct = std::max(s.fx_pct, std::abs(fx.back()));
        s.fy_pct = std::max(s.fy_pct, std::abs(fy.back()));
        s.cx_px = std::max(s.cx_px, std::abs(cx.back()));
        s.cy_px = std::max(s.cy_px, std::abs(cy.back()));
        s.rotation_deg = std::max(s.rotation_deg, angleDeg(e->rotation, all.rotation));
        s.translation_dir_deg = std::max(s.translation_dir_deg, directionDeg(e->translation, all.translation));
        const Eigen::Vector3d o = -e->rotation.transpose() * e->translation;
        const Eigen::Vector3d oa = -all.rotation.transpose() * all.translation;
        s.origin_mm = std::max(s.origin_mm, 1000 * (o - oa).norm());
    }
    s.se_fx_pct = jackknifeError(fx);
    s.se_fy_pct = jackknifeError(fy);
    s.se_cx_px = jackknifeError(cx);
    s.se_cy_px = jackknifeError(cy);
    return s;
}

std::string describeSpread(const PoseSpread &s) {
    if (s.poses == 0) return "not measured (too few poses to leave one out)";
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  "fx %.2f %%, fy %.2f %%, cx %.1f px, cy %.1f px, rotation %.2f deg, translation direction %.2f deg, "
                  "origin %.1f mm (largest change with one of %d poses left out%s)",
                  s.fx_pct, s.fy_pct, s.cx_px, s.cy_px, s.rotation_deg, s.translation_dir_deg, s.origin_mm, s.poses,
                  s.failed ? ", some fits failed" : "");
    return buf;
}

std::string spreadWarning(const PoseSpread &s, const SpreadLimits &l) {
    if (s.poses == 0) return "";
    std::string large;
    char buf[120];
    auto add = [&](bool over, const char *format, double v, double limit) {
        if (!over) return;
        std::snprintf(buf, sizeof buf, format, v, limit);
        large += (large.empty() ? "" : ", ") + std::string(buf);
    };
    add(std::max(s.fx_pct, s.fy_pct) > l.focal_pct, "focal length %.2f %% (> %.1f %%)", std::max(s.fx_pct, s.fy_pct),
        l.focal_pct);
    add(std::max(s.cx_px, s.cy_px) > l.principal_px, "principal point %.1f px (> %.0f px)",
        std::max(s.cx_px, s.cy_px), l.principal_px);
    add(s.rotation_deg > l.rotation_deg, "rotation %.2f deg (> %.1f deg)", s.rotation_deg, l.rotation_deg);
    add(s.translation_dir_deg > l.translation_dir_deg, "translation direction %.2f deg (> %.1f deg)",
        s.translation_dir_deg, l.translation_dir_deg);
    if (s.failed) large += (large.empty() ? "" : ", ") + std::to_string(s.failed) + " leave-one-out fit(s) failed";
    if (large.empty()) return "";
    return "leaving one pose out moves the projector by up to: " + large +
           "; these poses do not pin it down: add poses at other angles and distances";
}

}  // namespace projsurf
