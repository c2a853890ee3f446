#pragma once
// Boundaries of a planar point set (paper 3.2.2): convex hull and concave hull (alpha shape).
#include <Eigen/Core>
#include <array>
#include <vector>

namespace projsurf {

using Segment2 = std::array<Eigen::Vector2d, 2>;

/// Convex hull, counter-clockwise, no repeated first point (Andrew's monotone chain).
std::vector<Eigen::Vector2d> convexHull(std::vector<Eigen::Vector2d> points);

/// Boundary edges of the alpha shape: the Delaunay triangles whose circumradius is below
/// `alpha` (m) are kept, and every edge of exactly one kept triangle is a boundary edge.
/// Finds outer and inner contours (holes), as the paper's concave hull does.
std::vector<Segment2> concaveHullEdges(const std::vector<Eigen::Vector2d> &points, double alpha);

/// Edges of a closed polygon.
std::vector<Segment2> polygonEdges(const std::vector<Eigen::Vector2d> &polygon);

}  // namespace projsurf
