#pragma once
// How a wall seen by a real depth camera departs from its plane. Structured-light and stereo
// cameras bend a flat wall smoothly by centimetres (Kinect v1: +-1-2 cm at 2 m, +-3-5 cm at 3 m
// towards the image border, fixed per unit: Smisek et al. 2011, Herrera et al. 2012; the
// classroom frame in shared/data/real: 19-21 mm RMS about its plane against ~10 mm of local
// noise), and real walls bow by millimetres. A quadratic height over the plane follows the
// broad bend, a relief (wall_relief.hpp) the distortion's features of a hundred pixels; what
// stands proud of the wall (a box, a frame) is local and stays in the residual.
#include <Eigen/Core>
#include <optional>
#include <vector>

#include "projsurf/types/cloud.hpp"
#include "projsurf/types/depth_tolerance.hpp"
#include "projsurf/types/plane.hpp"
#include "projsurf/types/plane_frame.hpp"
#include "projsurf/detection/default/wall_relief.hpp"

namespace projsurf {

/// Height of the seen wall above its plane (towards the camera), m: a quadratic in the plane
/// coordinates (u, v) taken about `centre`,
/// s = c0 + c1 x + c2 y + c3 x^2 + c4 x y + c5 y^2, (x, y) = (u, v) - centre,
/// plus the relief.
struct WallShape {
    Eigen::Vector2d centre = Eigen::Vector2d::Zero();
    Eigen::Matrix<double, 6, 1> c = Eigen::Matrix<double, 6, 1>::Zero();
    double noise_k =
        0.0;  ///< 1/m, measured sigma_z / z^2 (0 = not measured): residual about the shape, or local (localNoiseK)

    WallRelief relief;

    double quadratic(const Eigen::Vector2d &uv) const {
        const double x = uv.x() - centre.x(), y = uv.y() - centre.y();
        return c[0] + c[1] * x + c[2] * y + c[3] * x * x + c[4] * x * y + c[5] * y * y;
    }
    double height(const Eigen::Vector2d &uv) const { return quadratic(uv) + relief.at(uv); }
    bool flat() const { return c.isZero(0.0) && relief.empty(); }
};

struct WallShapeOptions {
    double capture_bands = 2.5;  ///< points within this many inlier bands of the plane take part
    double tukey_bands = 1.5;    ///< Tukey biweight width, in inlier bands (outliers: what stands proud)
    int iterations = 5;          ///< reweighted least-squares rounds
    int min_points = 60;         ///< fewer points: the wall stays flat
    int max_points =
        2000;  ///< more are thinned evenly (six coefficients; same areas on the real frames as 12000, measured)
    double max_bend = 0.08;  ///< m, a fitted bend larger than this anywhere in the points' extent is refused,
    double bend_per_z2 = 0.0089;  ///< 1/m, or than this times the depth squared there (max_bend at 3 m; Kinect v1's
                                  ///< +-3-5 cm at 3 m grows with z^2 as its disparity error does)
    WallReliefOptions relief;
};

/// Robust (Tukey-reweighted) fit of the shape to the points near `plane` (`band[i]` is the
/// inlier distance of points[i]): the quadratic, then the relief on the points near it
/// (`focal_px`: the depth camera's focal length), and the noise about both (median absolute
/// residual over z^2, scaled to a sigma). nullopt when too few points or the quadratic bends
/// more than `max_bend`.
std::optional<WallShape> fitWallShape(const std::vector<Point> &points, const std::vector<float> &band,
                                      const Plane &plane, const PlaneFrame &frame,
                                      const WallShapeOptions &options = {}, double focal_px = 525.0);

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
