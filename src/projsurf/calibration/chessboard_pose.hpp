#pragma once
// One chessboard pose of the structured-light calibration without depth: the board found in
// the capture under the white pattern, the captures decoded, the board's corners carried into
// the framebuffer by local homographies; the result is one view for fitStereo.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/calibration/local_homography.hpp"
#include "projsurf/calibration/stereo_fit.hpp"

namespace projsurf {

/// The decoder's thresholds for a board: no fixed shadow level (a printed board's black squares
/// reflect a tenth of the light of its white ones: white - black 4-20 grey levels on
/// procam-calibration's captures), the measured noise decides what is lit; pixels too dark to
/// decode alone are decoded from their 3 x 3 means (1 camera px of blur, about 0.6 projector px
/// on that rig; the corners' local homographies average over 17 x 17).
inline GrayDecodeConfig boardDecodeConfig() {
    GrayDecodeConfig c;
    c.min_contrast = 0.0;
    c.pool_px = 1;
    return c;
}

struct ChessboardPoseConfig {
    std::vector<cv::Size> board_sizes;  ///< inner corners to try; empty = found from the image
    double square = 1.0;                ///< board square edge, in the units the translation is wanted in
    /// See boardDecodeConfig.
    GrayDecodeConfig decode = boardDecodeConfig();
    LocalHomographyConfig homography;
};

struct ChessboardPose {
    bool board_found = false;
    cv::Size inner;                ///< inner corners per row, per column
    StereoView view;               ///< the corners both devices saw
    int corners = 0;               ///< corners found in the camera image
    int decoded_pixels = 0;        ///< camera pixels decoded
    double decoded_board_share = 0;  ///< of the camera pixels inside the board's corner outline
};

/// `captures[i]` taken while `order[i]` was projected (a complete set, see decodeGray; the
/// board is looked for in the capture of the white pattern). Throws std::invalid_argument as
/// decodeGray does.
ChessboardPose chessboardPose(const std::vector<cv::Mat> &captures, const std::vector<GrayPattern> &order,
                              int width, int height, const ChessboardPoseConfig &config = {});

}  // namespace projsurf
