#pragma once
// Whether a colour image is pixel-registered to an organized cloud (the same pixel grid): the
// depth edges (depth discontinuities) are correlated with the colour edges (gradient
// magnitude, relative to its neighbourhood) at offset 0 and at every shift up to
// max_shift_px; registered when the score at offset 0 clearly beats the median shift and is
// close to the best one.
#include <opencv2/core.hpp>
#include <string>

#include "projsurf/types/cloud.hpp"

namespace projsurf {

struct RegistrationOptions {
    int max_shift_px = 20;     ///< px, shifts tried in x and y (unregistered pairs are 10-20 px off; docs/tuning.md)
    double depth_jump = 0.04;  ///< m, a depth edge: the depth changes by more than this ...
    double depth_jump_share = 0.03;  ///< ... and by more than this share of the depth, across 2 px
    double jump_over_slope =
        3.0;  ///< ... and is this many times steeper than the surface beside it (a grazing floor is no edge)
    int min_edge_pixels = 150;  ///< fewer depth-edge pixels: the check cannot tell (measured, docs/tuning.md)
    double min_prominence =
        1.05;  ///< the best score must exceed the median over all shifts by this factor, else it cannot tell
    int local_window_px =
        41;  ///< px, colour edges are taken relative to their mean over this window (texture does not win)
    double min_zero_over_median = 1.25;  ///< registered: the score at offset 0 over the median shift's (measured,
                                         ///< docs/tuning.md)
    double min_zero_over_best = 0.7;     ///< ... and at least this share of the best shift's (a shift along one edge
                                         ///< direction keeps the other's edges; measured, docs/tuning.md)
    int max_samples = 6000;              ///< depth-edge pixels used at most (evenly spread), for speed
};

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
/// the sizes differ or the cloud is not organized.
RegistrationResult checkColourRegistration(const Cloud &cloud, const cv::Mat &bgr,
                                           const RegistrationOptions &options = {});

/// Puts `bgr` (CV_8UC3, the organized cloud's size) into cloud.colours, pixel by pixel; false
/// (and nothing changed) when the sizes or the type do not fit.
bool attachColour(Cloud &cloud, const cv::Mat &bgr);

}  // namespace projsurf
