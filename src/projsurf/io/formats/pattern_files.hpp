#pragma once
// The structured-light capture folder (contract, "Structured-light calibration"):
// DIR/patterns.yaml lists the patterns in the order to project, DIR/patterns/<name>.png are
// the framebuffer images; the user adds camera.yaml and pose_<k>/{depth.png, <name>.png}.
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace projsurf {

struct PatternList {
    int width = 0, height = 0;       ///< framebuffer, px
    std::string coding;              ///< "gray_code_inverse" (the only one so far)
    std::vector<std::string> names;  ///< in the order to project
};

/// Writes DIR/patterns/<name>.png and DIR/patterns.yaml for a width x height framebuffer (all
/// or nothing); returns the list.
PatternList writePatternSet(const std::string &dir, int width, int height);
/// Reads DIR/patterns.yaml; InputError when malformed or of a coding this version does not know.
PatternList readPatternList(const std::string &path);

/// One robot position: its depth image and one colour image per pattern, in list order.
struct PoseCaptures {
    std::string dir;
    cv::Mat depth;
    std::vector<cv::Mat> colour;
};
/// Bytes that decoding `poses` poses of `pixels` camera pixels each under `patterns` patterns
/// allocates at its peak: one pose at a time (its 8-bit captures, the image being decoded, its
/// depth, its decoding) plus the lifted points of every pose (at most one per pixel).
std::uint64_t structuredLightBytes(std::uint64_t poses, std::uint64_t pixels, std::uint64_t patterns);
/// The folders DIR/pose_0, pose_1, ... (consecutive); InputError when there is none, more than
/// limits::kMaxCaptures, or when decoding them for `list` at the camera's `width` x `height`
/// would exceed limits::kMaxStructuredLightBytes. Nothing is read but the folder listing.
std::vector<std::string> listPoseFolders(const std::string &dir, const PatternList &list, int width, int height);
/// Reads one pose folder for `list`; every image must have the camera's `width` x `height`.
/// InputError naming the file otherwise (a missing capture included).
PoseCaptures readPoseCaptures(const std::string &pose_dir, const PatternList &list, int width, int height);

}  // namespace projsurf
