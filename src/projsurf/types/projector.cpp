#include "projsurf/types/projector.hpp"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>

namespace projsurf {

void Projector::setRotation(const Eigen::Matrix3d &r) {
    rotation = r;
    direction = r.col(2).normalized();
}

Eigen::Vector3d Projector::right() const {
    if (rotation) return rotation->col(0);
    return Eigen::Vector3d::UnitY().cross(direction.normalized()).normalized();
}

Eigen::Vector3d Projector::down() const {
    if (rotation) return rotation->col(1);
    return direction.normalized().cross(right());
}

Eigen::Vector3d Projector::axis() const {
    if (rotation) return rotation->col(2);
    return direction.normalized();
}

double Projector::fx() const { return intrinsics ? intrinsics->fx : 0.5 * width / std::tan(0.5 * fov_h); }
double Projector::fy() const { return intrinsics ? intrinsics->fy : 0.5 * height / std::tan(0.5 * fov_v); }

bool Projector::distorted() const {
    return std::any_of(distortion.begin(), distortion.end(), [](double k) { return k != 0.0; });
}

Eigen::Vector2d Projector::distort(const Eigen::Vector2d &p) const {
    const double k1 = distortion[0], k2 = distortion[1], p1 = distortion[2], p2 = distortion[3], k3 = distortion[4];
    const double x = p.x(), y = p.y(), r2 = x * x + y * y;
    const double radial = 1.0 + r2 * (k1 + r2 * (k2 + r2 * k3));
    return {x * radial + 2.0 * p1 * x * y + p2 * (r2 + 2.0 * x * x),
            y * radial + p1 * (r2 + 2.0 * y * y) + 2.0 * p2 * x * y};
}

Eigen::Vector2d Projector::undistort(const Eigen::Vector2d &target) const {
    if (!distorted()) return target;
    Eigen::Vector2d p = target;
    for (int it = 0; it < 30; ++it) {
        const Eigen::Vector2d e = distort(p) - target;
        if (e.norm() < 1e-15) break;
        const double h = 1e-7;
        Eigen::Matrix2d J;
        J.col(0) = (distort(p + Eigen::Vector2d(h, 0)) - distort(p - Eigen::Vector2d(h, 0))) / (2 * h);
        J.col(1) = (distort(p + Eigen::Vector2d(0, h)) - distort(p - Eigen::Vector2d(0, h))) / (2 * h);
        const double det = J.determinant();
        if (!(std::abs(det) > 1e-12)) break;
        p -= J.inverse() * e;
        if (!p.allFinite()) return target;
    }
    return p;
}

std::optional<Eigen::Vector2d> Projector::toPixel(const Eigen::Vector3d &point) const {
    if (distorted()) {
        const auto ideal = toIdealPixel(point);
        if (!ideal) return std::nullopt;
        // Beyond the radius where the radial polynomial stops growing the model folds back
        // into the picture: such directions are not lit.
        const double x = (ideal->x() - cx()) / fx(), y = (ideal->y() - cy()) / fy(), r2 = x * x + y * y;
        const double k1 = distortion[0], k2 = distortion[1], k3 = distortion[4];
        if (!(1.0 + r2 * (3.0 * k1 + r2 * (5.0 * k2 + r2 * 7.0 * k3)) > 0.0)) return std::nullopt;
        return pixelFromIdeal(*ideal);
    }
    return toIdealPixel(point);
}

std::optional<Eigen::Vector2d> Projector::toIdealPixel(const Eigen::Vector3d &point) const {
    const Eigen::Vector3d rel = point - origin;
    const double z = rel.dot(axis());
    if (!(z > 1e-9)) return std::nullopt;
    return Eigen::Vector2d(cx() + fx() * rel.dot(right()) / z, cy() + fy() * rel.dot(down()) / z);
}

Eigen::Vector2d Projector::idealFromPixel(const Eigen::Vector2d &pixel) const {
    if (!distorted()) return pixel;
    const Eigen::Vector2d n = undistort({(pixel.x() - cx()) / fx(), (pixel.y() - cy()) / fy()});
    return {cx() + fx() * n.x(), cy() + fy() * n.y()};
}

Eigen::Vector2d Projector::pixelFromIdeal(const Eigen::Vector2d &ideal) const {
    if (!distorted()) return ideal;
    const Eigen::Vector2d d = distort({(ideal.x() - cx()) / fx(), (ideal.y() - cy()) / fy()});
    return {cx() + fx() * d.x(), cy() + fy() * d.y()};
}

Eigen::Vector3d Projector::ray(const Eigen::Vector2d &pixel) const {
    double x = (pixel.x() - cx()) / fx();
    double y = (pixel.y() - cy()) / fy();
    if (distorted()) {
        const Eigen::Vector2d n = undistort({x, y});
        x = n.x();
        y = n.y();
    }
    return (axis() + x * right() + y * down()).normalized();
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

std::array<Eigen::Vector3d, 4> Projector::footprintRays() const {
    if (!distorted()) return cornerRays();
    // The framebuffer's outer edges in ideal pixels; the inscribed axis-aligned rectangle.
    const double l = -0.5, t = -0.5, r = width - 0.5, b = height - 0.5;
    double il = -HUGE_VAL, ir = HUGE_VAL, it = -HUGE_VAL, ib = HUGE_VAL;
    const int n = 64;
    for (int i = 0; i <= n; ++i) {
        const double s = static_cast<double>(i) / n;
        const double u = l + s * (r - l), v = t + s * (b - t);
        il = std::max(il, idealFromPixel({l, v}).x());
        ir = std::min(ir, idealFromPixel({r, v}).x());
        it = std::max(it, idealFromPixel({u, t}).y());
        ib = std::min(ib, idealFromPixel({u, b}).y());
    }
    const Eigen::Vector2d ideal[4] = {{il, it}, {ir, it}, {ir, ib}, {il, ib}};
    std::array<Eigen::Vector3d, 4> rays;
    for (int i = 0; i < 4; ++i) {
        const double x = (ideal[i].x() - cx()) / fx(), y = (ideal[i].y() - cy()) / fy();
        rays[i] = (axis() + x * right() + y * down()).normalized();
    }
    return rays;
}

bool isValidProjector(const Projector &p) {
    if (!p.origin.allFinite() || !p.direction.allFinite()) return false;
    if (p.direction.norm() < 1e-9) return false;
    if (p.width < 2 || p.height < 2) return false;
    if (!(p.fov_h > 0.0 && p.fov_h < 3.1) || !(p.fov_v > 0.0 && p.fov_v < 3.1)) return false;
    if (p.intrinsics) {
        const auto &k = *p.intrinsics;
        if (!(k.fx > 0 && k.fy > 0 && std::isfinite(k.fx) && std::isfinite(k.fy))) return false;
        if (!(std::isfinite(k.cx) && std::isfinite(k.cy))) return false;
    }
    for (double k : p.distortion)
        if (!std::isfinite(k)) return false;
    if (p.rotation) {
        const Eigen::Matrix3d &r = *p.rotation;
        if (!r.allFinite()) return false;
        if ((r.transpose() * r - Eigen::Matrix3d::Identity()).cwiseAbs().maxCoeff() > 1e-3) return false;
        return r.determinant() > 0;
    }
    const Eigen::Vector3d d = p.direction.normalized();
    return std::abs(d.y()) < 0.99;  // right() is undefined along camera y
}

std::array<double, 2> fieldOfView(const Projector &p) {
    const double fx = p.fx(), fy = p.fy(), cx = p.cx(), cy = p.cy();
    return {std::atan((cx + 0.5) / fx) + std::atan((p.width - 0.5 - cx) / fx),
            std::atan((cy + 0.5) / fy) + std::atan((p.height - 0.5 - cy) / fy)};
}

}  // namespace projsurf
