#pragma once
// `projsurf detect`'s answer for one cloud, one call for every front end that reports it
// (detect itself, plan's "today", the node, Python): the user's gravity choice resolved on the
// cloud, the detector's answer, a library failure on this cloud (an OpenCV assertion) reported
// as a problem of its source on one line, the smallest picture worth showing applied.
#include <Eigen/Core>
#include <string>

#include "projsurf/detector/detector.hpp"
#include "projsurf/frontend/settings/gravity_choice.hpp"
#include "projsurf/frontend/settings/minimum_size.hpp"

namespace projsurf::frontend {

/// Throws InputError(source, ...) when the detector fails on the cloud; `width_option` and
/// `area_option` name the minimum in the reason, as this front end spells them.
Detection detectAnswer(SurfaceDetector &detector, const Cloud &cloud, const Eigen::Vector3d &gravity,
                       const MinimumSize &minimum, const std::string &source,
                       const std::string &width_option = "--min-width", const std::string &area_option = "--min-area");

struct GravityDetection {
    Detection detection;
    ResolvedGravity gravity;  ///< what the detector was given, and whether `auto` found a floor (for warnings)
};

/// The gravity for `cloud` by `choice` (resolveGravity), then detectAnswer with it: what every
/// front end runs on a cloud. Throws as detectAnswer.
GravityDetection detectWithGravity(SurfaceDetector &detector, const Cloud &cloud, const GravityChoice &choice,
                                   const MinimumSize &minimum, const std::string &source,
                                   const std::string &width_option = "--min-width",
                                   const std::string &area_option = "--min-area");

}  // namespace projsurf::frontend
