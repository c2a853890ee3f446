#pragma once
// Planes, their fit to points, and ray-plane intersection (paper eqs. 5-6).
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

/// rad: a plane is vertical when its normal is within this of horizontal (perpendicular to
/// gravity): the contract's `--max-tilt` default (paper 3.2.1). Every default that says
/// "vertical" is this one.
constexpr double kVerticalTolerance = 0.1;

/// n . x + d = 0 with |n| = 1. Oriented so that the camera (origin) is on the positive
/// side (d > 0): the normal points from the wall towards the camera.
struct Plane {
    Eigen::Vector3d normal{0.0, 0.0, -1.0};
    double d = 0.0;

    double signedDistance(const Eigen::Vector3d &p) const { return normal.dot(p) + d; }
    Eigen::Vector4d coefficients() const { return {normal.x(), normal.y(), normal.z(), d}; }
    /// Point of the plane closest to p.
    Eigen::Vector3d project(const Eigen::Vector3d &p) const { return p - signedDistance(p) * normal; }
};

/// Plane through n.x + d = 0 made unit and oriented towards the camera.
Plane makePlane(const Eigen::Vector3d &normal, double d);

/// Least-squares plane (smallest eigenvector of the covariance) through the given points.
/// nullopt for fewer than 3 points or a degenerate (collinear) set.
std::optional<Plane> fitPlane(const std::vector<Point> &points, const std::vector<int> &indices);

/// Eq. (6): the parameter t of the line origin + t * direction where it meets the plane;
/// nullopt when parallel.
std::optional<double> intersectLine(const Plane &plane, const Eigen::Vector3d &origin,
                                    const Eigen::Vector3d &direction);

/// The intersection point of a ray (t > 0) with the plane; nullopt when it misses.
std::optional<Eigen::Vector3d> intersectRay(const Plane &plane, const Eigen::Vector3d &origin,
                                            const Eigen::Vector3d &direction);

/// Angle between the plane normal and the camera z axis, in degrees, in [0, 90]
/// (the paper's orientation, section 3.2.1).
double orientationDeg(const Plane &plane);

/// Angle between the normal and the horizontal (perpendicular to gravity), rad.
double tiltFromVertical(const Plane &plane, const Eigen::Vector3d &gravity);

}  // namespace projsurf
