#pragma once
// Whole-file writes that never leave a partial output: write beside, then rename.
#include <opencv2/core.hpp>
#include <string>

namespace projsurf {

/// Writes `bytes` to `path` atomically; throws InputError naming the path on failure.
void writeFileAtomic(const std::string &path, const std::string &bytes);
/// Encodes an image by the path's extension (png, jpg, ...) and writes it atomically.
void writeImageAtomic(const std::string &path, const cv::Mat &image);
/// Reads an image (cv::IMREAD flags); throws InputError naming the path when missing or unreadable.
cv::Mat readImage(const std::string &path, int flags);
/// Throws InputError when the file does not exist or is not a regular readable file.
void requireReadable(const std::string &path);
/// Throws InputError when the directory of `path` does not exist (checked before any work).
void requireWritableLocation(const std::string &path);

}  // namespace projsurf
