#pragma once
// Whether a colour image is pixel-registered to an organized cloud (the same pixel grid): the
// depth edges (depth discontinuities) are correlated with the colour edges (gradient
// magnitude, relative to its neighbourhood) at offset 0 and at every shift up to
// max_shift_px; registered when the score at offset 0 clearly beats the median shift and is
// close to the best one.
#include <opencv2/core.hpp>
#include <string>

#include "projsurf/detection/detector_config.hpp"
#include "projsurf/types/cloud.hpp"

namespace projsurf {

struct RegistrationResult {
    bool checked = false;          ///< false: too few depth edges (or no texture) to tell
    bool registered = false;       ///< checked and offset 0 wins clearly (over the median shift and near the best)
    int best_dx = 0, best_dy = 0;  ///< px, colour pixel (u + dx, v + dy) matches depth pixel (u, v) best
    double score_zero =
        0.0;  ///< mean colour-edge strength on the depth edges at offset 0, (each relative to its neighbourhood)
    double score_best = 0.0;    ///< the same at the best shift
    double score_median = 0.0;  ///< the median over all shifts tried
    int edge_pixels = 0;        ///< depth-edge pixels found

    /// The scores in a few words, for a message.
    std::string summary() const;
};

/// `bgr`: CV_8UC3 of the cloud's size; `cloud` organized. Not checked (checked = false) when
/// the sizes differ or the cloud is not organized. `options`: the config's
/// suitability.registration (the front ends pass it; a library caller may keep the defaults).
RegistrationResult checkColourRegistration(const Cloud &cloud, const cv::Mat &bgr,
                                           const RegistrationOptions &options = {});

/// Puts `bgr` (CV_8UC3, the organized cloud's size) into cloud.colours, pixel by pixel; false
/// (and nothing changed) when the sizes or the type do not fit.
bool attachColour(Cloud &cloud, const cv::Mat &bgr);

}  // namespace projsurf
