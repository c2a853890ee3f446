#include "projsurf/types/plane.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace projsurf {

Plane makePlane(const Eigen::Vector3d &normal, double d) {
    const double n = normal.norm();
    Plane plane{normal / n, d / n};
    if (plane.d < 0.0) {
        plane.normal = -plane.normal;
        plane.d = -plane.d;
    }
    return plane;
}

std::optional<Plane> fitPlane(const std::vector<Point> &points, const std::vector<int> &indices) {
    if (indices.size() < 3) return std::nullopt;
    // One pass: sums of p and p p^T about the first point (in double, so the shifted second
    // moments lose nothing that matters at metre scale).
    const Eigen::Vector3d origin = points[indices.front()].cast<double>();
    double sx = 0, sy = 0, sz = 0, sxx = 0, sxy = 0, sxz = 0, syy = 0, syz = 0, szz = 0;
    for (int i : indices) {
        const double x = points[i].x() - origin.x(), y = points[i].y() - origin.y(), z = points[i].z() - origin.z();
        sx += x;
        sy += y;
        sz += z;
        sxx += x * x;
        sxy += x * y;
        sxz += x * z;
        syy += y * y;
        syz += y * z;
        szz += z * z;
    }
    const double count = static_cast<double>(indices.size());
    const Eigen::Vector3d shift = Eigen::Vector3d(sx, sy, sz) / count;
    const Eigen::Vector3d mean = origin + shift;
    Eigen::Matrix3d cov;
    cov << sxx, sxy, sxz, sxy, syy, syz, sxz, syz, szz;
    cov -= count * shift * shift.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(cov);
    const auto &ev = solver.eigenvalues();
    if (!(ev(1) > 1e-12 * std::max(1.0, ev(2)))) return std::nullopt;  // collinear
    const Eigen::Vector3d n = solver.eigenvectors().col(0);
    return makePlane(n, -n.dot(mean));
}

std::optional<double> intersectLine(const Plane &plane, const Eigen::Vector3d &origin,
                                    const Eigen::Vector3d &direction) {
    // t = n.(A - P0) / n.(P1 - P0), with A any point of the plane (A = -d n).
    const double denom = plane.normal.dot(direction);
    if (std::abs(denom) < 1e-12) return std::nullopt;
    const Eigen::Vector3d a = -plane.d * plane.normal;
    return plane.normal.dot(a - origin) / denom;
}

std::optional<Eigen::Vector3d> intersectRay(const Plane &plane, const Eigen::Vector3d &origin,
                                            const Eigen::Vector3d &direction) {
    const auto t = intersectLine(plane, origin, direction);
    if (!t || *t <= 0.0) return std::nullopt;
    return origin + *t * direction;
}

double orientationDeg(const Plane &plane) {
    return std::acos(std::min(1.0, std::abs(plane.normal.z()))) * 180.0 / 3.14159265358979323846;
}

double tiltFromVertical(const Plane &plane, const Eigen::Vector3d &gravity) {
    return std::asin(std::min(1.0, std::abs(plane.normal.dot(gravity.normalized()))));
}

}  // namespace projsurf
