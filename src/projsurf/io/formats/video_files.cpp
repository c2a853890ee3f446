#include "projsurf/io/formats/video_files.hpp"

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <opencv2/core/utils/logger.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <regex>

#include "projsurf/io/files/errors.hpp"
#include "projsurf/io/files/files.hpp"
#include "projsurf/io/files/limits.hpp"
#include "projsurf/io/files/quiet_stderr.hpp"

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
        QuietStderr quiet;
        cap.open(path, pattern ? cv::CAP_IMAGES : cv::CAP_FFMPEG);
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
    if (fourcc == 0) throw InputError(name_for_errors, "a video needs a .avi, .mkv, .mp4 or .mov name");
    cv::VideoWriter writer;
    try {
        QuietStderr quiet;
        writer.open(path, cv::CAP_FFMPEG, fourcc, fps, size, true);
        // OpenCV's own MJPG writer when FFmpeg is missing (not CAP_ANY: its fallbacks leak).
        if (!writer.isOpened() && fourcc == cv::VideoWriter::fourcc('M', 'J', 'P', 'G'))
            writer.open(path, cv::CAP_OPENCV_MJPEG, fourcc, fps, size, true);
    } catch (const cv::Exception &) {
        writer.release();
    }
    if (!writer.isOpened()) throw InputError(name_for_errors, "cannot write a video here (try an .avi file: MJPG)");
    return writer;
}

namespace {

std::string frameName(const std::string &pattern, long n) {
    char name[4096];
    const int len = std::snprintf(name, sizeof name, pattern.c_str(), static_cast<int>(n));
    if (len < 0 || static_cast<std::size_t>(len) >= sizeof name) throw InputError(pattern, "frame names are too long");
    return name;
}

/// Whether a sequence's frame is there: nothing at the name ends the sequence; anything else
/// must be a readable regular file (a FIFO, a folder or a broken link there is an error naming it).
bool exists(const std::string &path) {
    std::error_code ec;
    if (std::filesystem::symlink_status(path, ec).type() == std::filesystem::file_type::not_found) return false;
    requireReadable(path);
    return true;
}

void toBgr8(cv::Mat &frame) {
    if (frame.channels() == 1)
        cv::cvtColor(frame, frame, cv::COLOR_GRAY2BGR);
    else if (frame.channels() == 4)
        cv::cvtColor(frame, frame, cv::COLOR_BGRA2BGR);
    if (frame.depth() != CV_8U) frame.convertTo(frame, CV_8U, frame.depth() == CV_16U ? 1.0 / 257.0 : 1.0);
}

}  // namespace

FrameSource::FrameSource(const std::string &path) : path_(path), current_(path), pattern_(isFramePattern(path)) {
    if (pattern_) {
        if (!isValidFramePattern(path))
            throw InputError(path, "an image-sequence pattern needs exactly one frame-number field such as %04d");
        while (first_ < 1000 && !exists(frameName(path, first_))) ++first_;
        if (first_ == 1000) throw InputError(path, "no image of this sequence exists (numbers 0..999 tried)");
        // Counted before any work: the length is known and checked up front.
        long n = first_;
        while (exists(frameName(path, n))) {
            if (static_cast<std::uint64_t>(n - first_) >= limits::kMaxSequenceFrames)
                throw InputError(path, "image sequence longer than the limit of " +
                                           std::to_string(limits::kMaxSequenceFrames) + " frames");
            ++n;
        }
        count_ = n - first_;
        next_ = first_;
        return;
    }
    cap_ = openVideoInput(path);
    const double w = cap_.get(cv::CAP_PROP_FRAME_WIDTH), h = cap_.get(cv::CAP_PROP_FRAME_HEIGHT);
    if (!(w * h <= static_cast<double>(limits::kMaxImagePixels)))
        throw InputError(path, "video frames of " + std::to_string(static_cast<long long>(std::min(w, 1e15))) + " x " +
                                   std::to_string(static_cast<long long>(std::min(h, 1e15))) +
                                   " pixels exceed the limit of " + std::to_string(limits::kMaxImagePixels) +
                                   " pixels");
    const double n = cap_.get(cv::CAP_PROP_FRAME_COUNT);
    if (n > static_cast<double>(limits::kMaxSequenceFrames))
        throw InputError(path, "video of " + std::to_string(static_cast<long long>(std::min(n, 1e15))) +
                                   " frames exceeds the limit of " + std::to_string(limits::kMaxSequenceFrames) +
                                   " frames");
    count_ = n > 0 ? static_cast<long>(n) : 0;
    const double f = cap_.get(cv::CAP_PROP_FPS);
    fps_ = f > 0 && f < 1000 ? f : 0.0;
}

bool FrameSource::read(cv::Mat &frame) {
    if (pattern_) {
        if (next_ - first_ >= count_) return false;
        current_ = frameName(path_, next_);
        frame = readImage(current_, cv::IMREAD_UNCHANGED);  // an unreadable frame is an error naming it
        ++next_;
        toBgr8(frame);
        return true;
    }
    if (static_cast<std::uint64_t>(done_) >= limits::kMaxSequenceFrames)
        throw InputError(path_,
                         "video longer than the limit of " + std::to_string(limits::kMaxSequenceFrames) + " frames");
    bool ok = false;
    try {
        QuietStderr quiet;
        ok = cap_.read(frame) && !frame.empty();
    } catch (const cv::Exception &) {
        throw InputError(path_, "frame " + std::to_string(done_) + " cannot be decoded");
    }
    if (!ok) return false;
    if (frame.total() > limits::kMaxImagePixels)
        throw InputError(path_,
                         "video frame exceeds the limit of " + std::to_string(limits::kMaxImagePixels) + " pixels");
    ++done_;
    toBgr8(frame);
    return true;
}

}  // namespace projsurf
