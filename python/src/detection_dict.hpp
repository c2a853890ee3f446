#pragma once
// The detection as plain Python values and numpy arrays, converted from the detection JSON
// itself; and back, the rectangle that `correct` and `keystone` need.
#include <pybind11/pybind11.h>

#include "projsurf/detector/detector.hpp"
#include "projsurf/tracking/continuous_tracker.hpp"

namespace projsurf::python {

/// The detection JSON of `projsurf detect --json` (frontend/answer/detection_document.hpp: with the
/// projector's `focus`, and with `explain` the `candidates`) as Python values, the same keys and
/// numbers; the vectors gravity (3,), plane.coefficients (4,) and rectangle.corners (4, 3) as
/// float64 numpy arrays.
pybind11::dict detectionToDict(const Detection &detection, const DetectorConfig &config, const Projector &projector,
                               bool explain = false);

/// detectionToDict plus continuous mode's `shown` (a rectangle dict as `rectangle`, corners a
/// (4, 3) numpy array; None when nothing is held) and `event` (frontend/answer/continuous_json.hpp).
pybind11::dict continuousFrameToDict(const Detection &detection, const ContinuousFrame &frame,
                                     const DetectorConfig &config, const Projector &projector);

/// The rectangle of a detection dict (found must be true) or of a (4, 3) array of corners
/// (TL, TR, BR, BL). Throws InputError("detection", problem) as `correct --detection` does for
/// a file: not found, missing keys, corners that are not a rectangle.
Rectangle rectangleFromDetection(const pybind11::handle &detection);

}  // namespace projsurf::python
