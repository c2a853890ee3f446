#pragma once
// How a wall seen by a real depth camera departs from its plane. Structured-light and stereo
// cameras bend a flat wall smoothly by centimetres (Kinect v1: +-1-2 cm at 2 m, +-3-5 cm at 3 m
// towards the image border, fixed per unit: Smisek et al. 2011, Herrera et al. 2012; measured
// on a real frame: docs/tuning.md), and real walls bow by millimetres. A quadratic height over the plane follows the
// broad bend, a relief (wall_relief.hpp) the distortion's features of a hundred pixels; what
// stands proud of the wall (a box, a frame) is local and stays in the residual.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/detection/wall_height.hpp"
#include "projsurf/types/cloud.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf {

/// Robust (Tukey-reweighted) fit of the shape to the points near `plane` (`band[i]` is the
/// inlier distance of points[i]): the quadratic, then the relief on the points near it
/// (`focal_px`: the depth camera's focal length), and the noise about both (median absolute
/// residual over z^2, scaled to a sigma). nullopt when too few points or the quadratic bends
/// more than `max_bend`.
std::optional<WallShape> fitWallShape(const std::vector<Point> &points, const std::vector<float> &band,
                                      const Plane &plane, const PlaneFrame &frame, const WallShapeOptions &options = {},
                                      double focal_px = 525.0);

/// Depth noise of a wall measured between readings `offset` pixels apart in an organized cloud
/// (right and below each point `sample` lists, both within `capture` m x its band of the
/// plane): the part of the error a smooth shape does not absorb, including what is correlated
/// over a few pixels (stereo cameras). Returned as k = sigma_z / z^2 (1/m), from the 90 %
/// trimmed mean absolute difference (quantised depth makes a median of differences 0); 0 when
/// fewer than `min_pairs` pairs.
double localNoiseK(const Cloud &cloud, const std::vector<int> &sample, const std::vector<float> &band,
                   const Plane &plane, double capture_bands, int offset, int min_pairs = 100);

/// The tolerance about a fitted shape: the depth-noise coefficient measured on it, kept within
/// [lo, hi] times the sensor model's (a better sensor tightens the band, a worse one widens it).
DepthTolerance toleranceFor(const WallShape &shape, const DepthTolerance &model, double lo = 0.5, double hi = 4.0);

}  // namespace projsurf
