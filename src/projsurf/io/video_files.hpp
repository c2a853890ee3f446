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

/// Opens a video file (FFmpeg) or an image sequence pattern (OpenCV's image reader) with the
/// backends' logging silenced; throws InputError naming the path when nothing can be read.
cv::VideoCapture openVideoInput(const std::string &path);

/// Opens a writer (FFmpeg, else any backend) for `path` by its extension; throws InputError
/// naming `name_for_errors` when it cannot.
cv::VideoWriter openVideoOutput(const std::string &path, const std::string &name_for_errors, double fps,
                                cv::Size size);

}  // namespace projsurf
