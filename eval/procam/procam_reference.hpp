#pragma once
// The published method (kamino410/procam-calibration's calibrate.py) re-run on the same
// captures, to convergence: the reference `eval --procam` compares with. Its steps as the script
// has them: OpenCV's Gray-code decoder (opencv_contrib structured_light, GrayCodePattern::
// getProjPixel; white - black above black_thr, every pair white_thr apart), the board's corners
// from cv::findChessboardCorners on the white capture (no sub-pixel refinement), each carried
// into the projector by a least-squares homography (cv::findHomography, method 0) over a
// (2 ceil(cols / 180) + 1)^2 patch when at least ceil(cols / 180)^2 pixels decode there,
// cv::calibrateCamera for each device (5 coefficients; the image sizes as the script passes
// numpy's shapes: (rows, cols)), cv::stereoCalibrate with the intrinsics fixed. The one change:
// every fit has explicit criteria (COUNT + EPS, 500, DBL_EPSILON) and runs to convergence
// where the script's stop after OpenCV's default 30 (calibrateCamera) iterations.
#include <cfloat>
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/calibration/converged_fit.hpp"
#include "projsurf/calibration/stereo_fit.hpp"
#include "projsurf/io/formats/procam_captures.hpp"

namespace projsurf::eval {

struct PublishedMethodConfig {
    int black_threshold = 40, white_threshold = 5;  ///< the README's
    cv::Size board{9, 7};                           ///< the README's 9 7
    double square_m = 0.075;                        ///< the README's 75 (read as mm)
    LmCriteria criteria{500, DBL_EPSILON, true};
    /// The stereo step's criteria; unset: `criteria`. OpenCV's defaults, as the script ran:
    /// calibrateCamera {30, DBL_EPSILON}, stereoCalibrate {30, 1e-6}.
    std::optional<LmCriteria> stereo_criteria;
    bool numpy_sizes = true;  ///< image sizes as (rows, cols), as the script passes them
    bool jackknife = true;    ///< leave each pose out once
};

struct PublishedMethodRun {
    bool opencv_decoder = false;  ///< opencv_contrib's GrayCodePattern; false: projsurf's decoder stood in
    StereoFit fit;                ///< the all-pose fit (translation in m)
    /// The same captures with OpenCV's default criteria, as the script ran (calibrateCamera
    /// stops after 30 iterations, stereoCalibrate after 30 or a relative step of 1e-6): what
    /// the published XML should be when it was made from these captures.
    StereoFit opencv_defaults;
    std::vector<int> carried;     ///< corners carried into the projector, per pose
    int corners = 0;              ///< per pose
};

/// Throws InputError when a pose's board is not found or too few corners decode.
PublishedMethodRun runPublishedMethod(const ProcamFolder &folder, const PublishedMethodConfig &config = {});

}  // namespace projsurf::eval
