#pragma once
// The detection as plain Python values and numpy arrays, with the keys of the contract's
// detection JSON (found, reason, method, plane, rectangle, surface_check, timing_ms, gravity);
// and back, the rectangle that `correct` and `keystone` need.
#include <pybind11/pybind11.h>

#include "projsurf/detector/detector.hpp"

namespace projsurf::python {

/// found (bool), reason (None when found, else str), method (str), plane (None, or
/// {coefficients: (4,) [a, b, c, d], orientation_deg, inliers}), rectangle (None, or
/// {corners: (4, 3) top-left, top-right, bottom-right, bottom-left in metres, camera frame,
/// width_m, height_m, area_m2}), surface_check {points, outliers, accepted}, timing_ms {stage:
/// ms}, gravity (3,) the unit gravity used; with `explain`, candidates (the JSON's list of
/// every plane considered and why it lost, frontend/candidates_json.hpp).
pybind11::dict detectionToDict(const Detection &detection, const DetectorConfig &config, bool explain = false);

/// The rectangle of a detection dict (found must be true) or of a (4, 3) array of corners
/// (TL, TR, BR, BL). Throws InputError("detection", problem) as `correct --detection` does for
/// a file: not found, missing keys, corners that are not a rectangle.
Rectangle rectangleFromDetection(const pybind11::handle &detection);

}  // namespace projsurf::python
