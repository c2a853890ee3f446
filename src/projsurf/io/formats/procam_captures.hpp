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
    int camera_width = 0, camera_height = 0;  ///< of every capture (the first one's header)
};

/// Bytes decoding one chessboard pose of `pixels` camera pixels under `patterns` patterns
/// allocates at its peak: its 8-bit captures, their 3 x 3 sums (16 bits each) for the dark
/// pixels, the decoding (two doubles, a float, a byte) and the board search's copies.
std::uint64_t chessboardPoseBytes(std::uint64_t pixels, std::uint64_t patterns);

/// True when DIR holds a capture_<k>/ folder with graycode_<NN> images.
bool isProcamFolder(const std::string &dir);

/// Lists the poses and checks each holds the full pattern set for the projector size (from
/// graycode_pattern/pattern_00.png, else `resolution`); InputError saying what is missing.
/// The camera's size is the first capture's header; before any capture is decoded the folder
/// is refused when one pose needs more than limits::kMaxStructuredLightBytes to decode
/// (chessboardPoseBytes) or all the poses hold more than limits::kMaxChessboardCaptureBytes of
/// captures (a time bound: every pose folder counts, a link to another one too).
ProcamFolder readProcamFolder(const std::string &dir, std::optional<std::pair<int, int>> resolution);

/// The pose's captures, grey, each of the folder's camera size (else InputError, from the
/// header, before decoding).
std::vector<cv::Mat> readProcamPose(const ProcamPose &pose, int camera_width, int camera_height);

}  // namespace projsurf
