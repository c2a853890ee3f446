#pragma once
// Chessboard corners carried from the camera into the projector (Moreno and Taubin 2012): the
// decoded camera pixels around each corner are mapped to their projector pixels by one
// homography (the board is flat there, and a small patch of it sees the projector through a
// nearly projective map), and the corner's sub-pixel camera position goes through it. The
// decoder's per-pixel quantisation (whole framebuffer pixels) averages out over the patch.
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/calibration/gray_code.hpp"

namespace projsurf {

struct LocalHomographyConfig {
    /// Half the patch side, camera px; 0 = ceil(camera width / 180) (8 px at 1280 wide: a patch
    /// of 17 x 17, the size procam-calibration uses).
    int half_patch = 0;
    /// Decoded pixels a patch needs, share of its area; fewer: the corner is left out.
    double min_decoded_share = 0.25;
    /// Decoded pixels used, by their direct light: at least this share of the patch's brightest
    /// (its 90th percentile). A printed board's dark squares get a tenth of the light of its
    /// bright ones, and near the squares' edges much of it is the bright neighbours' light
    /// blurred in by the camera's lens, carrying the neighbours' projector position. 0: all.
    double min_direct_share = 0.5;
    double ransac_px = 2.0;  ///< projector px: decoded pixels farther from the patch's homography are misreads
};

struct CornerInProjector {
    bool ok = false;
    cv::Point2f projector;  ///< framebuffer px (pixel centres at integers)
    int decoded = 0;        ///< decoded pixels in the patch
    int inliers = 0;        ///< of them, those the homography kept
};

/// One entry per camera corner, in the same order.
std::vector<CornerInProjector> cornersInProjector(const GrayDecoding &decoding,
                                                  const std::vector<cv::Point2f> &camera_corners,
                                                  const LocalHomographyConfig &config = {});

/// Share of the camera pixels inside the board's inner-corner outline (corners row by row,
/// `inner` per row and column) that were decoded.
double decodedBoardShare(const GrayDecoding &decoding, const std::vector<cv::Point2f> &camera_corners,
                         cv::Size inner);

}  // namespace projsurf
