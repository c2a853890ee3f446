#include "projsurf/io/formats/procam_captures.hpp"

#include <filesystem>
#include <map>
#include <regex>

#include <opencv2/imgcodecs.hpp>

#include "projsurf/calibration/gray_code.hpp"
#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"

namespace fs = std::filesystem;

namespace projsurf {
namespace {

const std::regex kPoseName(R"(capture_(\d{1,4}))");
const std::regex kImageName(R"(graycode_(\d{1,3})\.(png|jpg|jpeg|bmp|tif|tiff))", std::regex::icase);

/// Number -> entry of DIR's entries whose name matches `name` (folders only, or files only).
std::map<int, fs::path> numberedEntries(const fs::path &dir, const std::regex &name, bool folders) {
    std::map<int, fs::path> out;
    std::error_code ec;
    for (const auto &e : fs::directory_iterator(dir, ec)) {
        std::smatch m;
        const std::string n = e.path().filename().string();
        if (e.is_directory(ec) == folders && std::regex_match(n, m, name)) out[std::stoi(m[1])] = e.path();
    }
    return out;
}

std::map<int, fs::path> poseFolders(const fs::path &dir) { return numberedEntries(dir, kPoseName, true); }
std::map<int, fs::path> poseImages(const fs::path &pose) { return numberedEntries(pose, kImageName, false); }

}  // namespace

bool isProcamFolder(const std::string &dir) {
    for (const auto &[k, p] : poseFolders(dir))
        if (!poseImages(p).empty()) return true;
    return false;
}

ProcamFolder readProcamFolder(const std::string &dir, std::optional<std::pair<int, int>> resolution) {
    ProcamFolder f;
    const fs::path patterns = fs::path(dir) / "graycode_pattern" / "pattern_00.png";
    std::error_code ec;
    if (fs::exists(patterns, ec)) {
        const cv::Mat p = readImage(patterns.string(), cv::IMREAD_GRAYSCALE);
        if (resolution && (resolution->first != p.cols || resolution->second != p.rows))
            throw InputError(patterns.string(), "patterns are " + std::to_string(p.cols) + "x" +
                                                    std::to_string(p.rows) + " but --resolution says " +
                                                    std::to_string(resolution->first) + "x" +
                                                    std::to_string(resolution->second));
        f.width = p.cols;
        f.height = p.rows;
    } else if (resolution) {
        f.width = resolution->first;
        f.height = resolution->second;
    } else {
        throw InputError(dir, "no graycode_pattern/pattern_00.png to give the projector's size: pass --resolution W,H");
    }
    const std::size_t need = openCvGrayPatterns(f.width, f.height).size();
    const auto poses = poseFolders(dir);
    if (poses.empty()) throw InputError(dir, "no capture_<k>/ folders with graycode_<NN>.png captures");
    if (poses.size() > limits::kMaxCaptures)
        throw InputError(dir, std::to_string(poses.size()) + " capture folders, at most " +
                                  std::to_string(limits::kMaxCaptures));
    for (const auto &[k, p] : poses) {
        const auto images = poseImages(p);
        ProcamPose pose;
        pose.dir = p.string();
        for (std::size_t i = 0; i < need; ++i) {
            const auto it = images.find(static_cast<int>(i));
            if (it == images.end())
                throw InputError(p.string(), "lacks graycode_" + std::string(i < 10 ? "0" : "") + std::to_string(i) +
                                                 ".png (a " + std::to_string(f.width) + "x" +
                                                 std::to_string(f.height) + " projector's Gray-code set is " +
                                                 std::to_string(need) + " captures, graycode_00 .. graycode_" +
                                                 std::to_string(need - 1) + ", white and black last)");
            pose.files.push_back(it->second.string());
        }
        if (images.size() > need)
            throw InputError(p.string(), std::to_string(images.size()) + " captures for " + std::to_string(need) +
                                             " patterns (a " + std::to_string(f.width) + "x" +
                                             std::to_string(f.height) + " projector; --resolution?)");
        f.poses.push_back(pose);
    }
    const auto [cw, ch] = imageFileSize(f.poses.front().files.front());
    const std::string &first = f.poses.front().files.front();
    if (cw * ch > limits::kMaxImagePixels)
        throw InputError(first, "image of " + std::to_string(cw) + " x " + std::to_string(ch) +
                                    " pixels exceeds the limit of " + std::to_string(limits::kMaxImagePixels) +
                                    " pixels");
    f.camera_width = static_cast<int>(cw);
    f.camera_height = static_cast<int>(ch);
    const std::uint64_t pixels = cw * ch, pose_bytes = chessboardPoseBytes(pixels, need);
    const std::string shape = std::to_string(need) + " captures of " + std::to_string(cw) + "x" + std::to_string(ch);
    if (pose_bytes > limits::kMaxStructuredLightBytes)
        throw InputError(dir, "a pose of " + shape + " pixels needs " + std::to_string(pose_bytes >> 20) +
                                  " MiB to decode, beyond the limit of " +
                                  std::to_string(limits::kMaxStructuredLightBytes >> 20) +
                                  " MiB (a smaller camera image)");
    const std::uint64_t capture_bytes = f.poses.size() * need * pixels;
    if (capture_bytes > limits::kMaxChessboardCaptureBytes)
        throw InputError(dir, std::to_string(f.poses.size()) + " poses of " + shape + " pixels are " +
                                  std::to_string(capture_bytes >> 20) + " MiB of captures to decode, beyond the limit of " +
                                  std::to_string(limits::kMaxChessboardCaptureBytes >> 20) +
                                  " MiB (fewer poses, or a smaller camera image)");
    return f;
}

std::uint64_t chessboardPoseBytes(std::uint64_t pixels, std::uint64_t patterns) {
    return (patterns        // the captures, 8 bits each
            + 2 * patterns  // their 3 x 3 sums
            + 2 * 8 + 4 + 1  // the decoding: column, row, direct light, confidence
            + 4)             // the board search: a grey copy, its half-size image, the white capture's
           * pixels;
}

std::vector<cv::Mat> readProcamPose(const ProcamPose &pose, int camera_width, int camera_height) {
    std::vector<cv::Mat> out;
    for (const std::string &file : pose.files)
        out.push_back(readImageOfSize(file, cv::IMREAD_GRAYSCALE, camera_width, camera_height, "the first capture"));
    return out;
}

}  // namespace projsurf
