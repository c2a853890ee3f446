#pragma once
// The capture folder of procam-calibration tools (kamino410/procam-calibration and its
// kind): DIR/capture_<k>/graycode_<NN>.png, NN = 00.. in OpenCV's Gray-code order (columns,
// rows, each pattern then its inverse, then white and black), the chessboard seen under the
// white pattern; DIR/graycode_pattern/pattern_00.png (optional) gives the projector's size.
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include <opencv2/core.hpp>

namespace projsurf {

struct ProcamPose {
    std::string dir;                 ///< DIR/capture_<k>
    std::vector<std::string> files;  ///< graycode_00.png .. in order
};

struct ProcamFolder {
    std::vector<ProcamPose> poses;  ///< by k
    int width = 0, height = 0;      ///< projector framebuffer, px
};

/// True when DIR holds a capture_<k>/ folder with graycode_<NN> images.
bool isProcamFolder(const std::string &dir);

/// Lists the poses and checks each holds the full pattern set for the projector size (from
/// graycode_pattern/pattern_00.png, else `resolution`); InputError saying what is missing.
ProcamFolder readProcamFolder(const std::string &dir, std::optional<std::pair<int, int>> resolution);

/// The pose's captures, grey, all of one size (else InputError).
std::vector<cv::Mat> readProcamPose(const ProcamPose &pose);

}  // namespace projsurf
