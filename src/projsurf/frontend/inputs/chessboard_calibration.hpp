#pragma once
// The chessboard mode of `calibrate --captures` and `eval --procam`: every pose of a
// procam-style capture folder decoded (OpenCV's Gray-code order), its chessboard found under
// the white pattern, the corners carried into the projector by local homographies, camera and
// projector calibrated together.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/calibration/stereo_fit.hpp"
#include "projsurf/io/formats/procam_captures.hpp"

namespace projsurf::frontend {

struct ChessboardPose {
    std::string dir;
    bool board = false;      ///< chessboard found under the white pattern
    int corners = 0;         ///< inner corners found
    int carried = 0;         ///< of which carried into the projector
    int decoded = 0;         ///< camera pixels decoded
    double board_share = 0;  ///< decoded share of the board's pixels
};

struct ChessboardCalibration {
    StereoFit fit;
    std::vector<ChessboardPose> poses;
    cv::Size inner;                ///< inner corners per row, per column
    cv::Size camera_size;          ///< px
    double square_m = 0;           ///< printed square's edge, m (as given)
    int width = 0, height = 0;     ///< projector framebuffer, px
    double decoded_board_share = 0;  ///< the mean of board_share over the poses with a board
};

/// InputError naming the pose when no board is found anywhere or fewer than 3 poses hold one,
/// or the folder when the fit fails.
ChessboardCalibration calibrateChessboard(const ProcamFolder &folder, double square_m);

}  // namespace projsurf::frontend
