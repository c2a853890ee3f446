#pragma once
// The calibration YAML written by the chessboard mode of `calibrate`: the contract's keys and
// the full-model keys (io/yaml/yaml_files.cpp), the camera's own intrinsics as fitted with it, and
// the residuals.
#include <string>

#include "projsurf/calibration/stereo_fit.hpp"

namespace projsurf {

struct ChessboardReport {
    std::string captures_dir, created_utc;
    int poses = 0;
    double square_m = 0;
    double decoded_board_share = 0;
};

void writeChessboardCalibration(const std::string &path, const StereoFit &fit, int width, int height,
                                const ChessboardReport &report);

}  // namespace projsurf
