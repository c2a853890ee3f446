#pragma once
// A wall candidate's points in its plane's coordinates, in one straight pass each: the forms of
// PlaneFrame::toPlane, Plane::signedDistance, WallShape::quadratic and DepthTolerance::band
// written out on plain doubles so that the per-point loops vectorise (the wall shape's fit and
// the points on it). Those library forms are the reference they are tested against
// (tests/detection/default/test_plane_samples.cpp).
#include <Eigen/Core>
#include <vector>

#include "projsurf/detection/default/wall_shape.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// A point in plane coordinates: where on the plane, how far off it (m, signed), its band and depth.
struct PlaneSample {
    Eigen::Vector2d uv;
    double h, band, z;
};

/// Each point's plane coordinates, height above the plane, band (given per point) and depth,
/// into out[0 .. points.size()).
void planeSamples(const std::vector<Point> &points, const std::vector<float> &band, const Plane &plane,
                  const PlaneFrame &frame, PlaneSample *out);

/// Each point's distance from the quadratic of `shape` about `plane` (m) and its band, into
/// off[i] and band[i].
void offQuadratic(const std::vector<Point> &points, const Plane &plane, const PlaneFrame &frame, const WallShape &shape,
                  const DepthTolerance &tolerance, double *off, float *band);

}  // namespace projsurf
