#pragma once
// The detector's settings from Python keyword arguments, checked as the CLI checks its options
// (InputError("<option>", problem) -> projsurf.InputError with the same line).
#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include <pybind11/pybind11.h>

#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::python {

struct DetectorOptions {
    DetectorConfig config;
    bool gravity_level_assumed = false;  ///< no gravity= at all: a level camera, checked against the floor
    bool suitability_given = false;      ///< suitability= was given: warned about without registered colour
    frontend::GravityChoice gravity;  ///< the given one, the level camera's, or "auto" (from the floor of each cloud)
    frontend::MinimumSize minimum;    ///< smaller rectangles are "not found" (frontend/settings/minimum_size.hpp)
};

/// The keyword arguments as given (any Python object; a wrong type is an InputError).
struct DetectorArguments {
    pybind11::object aspect, gravity, method, hull, seed, min_width, min_area, suitability;
    pybind11::object config;  ///< None or the path of a detector settings YAML (`detect --config`)
    /// The other keyword arguments: the pipeline settings `projsurf detect` has as options,
    /// under the same names (max_tilt, voxel_leaf, ransac_distance, max_outliers, cell,
    /// max_planes, max_outlier_fraction), in the same units and ranges; any other name is an
    /// InputError that lists the known ones.
    pybind11::dict settings;
};

/// config: None or a settings YAML read first (frontend/settings/detector_config_file.hpp); every other
/// argument that is not None overrides its value. aspect: None (the framebuffer's), a number (width / height), "W:H" or
/// a pair (16, 9); gravity: None (level camera), 3 numbers (camera frame, pointing down; any length but zero),
/// "gx,gy,gz" or "auto"; method: None ("default"), "default" | "paper"; hull: "concave" |
/// "convex" (paper method); seed: None (42) or a RANSAC seed; min_width (m), min_area (m^2): None (the method's
/// default) or a number >= 0; suitability: None, "off", "avoid" or "prefer" (detect --suitability). A setting the
/// method ignores is a UserWarning, as the CLI's warning line.
DetectorOptions detectorOptions(const DetectorArguments &arguments);

/// `cloud` detected by the options (frontend/answer/detect_answer.hpp's detectWithGravity: the gravity
/// choice resolved, the minimum size applied), the gravity it was detected with, and the
/// warnings the CLI gives about it and the cloud (frontend's texts). `check_gravity`: also look
/// for the floor to check the gravity given or assumed (a search of its own: a stream checks
/// its first cloud only, the camera's mount does not change). Needs no GIL: the warnings are
/// issued by warnAll. Throws InputError("points", ...) when the detector fails on it.
struct CheckedDetection {
    Detection detection;
    Eigen::Vector3d gravity;
    std::vector<std::string> warnings;
};
CheckedDetection detectChecked(SurfaceDetector &detector, const DetectorOptions &options, const Cloud &cloud,
                               bool check_gravity = true);

/// Each line as a Python UserWarning (the CLI's "projsurf: warning: " lines).
void warnAll(const std::vector<std::string> &warnings);

}  // namespace projsurf::python
