#pragma once
// Scoring a detector's rectangle against a real frame's label: is it valid (on a labelled
// usable surface, upright, at least 95 % of its area free by the labels) and how big is it
// against the label's best rectangle; and, for the labels judged on colour, how much of it lies
// over what the colour makes unsuitable.
#include <Eigen/Core>
#include <string>

#include "eval/real/real_labels.hpp"
#include "projsurf/types/camera.hpp"
#include "projsurf/types/plane_frame.hpp"

namespace projsurf::eval {

struct RealScoreRules {
    double min_free = 0.95;    ///< share of the rectangle's area free by the labels
    double on_surface = 0.05;  ///< m, |distance| to the surface's labelled plane (paper 3.2.3's outlier distance) ...
    double on_surface_share = 0.03;  ///< ... or this share of the range if larger (1.5 x Intel's 2 % RMS for the D4xx)
    double max_upright_deg = 2.0;    ///< deg, its sides vs gravity seen on its plane (the detector uses the same
                                     ///< gravity: 0 up to rounding; 2 deg is visibly crooked on a 1 m picture)
    int samples_u = 64, samples_v = 40;  ///< sample grid over the rectangle (cell centres; 1/64 of its width)
};

struct RealScore {
    bool has_best = false;           ///< the label has a usable surface with a best rectangle
    bool found = false;              ///< the detector gave a rectangle
    bool valid = false;              ///< found, upright, and free on one labelled surface
    bool right = false;              ///< valid, or found: false where the label has no usable surface
    double area = 0.0;               ///< m^2, the detector's
    double best_area = 0.0;          ///< m^2, the label's
    double ratio = 0.0;              ///< area / best_area for a valid answer, else 0
    double free_fraction = 0.0;      ///< free by the labels and on the surface's plane, where largest
    double in_label_fraction = 0.0;  ///< free by the label's polygons alone, on that surface
    std::string surface;             ///< that surface
    double upright_deg = 0.0;        ///< worst angle of its sides to the upright
    std::string why;                 ///< why not valid ("" when valid)
};

/// Scores `rectangle` (camera frame; ignored when !found) against the label.
RealScore scoreRealRectangle(const RealLabel &label, const CameraIntrinsics &camera, bool found,
                             const Rectangle &rectangle, const RealScoreRules &rules = {});

/// Share of `rectangle`'s area (the same sample grid) that the camera sees inside one of the
/// label's colour-unsuitable polygons (the target: <= 2 %). 0 without any.
double unsuitableShare(const RealLabel &label, const CameraIntrinsics &camera, const Rectangle &rectangle,
                       const RealScoreRules &rules = {});

/// A rectangle against the colour-aware label (colourAwareLabel: the unsuitable polygons are
/// obstacles, colour.best is the best): right / ratio as scoreRealRectangle, and its share
/// over the unsuitable polygons.
struct ColourScore {
    RealScore score;
    double unsuitable_share = 0.0;  ///< 0 when nothing was found
    bool clean() const { return score.found && unsuitable_share <= 0.02; }
};
ColourScore scoreColourRectangle(const RealLabel &label, const CameraIntrinsics &camera, bool found,
                                 const Rectangle &rectangle, const RealScoreRules &rules = {});

}  // namespace projsurf::eval
