#pragma once
// Colour given with a cloud (`detect --rgb`, Python's colour=, the node's ~use_colour): checked
// as one policy for every front end. Not 8-bit, 3-channel or not the cloud's size is an error;
// colour that cannot be registered (an unorganized cloud) or whose edges do not fit the depth's
// is not used, with a warning; colour whose registration cannot be checked is used, with a
// warning. The node, which cannot stop on a stream, takes the error as a warning and detects
// that frame without colour.
#include <functional>
#include <opencv2/core/mat.hpp>
#include <string>
#include <vector>

#include "projsurf/detection/colour/colour_registration.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf::frontend {

struct ColourAttachment {
    bool used = false;                  ///< the colour went into cloud.colours
    std::vector<std::string> warnings;  ///< lines without "projsurf: warning: ", each naming `source`
};

/// Whether `bgr` is registered to the organized `cloud`: checkColourRegistration, or a front
/// end's own that keeps one verdict for a stream (the node checks once per stream, not per frame).
using RegistrationCheck = std::function<RegistrationResult(const Cloud &cloud, const cv::Mat &bgr)>;

/// Puts `bgr` into `cloud` when the policy above allows it. Throws InputError(source, problem)
/// for colour of the wrong type or size; `source` names the colour (a file, "colour", a topic);
/// `options`: the config's suitability.registration.
ColourAttachment attachRegisteredColour(Cloud &cloud, const cv::Mat &bgr, const std::string &source,
                                        const RegistrationOptions &options);
/// The same, the registration judged by `check`.
ColourAttachment attachRegisteredColour(Cloud &cloud, const cv::Mat &bgr, const std::string &source,
                                        const RegistrationCheck &check);

/// The warning when the surface suitability was asked for (`what`: "--suitability avoid",
/// "suitability", "~suitability") and no registered colour comes with the clouds
/// (`colour_option`: "--rgb", "colour=", "~use_colour"): the surface is judged by depth only.
std::string suitabilityWithoutColourWarning(const std::string &what, const std::string &colour_option);

}  // namespace projsurf::frontend
