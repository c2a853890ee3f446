#include "eval/real/real_scoring.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "eval/real/label_reference.hpp"

namespace projsurf::eval {

RealScore scoreRealRectangle(const RealLabel &label, const CameraIntrinsics &camera, bool found, const Rectangle &r,
                             const RealScoreRules &rules) {
    RealScore s;
    s.has_best = label.best.found;
    s.best_area = label.best.found ? label.best.area() : 0.0;
    s.found = found;
    if (!found) {
        s.right = !s.has_best;
        s.why = "nothing found";
        return s;
    }
    s.area = r.area();
    // Upright: the left and right sides along -gravity projected on the rectangle's plane.
    const Eigen::Vector3d across = r.corners[1] - r.corners[0], down = r.corners[3] - r.corners[0];
    const Eigen::Vector3d n = across.cross(down).normalized();
    Eigen::Vector3d up = -(label.gravity - label.gravity.dot(n) * n);
    if (up.norm() > 1e-9) {
        up.normalize();
        for (const Eigen::Vector3d side : {r.corners[0] - r.corners[3], r.corners[1] - r.corners[2]}) {
            const double c = std::clamp(side.normalized().dot(up), -1.0, 1.0);
            s.upright_deg = std::max(s.upright_deg, std::acos(c) * 180.0 / M_PI);
        }
    } else {
        s.upright_deg = 90.0;  // a horizontal rectangle
    }
    // Free share on each labelled surface: sample points at the centres of a fine grid.
    for (int k = 0; k < static_cast<int>(label.surfaces.size()); ++k) {
        const LabelSurface &surface = label.surfaces[k];
        if (!surface.has_plane) continue;
        int free = 0, both = 0;
        for (int j = 0; j < rules.samples_v; ++j)
            for (int i = 0; i < rules.samples_u; ++i) {
                const double a = (i + 0.5) / rules.samples_u, b = (j + 0.5) / rules.samples_v;
                const Eigen::Vector3d p = r.corners[0] + a * across + b * down;
                if (!labelledFree(label, camera, k, p)) continue;
                ++free;
                const double tolerance = std::max(rules.on_surface, rules.on_surface_share * p.norm());
                if (std::abs(surface.plane.signedDistance(p)) <= tolerance) ++both;
            }
        const double n_samples = rules.samples_u * rules.samples_v;
        const double f = both / n_samples;
        if (f > s.free_fraction || s.surface.empty()) {
            s.free_fraction = f;
            s.in_label_fraction = free / n_samples;
            s.surface = surface.name;
        }
    }
    char why[200] = "";
    if (s.upright_deg > rules.max_upright_deg)
        std::snprintf(why, sizeof why, "not upright (%.1f deg)", s.upright_deg);
    else if (s.surface.empty())
        std::snprintf(why, sizeof why, "no usable surface in the label");
    else if (s.free_fraction < rules.min_free)
        std::snprintf(why, sizeof why, "%.0f %% free on '%s', %.0f %% also on its plane (needs %.0f %%)",
                      100.0 * s.in_label_fraction, s.surface.c_str(), 100.0 * s.free_fraction, 100.0 * rules.min_free);
    s.why = why;
    s.valid = s.why.empty();
    s.right = s.valid;
    s.ratio = s.valid && s.best_area > 0 ? s.area / s.best_area : 0.0;
    return s;
}

double unsuitableShare(const RealLabel &label, const CameraIntrinsics &camera, const Rectangle &r,
                       const RealScoreRules &rules) {
    if (label.colour.unsuitable.empty()) return 0.0;
    const Eigen::Vector3d across = r.corners[1] - r.corners[0], down = r.corners[3] - r.corners[0];
    int over = 0;
    for (int j = 0; j < rules.samples_v; ++j)
        for (int i = 0; i < rules.samples_u; ++i) {
            const Eigen::Vector3d p =
                r.corners[0] + (i + 0.5) / rules.samples_u * across + (j + 0.5) / rules.samples_v * down;
            if (!(p.z() > 1e-3)) continue;
            const Eigen::Vector2d px = camera.project(p);
            for (const auto &u : label.colour.unsuitable)
                if (insidePolygon(u.polygon.pixels, px)) {
                    ++over;
                    break;
                }
        }
    return over / static_cast<double>(rules.samples_u * rules.samples_v);
}

ColourScore scoreColourRectangle(const RealLabel &label, const CameraIntrinsics &camera, bool found,
                                 const Rectangle &rectangle, const RealScoreRules &rules) {
    ColourScore c;
    c.score = scoreRealRectangle(colourAwareLabel(label), camera, found, rectangle, rules);
    if (found) c.unsuitable_share = unsuitableShare(label, camera, rectangle, rules);
    return c;
}

}  // namespace projsurf::eval
