#include "projsurf/sim/scenes/scene.hpp"

#include <algorithm>
#include <cmath>

namespace projsurf::sim {

double Bow::at(const Eigen::Vector3d &p) const {
    if (amplitude == 0.0) return 0.0;
    constexpr double kPi = 3.14159265358979323846;
    const Eigen::Vector3d r = p - origin;
    return amplitude * std::sin(kPi * r.dot(axis_x)) * std::sin(kPi * r.dot(axis_y));
}

void bowSurface(Scene &scene, int surface, const Eigen::Vector3d &origin, const Eigen::Vector3d &right,
                const Eigen::Vector3d &up, double half_wave, double height, double amplitude) {
    Bow b;
    b.amplitude = amplitude;
    b.origin = origin;
    b.axis_x = right.normalized() / half_wave;
    b.axis_y = up.normalized() / height;
    for (auto &q : scene.quads) {
        if (q.surface != surface) continue;
        b.towards = q.normal();
        if (b.towards.dot(q.center()) > 0.0) b.towards = -b.towards;  // the camera is at the origin
        q.bow = b;
    }
}

std::optional<double> intersectQuad(const Quad &q, const Eigen::Vector3d &origin, const Eigen::Vector3d &direction,
                                    double t_min) {
    // Moeller-Trumbore style: solve origin + t d = corner + a A + b B.
    const Eigen::Vector3d p = direction.cross(q.edge_b);
    const double det = q.edge_a.dot(p);
    if (std::abs(det) < 1e-15) return std::nullopt;
    const double inv = 1.0 / det;
    const Eigen::Vector3d s = origin - q.corner;
    const double a = s.dot(p) * inv;
    if (a < 0.0 || a > 1.0) return std::nullopt;
    const Eigen::Vector3d r = s.cross(q.edge_a);
    const double b = direction.dot(r) * inv;
    if (b < 0.0 || b > 1.0) return std::nullopt;
    const double t = q.edge_b.dot(r) * inv;
    if (!(t > t_min)) return std::nullopt;
    return t;
}

std::optional<Hit> castRay(const Scene &scene, const Eigen::Vector3d &origin, const Eigen::Vector3d &direction,
                           double t_min, double t_max) {
    std::optional<Hit> best;
    double best_t = t_max;
    for (std::size_t i = 0; i < scene.quads.size(); ++i) {
        const auto t = intersectQuad(scene.quads[i], origin, direction, t_min);
        if (t && *t < best_t) {
            best_t = *t;
            best = Hit{*t, static_cast<int>(i)};
        }
    }
    return best;
}

std::array<int, 6> addBox(Scene &scene, const Eigen::Vector3d &corner, const Eigen::Vector3d &ex,
                          const Eigen::Vector3d &ey, const Eigen::Vector3d &ez, const cv::Vec3f &albedo,
                          const std::string &label) {
    std::array<int, 6> ids{};
    auto add = [&](int slot, const Eigen::Vector3d &c, const Eigen::Vector3d &a, const Eigen::Vector3d &b) {
        Quad q;
        q.corner = c;
        q.edge_a = a;
        q.edge_b = b;
        q.albedo = albedo;
        q.label = label;
        ids[slot] = static_cast<int>(scene.quads.size());
        scene.quads.push_back(q);
    };
    add(0, corner, ey, ez);
    add(1, corner + ex, ey, ez);
    add(2, corner, ex, ez);
    add(3, corner + ey, ex, ez);
    add(4, corner, ex, ey);
    add(5, corner + ez, ex, ey);
    return ids;
}

std::vector<int> addWall(Scene &scene, const Eigen::Vector3d &origin, const Eigen::Vector3d &right,
                         const Eigen::Vector3d &up, double width, double height, const std::vector<WallHole> &holes,
                         const cv::Vec3f &albedo, const std::string &label, int surface) {
    // Cut the wall along every hole edge into a grid of cells; keep the cells outside all
    // holes and merge runs of kept cells along each row.
    std::vector<double> xs{0.0, width}, ys{0.0, height};
    for (const auto &h : holes) {
        xs.push_back(std::clamp(h.x0, 0.0, width));
        xs.push_back(std::clamp(h.x1, 0.0, width));
        ys.push_back(std::clamp(h.y0, 0.0, height));
        ys.push_back(std::clamp(h.y1, 0.0, height));
    }
    auto unique_sorted = [](std::vector<double> &v) {
        std::sort(v.begin(), v.end());
        v.erase(std::unique(v.begin(), v.end(), [](double a, double b) { return std::abs(a - b) < 1e-12; }), v.end());
    };
    unique_sorted(xs);
    unique_sorted(ys);
    auto in_hole = [&](double x, double y) {
        for (const auto &h : holes)
            if (x > h.x0 && x < h.x1 && y > h.y0 && y < h.y1) return true;
        return false;
    };
    std::vector<int> ids;
    for (std::size_t j = 0; j + 1 < ys.size(); ++j) {
        const double ym = 0.5 * (ys[j] + ys[j + 1]);
        std::size_t i = 0;
        while (i + 1 < xs.size()) {
            if (in_hole(0.5 * (xs[i] + xs[i + 1]), ym)) {
                ++i;
                continue;
            }
            std::size_t k = i + 1;
            while (k + 1 < xs.size() && !in_hole(0.5 * (xs[k] + xs[k + 1]), ym)) ++k;
            Quad q;
            q.corner = origin + xs[i] * right + ys[j] * up;
            q.edge_a = (xs[k] - xs[i]) * right;
            q.edge_b = (ys[j + 1] - ys[j]) * up;
            q.albedo = albedo;
            q.label = label;
            q.surface = surface;
            ids.push_back(static_cast<int>(scene.quads.size()));
            scene.quads.push_back(q);
            i = k;
        }
    }
    return ids;
}

Scene transformed(const Scene &scene, const Eigen::Isometry3d &transform) {
    Scene out = scene;
    const Eigen::Matrix3d r = transform.linear();
    for (auto &q : out.quads) {
        q.corner = transform * q.corner;
        q.edge_a = r * q.edge_a;
        q.edge_b = r * q.edge_b;
        q.bow.origin = transform * q.bow.origin;
        q.bow.axis_x = r * q.bow.axis_x;
        q.bow.axis_y = r * q.bow.axis_y;
        q.bow.towards = r * q.bow.towards;
    }
    return out;
}

int nextSurfaceId(const Scene &scene) {
    int id = 0;
    for (const auto &q : scene.quads) id = std::max(id, q.surface + 1);
    return id;
}

}  // namespace projsurf::sim
