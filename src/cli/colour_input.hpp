#pragma once
// `--rgb FILE` as every command that takes one on a single cloud reads it (detect, plan): the
// image read, then put into the cloud by the front end's one policy
// (frontend/inputs/registered_colour.hpp), its warnings on stderr, one line each.
#include <opencv2/core/mat.hpp>
#include <string>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::cli {

/// The colour of `path` put into `cloud` (throws InputError, exit 2, for an unreadable image or
/// one of the wrong type or size); the image for the overlay's background, empty when the
/// policy did not use it. `options`: the config's suitability.registration.
cv::Mat attachColourFile(Cloud &cloud, const std::string &path, const RegistrationOptions &options);

}  // namespace projsurf::cli
