#pragma once
// The inner corners of a printed chessboard in a camera image (OpenCV's detector, refined to
// sub-pixel), for boards whose corner count is not told: the largest of the common sizes that
// is found.
#include <vector>

#include <opencv2/core.hpp>

namespace projsurf {

struct ChessboardCorners {
    bool found = false;
    cv::Size inner;                    ///< inner corners per row, per column
    std::vector<cv::Point2f> corners;  ///< row by row, camera px (pixel centres at integers)
};

/// `sizes`: inner-corner counts to try, largest first; empty = every count from 3 to 12 per
/// side, most corners first (a smaller board is found inside a larger one's corners too).
ChessboardCorners findChessboard(const cv::Mat &image, const std::vector<cv::Size> &sizes = {});

/// The board's object points (z = 0), row by row in the corners' order, square = edge length.
std::vector<cv::Point3f> chessboardObjectPoints(cv::Size inner, double square);

}  // namespace projsurf
