#pragma once
// Detection on every real RGB-D frame of a folder (one sub-folder per frame with depth.png and
// camera.yaml, optionally rgb.png registered to it), with an overlay picture per frame.
#include <optional>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "projsurf/detector/detector.hpp"

namespace projsurf::eval {

struct GalleryEntry {
    std::string name;     ///< the frame's folder name
    bool read = false;    ///< the frame could be read
    std::string problem;  ///< why not (when !read)
    bool found = false;
    std::string reason;                      ///< why nothing was found
    double width = 0, height = 0, area = 0;  ///< m, m, m^2
    double distance = 0;                     ///< m, plane's distance from the camera
    double orientation_deg = 0;
    int points = 0, outliers = 0;  ///< surface check
    double time_ms = 0;            ///< detection, in-process
    Rectangle rectangle;           ///< camera frame (when found)
    cv::Mat overlay;               ///< BGR
};

/// Sorted sub-folders of `dir` that hold depth.png and camera.yaml; empty when `dir` is not a
/// directory.
std::vector<std::string> listFrameFolders(const std::string &dir);

/// Reads one frame folder and runs detection; a frame that cannot be read gives read = false
/// and the problem (it does not throw). Without `gravity`, it is estimated from the floor with a
/// level camera as the prior (as `detect --gravity auto`); with it, it is used as given (as
/// `detect --gravity gx,gy,gz`).
GalleryEntry detectRealFrame(const std::string &folder, const Projector &projector, const DetectorConfig &config,
                             const std::optional<Eigen::Vector3d> &gravity = std::nullopt);

/// Thumbnails of the overlays in a grid, each labelled with its name and result.
cv::Mat contactSheet(const std::vector<GalleryEntry> &entries, int columns = 3, int thumb_width = 480);

}  // namespace projsurf::eval
