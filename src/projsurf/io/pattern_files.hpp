#pragma once
// The structured-light capture folder (contract, "Structured-light calibration"):
// DIR/patterns.yaml lists the patterns in the order to project, DIR/patterns/<name>.png are
// the framebuffer images; the user adds camera.yaml and pose_<k>/{depth.png, <name>.png}.
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
/// Reads DIR/pose_0, pose_1, ... (consecutive) for `list`; every image must have the camera's
/// `width` x `height`. InputError naming the file otherwise (a missing capture included).
std::vector<PoseCaptures> readPoseCaptures(const std::string &dir, const PatternList &list, int width, int height);

}  // namespace projsurf
