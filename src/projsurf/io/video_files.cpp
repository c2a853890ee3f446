#include "projsurf/io/video_files.hpp"

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <opencv2/core/utils/logger.hpp>
#include <regex>

#include "projsurf/io/errors.hpp"
#include "projsurf/io/files.hpp"

namespace projsurf {
namespace {

std::string lowerExtension(const std::string &path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

/// FFmpeg and GStreamer print their own errors (e.g. "moov atom not found"); a user-given
/// setting wins.
void quietVideoBackends() {
    ::setenv("OPENCV_FFMPEG_LOGLEVEL", "-8", 0);  // AV_LOG_QUIET
    ::setenv("OPENCV_VIDEOIO_PRIORITY_GSTREAMER", "0", 0);
    cv::utils::logging::setLogLevel(cv::utils::logging::LOG_LEVEL_SILENT);
}

}  // namespace

bool isFramePattern(const std::string &path) { return path.find('%') != std::string::npos; }

bool isValidFramePattern(const std::string &path) {
    static const std::regex one_field(R"([^%]*%0?[0-9]*d[^%]*)");
    return std::regex_match(path, one_field);
}

bool isVideoPath(const std::string &path) {
    const std::string e = lowerExtension(path);
    return e == ".mp4" || e == ".avi" || e == ".mkv" || e == ".mov" || e == ".m4v" || e == ".webm";
}

int videoFourcc(const std::string &path) {
    const std::string e = lowerExtension(path);
    if (e == ".avi" || e == ".mkv") return cv::VideoWriter::fourcc('M', 'J', 'P', 'G');
    if (e == ".mp4" || e == ".m4v" || e == ".mov") return cv::VideoWriter::fourcc('m', 'p', '4', 'v');
    return 0;
}

cv::VideoCapture openVideoInput(const std::string &path) {
    quietVideoBackends();
    const bool pattern = isFramePattern(path);
    if (pattern && !isValidFramePattern(path))
        throw InputError(path, "an image-sequence pattern needs exactly one frame-number field such as %04d");
    if (!pattern) requireReadable(path);
    cv::VideoCapture cap;
    try {
        cap.open(path, pattern ? cv::CAP_IMAGES : cv::CAP_FFMPEG);
        if (!cap.isOpened() && !pattern) cap.open(path, cv::CAP_ANY);
    } catch (const cv::Exception &) {
        cap.release();
    }
    if (!cap.isOpened())
        throw InputError(path, pattern ? "no readable image sequence matches this pattern" : "not a readable video");
    return cap;
}

cv::VideoWriter openVideoOutput(const std::string &path, const std::string &name_for_errors, double fps,
                                cv::Size size) {
    quietVideoBackends();
    const int fourcc = videoFourcc(path);
    if (fourcc == 0)
        throw InputError(name_for_errors, "a video needs a .avi, .mkv, .mp4 or .mov name");
    cv::VideoWriter writer;
    try {
        writer.open(path, cv::CAP_FFMPEG, fourcc, fps, size, true);
        if (!writer.isOpened()) writer.open(path, cv::CAP_ANY, fourcc, fps, size, true);
    } catch (const cv::Exception &) {
        writer.release();
    }
    if (!writer.isOpened()) throw InputError(name_for_errors, "cannot write a video here (try an .avi file: MJPG)");
    return writer;
}

}  // namespace projsurf
