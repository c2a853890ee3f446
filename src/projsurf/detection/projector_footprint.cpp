#include "projsurf/detection/projector_footprint.hpp"

namespace projsurf {

std::optional<Footprint> footprintOnPlane(const Plane &plane, const PlaneFrame &frame, const Eigen::Vector3d &origin,
                                          const std::array<Eigen::Vector3d, 4> &rays) {
    Footprint f;
    for (int i = 0; i < 4; ++i) {
        const auto hit = intersectRay(plane, origin, rays[i]);
        if (!hit) return std::nullopt;
        f.corners[i] = *hit;
        f.uv[i] = frame.toPlane(*hit);
    }
    return f;
}

Eigen::Vector2d quadCentre(const std::array<Eigen::Vector2d, 4> &quad) {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    for (const auto &w : quad) centre += 0.25 * w;
    return centre;
}

bool insideConvex(const std::array<Eigen::Vector2d, 4> &quad, const Eigen::Vector2d &p) {
    int sign = 0;
    for (int i = 0; i < 4; ++i) {
        const Eigen::Vector2d e = quad[(i + 1) % 4] - quad[i], q = p - quad[i];
        const double cr = e.x() * q.y() - e.y() * q.x();
        const int s = cr > 1e-12 ? 1 : (cr < -1e-12 ? -1 : 0);
        if (s != 0 && sign != 0 && s != sign) return false;
        if (s != 0) sign = s;
    }
    return true;
}

}  // namespace projsurf
