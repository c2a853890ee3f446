#include "projsurf/core/projector.hpp"

#include <Eigen/Geometry>
#include <cmath>

namespace projsurf {

Eigen::Vector3d Projector::right() const {
    return Eigen::Vector3d::UnitY().cross(direction.normalized()).normalized();
}

Eigen::Vector3d Projector::down() const { return direction.normalized().cross(right()); }

double Projector::fx() const { return 0.5 * width / std::tan(0.5 * fov_h); }
double Projector::fy() const { return 0.5 * height / std::tan(0.5 * fov_v); }

std::optional<Eigen::Vector2d> Projector::toPixel(const Eigen::Vector3d &point) const {
    const Eigen::Vector3d rel = point - origin;
    const double z = rel.dot(direction.normalized());
    if (!(z > 1e-9)) return std::nullopt;
    return Eigen::Vector2d(cx() + fx() * rel.dot(right()) / z, cy() + fy() * rel.dot(down()) / z);
}

Eigen::Vector3d Projector::ray(const Eigen::Vector2d &pixel) const {
    const double x = (pixel.x() - cx()) / fx();
    const double y = (pixel.y() - cy()) / fy();
    return (direction.normalized() + x * right() + y * down()).normalized();
}

std::array<Eigen::Vector2d, 4> Projector::framebufferCorners() const {
    const double l = -0.5, t = -0.5, r = width - 0.5, b = height - 0.5;
    return {Eigen::Vector2d(l, t), Eigen::Vector2d(r, t), Eigen::Vector2d(r, b), Eigen::Vector2d(l, b)};
}

std::array<Eigen::Vector3d, 4> Projector::cornerRays() const {
    std::array<Eigen::Vector3d, 4> rays;
    const auto corners = framebufferCorners();
    for (int i = 0; i < 4; ++i) rays[i] = ray(corners[i]);
    return rays;
}

bool isValidProjector(const Projector &p) {
    if (!p.origin.allFinite() || !p.direction.allFinite()) return false;
    if (p.direction.norm() < 1e-9) return false;
    if (p.width < 2 || p.height < 2) return false;
    if (!(p.fov_h > 0.0 && p.fov_h < 3.1) || !(p.fov_v > 0.0 && p.fov_v < 3.1)) return false;
    const Eigen::Vector3d d = p.direction.normalized();
    return std::abs(d.y()) < 0.99;  // right() is undefined along camera y
}

}  // namespace projsurf
