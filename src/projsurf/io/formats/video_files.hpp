#pragma once
// Videos and image sequences in and out (OpenCV videoio), quietly: the backends' own log lines
// would break the CLI's "one clear line on stderr" rule.
#include <opencv2/core.hpp>
#include <opencv2/videoio.hpp>
#include <string>

namespace projsurf {

/// A printf-style frame pattern such as frames/%04d.png (contains '%').
bool isFramePattern(const std::string &path);
/// The pattern has exactly one %d-style field (e.g. %d, %04d) and no other '%'.
bool isValidFramePattern(const std::string &path);
/// A video container by its extension: .mp4 .avi .mkv .mov .m4v .webm.
bool isVideoPath(const std::string &path);
/// The FourCC projsurf writes for an output container: MJPG for .avi/.mkv (every OpenCV build
/// has it), mp4v for .mp4/.m4v/.mov; 0 for anything else.
int videoFourcc(const std::string &path);

/// Opens a video file (FFmpeg only: the other backends' fallbacks leak on unreadable files)
/// or an image sequence pattern (OpenCV's image reader) with the backends' logging
/// silenced; throws InputError naming the path when nothing can be read.
cv::VideoCapture openVideoInput(const std::string &path);

/// The frames of a video file or of an image-sequence pattern, in order. A sequence starts at
/// the first existing number in 0..999 and ends at the first missing number; a frame that
/// exists but cannot be read is an error naming it (never a silently shorter video). Every
/// frame is checked against limits::kMaxImagePixels, the count against kMaxSequenceFrames.
class FrameSource {
public:
    explicit FrameSource(const std::string &path);
    /// The next frame (8-bit BGR); false after the last. Throws InputError.
    bool read(cv::Mat &frame);
    /// Frames per second of a video (0 when unknown, e.g. a sequence).
    double fps() const { return fps_; }
    /// The number of frames when known beforehand (a sequence; a video's header), else 0.
    long count() const { return count_; }
    /// The name of the frame last read (the file of a sequence, else the video).
    const std::string &current() const { return current_; }
    /// The number of a sequence's first frame (frames/0001.png... -> 1); 0 for a video.
    long firstNumber() const { return first_; }

private:
    std::string path_, current_;
    bool pattern_ = false;
    long next_ = 0, first_ = 0, count_ = 0, done_ = 0;
    double fps_ = 0.0;
    cv::VideoCapture cap_;
};

/// Opens a writer (FFmpeg, else any backend) for `path` by its extension; throws InputError
/// naming `name_for_errors` when it cannot.
cv::VideoWriter openVideoOutput(const std::string &path, const std::string &name_for_errors, double fps, cv::Size size);

}  // namespace projsurf
