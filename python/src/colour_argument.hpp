#pragma once
// The `colour=` keyword of detect(), Detector.detect() and plan(): an (H, W, 3) uint8 B, G, R
// image registered to the points, put into the cloud by the front ends' one policy
// (frontend/inputs/registered_colour.hpp), as `--rgb` is.
#include <pybind11/pybind11.h>

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::python {

/// Colour into the cloud; its warnings come back for the caller to issue as UserWarnings.
/// Throws InputError for another type or size. `options`: the config's suitability.registration.
std::vector<std::string> attachColourArgument(Cloud &cloud, const pybind11::object &colour,
                                              const RegistrationOptions &options);

/// The colour as the overlay's background when the cloud took it (else empty); `keep` holds
/// a packed copy when the array's rows were not.
cv::Mat overlayBackground(const Cloud &cloud, const pybind11::object &colour, pybind11::object &keep);

}  // namespace projsurf::python
