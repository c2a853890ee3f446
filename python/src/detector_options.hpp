#pragma once
// The detector's settings from Python keyword arguments, checked as the CLI checks its options
// (InputError("<option>", problem) -> projsurf.InputError with the same line).
#include <Eigen/Core>
#include <optional>
#include <string>

#include <pybind11/pybind11.h>

#include "projsurf/types/cloud.hpp"
#include "projsurf/frontend/gravity_choice.hpp"
#include "projsurf/frontend/minimum_size.hpp"
#include "projsurf/detection/detector.hpp"

namespace projsurf::python {

struct DetectorOptions {
    DetectorConfig config;
    frontend::GravityChoice gravity;  ///< the given one, the level camera's, or "auto" (from the floor of each cloud)
    frontend::MinimumSize minimum;    ///< smaller rectangles are "not found" (frontend/minimum_size.hpp)
};

/// aspect: None (the framebuffer's), a number (width / height) or "W:H"; gravity: None (level
/// camera), 3 numbers (camera frame, pointing down; any length but zero) or "auto"; method:
/// "default" | "paper"; hull: "concave" | "convex" (paper method); seed: RANSAC seed;
/// min_width (m), min_area (m^2): None (the method's default) or a number >= 0.
DetectorOptions detectorOptions(const pybind11::object &aspect, const pybind11::object &gravity,
                                const std::string &method, const std::string &hull, unsigned seed,
                                const pybind11::object &min_width, const pybind11::object &min_area);

/// The gravity to detect `cloud` with: the options' own, or with "auto" the floor's (prior:
/// the options' gravity), else that prior.
Eigen::Vector3d gravityFor(const DetectorOptions &options, const Cloud &cloud);

}  // namespace projsurf::python
