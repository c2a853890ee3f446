#pragma once
// Whole-file writes that never leave a partial output: write beside, then rename.
#include <cstdint>
#include <opencv2/core.hpp>
#include <string>
#include <utility>
#include <vector>

#include "projsurf/io/files/limits.hpp"

namespace projsurf {

/// Writes `bytes` to `path` atomically; throws InputError naming the path on failure.
void writeFileAtomic(const std::string &path, const std::string &bytes);
/// Encodes an image by the path's extension (png, jpg, ...) and writes it atomically.
void writeImageAtomic(const std::string &path, const cv::Mat &image);
/// Reads a PNG, JPEG, BMP or PNM image (cv::IMREAD flags). Its size is read from the header
/// first: more than `max_pixels` pixels (or a file over limits::kMaxImageFileBytes) is refused
/// before decoding. Decoder diagnostics are silenced. Throws InputError naming the path when
/// missing, unreadable, of another format or over the limits.
cv::Mat readImage(const std::string &path, int flags, std::uint64_t max_pixels = limits::kMaxImagePixels);
/// readImage of an image that must be `width` x `height` (the camera's, as `whose` says: "camera.yaml");
/// another size is an InputError saying both, before anything is decoded.
cv::Mat readImageOfSize(const std::string &path, int flags, int width, int height, const std::string &whose);

/// Width and height of an image file from its header alone (nothing decoded); InputError naming
/// the path when it is not a regular file, over limits::kMaxImageFileBytes, or not a PNG, JPEG,
/// BMP or PNM with a non-zero size.
std::pair<std::uint64_t, std::uint64_t> imageFileSize(const std::string &path);

/// The outputs of one command as a group (never a partial output): each add writes a
/// temporary file beside its target (same folder, so the rename cannot cross file systems);
/// commit() renames them all; whatever was not committed is removed by the destructor.
class OutputGroup {
public:
    OutputGroup() = default;
    ~OutputGroup();
    OutputGroup(const OutputGroup &) = delete;
    OutputGroup &operator=(const OutputGroup &) = delete;
    void addFile(const std::string &path, const std::string &bytes);
    /// Encoded by the path's extension; throws InputError when it cannot be.
    void addImage(const std::string &path, const cv::Mat &image);
    /// A temporary name for `path` (same folder and extension) that the caller writes itself
    /// (e.g. a video writer); renamed to `path` by commit().
    std::string reserve(const std::string &path);
    void commit();

private:
    std::vector<std::pair<std::string, std::string>> files_;  // temporary, final
};
/// The whole of a small text file (YAML, JSON): refused when larger than `max_bytes` or
/// nested deeper than limits::kMaxNesting brackets, indentation levels or (kind "XML") elements
/// (the parsers recurse).
/// `kind` names the format in messages.
std::string readSmallTextFile(const std::string &path, std::uint64_t max_bytes, const char *kind);
/// Throws InputError when the file does not exist or is not a regular readable file.
void requireReadable(const std::string &path);
/// Throws InputError when the directory of `path` does not exist (checked before any work).
void requireWritableLocation(const std::string &path);
/// requireWritableLocation, and `path` is not an existing directory.
void requireWritableFile(const std::string &path);
/// Throws InputError when no image encoder matches the extension of `path`.
void requireImageWriter(const std::string &path);

}  // namespace projsurf
